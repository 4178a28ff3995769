// The writer table: every output format, for controllers that cannot read the program as written
// and for CAD (DXF).
//
// Each entry is {name, one-line summary, what it needs (one plane or two), write function}; `kerf
// convert --to NAME` looks the name up and `kerf convert --list` prints the table. A format's
// writer and its options live in its folder (formats/<name>/write_<name>.h); the table holds them
// together in EmitRequest. Adding a format touches its folder, this table (its options' member
// and its row in emit.cpp) and the build list (docs/architecture.md). The writers take the
// Toolpath the one pipeline made (pipeline.h), so an output never says less than `kerf check`.
// Every writer whose format Kerf reads (3b, iso, polar, dxf) is tested by a round trip: write,
// read, compare within the format's resolution.
#pragma once

#include "kerf/converter/formats/3b/write_3b.h"
#include "kerf/converter/formats/dxf/write_dxf.h"
#include "kerf/converter/formats/iso/write_iso.h"
#include "kerf/converter/formats/points/points.h"
#include "kerf/converter/formats/polar/write_polar.h"
#include "kerf/converter/formats/writer.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace kerf::converter {

/// Which plane a 2-axis file follows on a taper program: `lower`, `upper` or `z=H`.
struct PlaneChoice {
  enum class Kind : std::uint8_t { Lower, Upper, Height } kind = Kind::Lower;
  double z = 0.0;  ///< Height only, mm
};
std::optional<PlaneChoice> parsePlane(std::string_view text);

/// The wire on one plane as a plain toolpath (warning K0804: a 2-axis machine cannot cut the
/// taper). Sections between the planes are exact lines and arcs where they can be, polylines
/// within tolerance otherwise. A plain toolpath is returned as it is.
std::optional<Toolpath> toolpathAtPlane(const Toolpath& toolpath, const PlaneChoice& plane, double tolerance,
                                        const SourceFile* source, Diagnostics& diags);

/// What an emitter needs of a taper program.
enum class PlaneNeed : std::uint8_t {
  One,   ///< a 2-axis format: a taper program is written for one plane (--plane)
  Both,  ///< writes the upper contour too (a plain program has its upper side equal to the lower)
};

/// What every writer in the table may be asked: each format's own options (declared in its
/// folder), and where the cut path starts.
struct EmitRequest {
  std::optional<std::uint32_t> startLine;  ///< begin at the cut move of this source line (points, 3B, 4B)
  PointWriteOptions points;                ///< bp95d, points4
  ThreeBWriteOptions threeB;               ///< 3b, 4b
  IsoWriteOptions iso;
  PolarWriteOptions polar;
  DxfWriteOptions dxf;
};

struct Emitter {
  std::string_view name;
  std::string_view summary;
  PlaneNeed planes;
  std::optional<EmitOutput> (*write)(const Toolpath& toolpath, const SourceFile* source, const EmitRequest& request,
                                     Diagnostics& diags);
};

/// Every emitter, in `kerf convert --list` order.
const std::vector<Emitter>& emitters();
/// The emitter with this name, or null.
const Emitter* findEmitter(std::string_view name);

}  // namespace kerf::converter
