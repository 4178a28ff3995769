// Emitters: a table of output formats for controllers that cannot read the program as written.
//
// Each emitter is {name, one-line summary, what it needs (one plane or two), write function};
// `kerf convert --to NAME` looks the name up and `kerf convert --list` prints the table. The
// emitters take the Toolpath the one pipeline made (pipeline.h), so an output never says less
// than `kerf check`. Every emitter whose format Kerf reads (3b, iso, polar) is tested by a round
// trip: write, read, compare within the format's resolution.
#pragma once

#include "kerf/converter/formats/points/points.h"
#include "kerf/converter/interpret/machine.h"
#include "kerf/converter/nc/diagnostics.h"
#include "kerf/converter/nc/program.h"
#include "kerf/converter/toolpath.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace kerf::converter {

/// Starts a cut path at the cut move of `startLine`: a closed path is rotated to begin there; on an
/// open one the moves before it are left out (warning K0803). False, with an error, when no cut
/// move comes from that line. Every emitter's --start-block.
bool startCutPathAt(const Toolpath& toolpath, CutPath& path, std::uint32_t startLine, const SourceFile* source,
                    Diagnostics& diags);

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

/// How X is written in polar X/C output and read inside G12.1.
enum class PolarX : std::uint8_t { Diameter, Radius };

struct EmitRequest {
  // Point files (bp95d, points4).
  PointProfile profile = bp95dProfile();
  geometry::Sampling sampling = geometry::Sampling::step(0.1);
  std::optional<std::size_t> maxPoints;
  std::optional<std::uint32_t> startLine;  ///< begin at the cut move of this source line
  bool relativeUv = false;                 ///< points4: U V as upper minus lower
  bool atGuides = false;                   ///< points4: X Y at the lower guide, U V at the upper (--plane guides)
  // ISO: the target controller's conventions (null: generic).
  const MachineProfile* target = nullptr;
  std::optional<int> decimals;  ///< iso, polar: digits after the point (default: the target's, 3)
  bool offsetsApplied = false;  ///< iso: G41/G42 marks are the controller's job (kerf cam), not a loss
  bool flattenSlivers = false;  ///< iso: arcs bulging less than half the resolution as lines (kerf cam)
  // 3B.
  bool compact = false;    ///< `B9900B0B9900GXL1` instead of `B9900 B0 B9900 GX L1`
  std::string end = "DD";  ///< the last line ("" for none)
  // Polar X/C.
  PolarX polarX = PolarX::Diameter;
  double tolerance = 0.001;  ///< mm: how far the machine's X/C path may leave the programmed one
  /// Set for an ISO source (how its text splits into blocks): polar output keeps each block's
  /// words that it does not convert, in place. Unset: the moves alone.
  std::optional<ParseOptions> sourceBlocks;
};

struct EmitOutput {
  std::string text;
  std::string what;    ///< "412 points (bp95d profile)", "14 records"
  std::string detail;  ///< "; step k = 0.100000 mm, max deviation 0.000031 mm"
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

// The write functions (also used directly by tests and benchmarks).
std::optional<EmitOutput> writeBp95d(const Toolpath&, const SourceFile*, const EmitRequest&, Diagnostics&);
std::optional<EmitOutput> writePoints4(const Toolpath&, const SourceFile*, const EmitRequest&, Diagnostics&);
/// 3B (docs/3b.md): records from rounded absolute positions, so the program ends exactly where the
/// source ends; an arc whose rounded ends do not share a circle gets the nearest µm centre that fits.
std::optional<EmitOutput> writeThreeB(const Toolpath&, const SourceFile*, const EmitRequest&, Diagnostics&);
/// 4B (docs/3b.md): `±B x B y B J B R G D|DD Z`, a layout marked [unsure].
std::optional<EmitOutput> writeFourB(const Toolpath&, const SourceFile*, const EmitRequest&, Diagnostics&);
/// Normalised ISO: absolute, mm, one move per block, I J incremental, in the target's conventions.
std::optional<EmitOutput> writeIso(const Toolpath&, const SourceFile*, const EmitRequest&, Diagnostics&);
/// Polar X/C for mill-turn lathes (docs/polar.md): X diameter or radius, C in degrees unwrapped,
/// each element subdivided so the machine's spiral stays within the tolerance.
std::optional<EmitOutput> writePolar(const Toolpath&, const SourceFile*, const EmitRequest&, Diagnostics&);

}  // namespace kerf::converter
