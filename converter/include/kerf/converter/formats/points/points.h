// Point-sequence emitter for point-driven 2-axis controllers (the BP-95d and its kin).
//
// No public description of the BP-95d format exists (docs/bp95d.md): the output is driven by a
// profile, and the built-in `bp95d` profile is our documented assumption — one point per line,
// `X Y` absolute, millimetres, 3 decimals, one space, no header, the start point first.
#pragma once

#include "kerf/converter/check/summary.h"
#include "kerf/converter/formats/writer.h"
#include "kerf/converter/nc/diagnostics.h"
#include "kerf/converter/toolpath.h"
#include "kerf/geometry/tessellation.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace kerf::converter {

struct PointProfile {
  std::string name = "bp95d";
  int decimals = 3;             ///< 0..6
  bool micrometres = false;     ///< integers in µm instead of mm with decimals
  bool incremental = false;     ///< each point relative to the previous one
  std::string separator = " ";  ///< between X and Y
  bool lineNumbers = false;     ///< prefix each point with `lineNumberPrefix` + counter
  std::string lineNumberPrefix = "N";
  std::size_t lineNumberStart = 1;
  std::string header;                    ///< written before the points (verbatim, may be empty)
  std::string footer;                    ///< written after them
  std::optional<std::size_t> maxPoints;  ///< the controller's capacity
};

/// The built-in profile (docs/bp95d.md).
PointProfile bp95dProfile();

/// Reads a profile file: `key = value` lines, `#` comments. Keys: name, decimals,
/// unit (mm|um), coordinates (absolute|incremental), separator (space|tab|comma|semicolon or a
/// quoted string), line_numbers (true|false), line_number_prefix, line_number_start,
/// header, footer (quoted; \n for a line break), max_points. Starts from the bp95d defaults.
std::optional<PointProfile> parseProfile(const SourceFile& file, Diagnostics& diags);

/// No point file is built larger than this: a step far too fine for a huge arc is refused with a
/// diagnostic instead of exhausting memory.
inline constexpr std::size_t kMaxPointsWritten = 50'000'000;

struct PointRequest {
  geometry::Sampling sampling = geometry::Sampling::step(0.1);
  std::optional<std::size_t> maxPoints;    ///< overrides the profile's; fits the step to it
  std::optional<std::uint32_t> startLine;  ///< begin at the cut move of this source line
  /// points4: the wire at its guides (PlaneHeights::guides), what the axes move, not at the part's
  /// faces: each row one position of the wire, extended to both guides.
  bool atGuides = false;
};

struct PointOutput {
  std::string text;
  std::size_t points = 0;
  geometry::Sampling sampling;  ///< the sampling used (chosen automatically with maxPoints)
  bool fitted = false;          ///< the sampling was chosen to fit maxPoints
  geometry::PathSampleStats stats;
};

/// Builds the point file. Returns nothing (with an error in diags) when it cannot: no cut
/// moves, a capacity no sampling can meet, an unknown start line.
std::optional<PointOutput> emitPoints(const Toolpath& toolpath, const SourceFile* source, const PointProfile& profile,
                                      const PointRequest& request, Diagnostics& diags);

/// `--to points4`: `X Y U V` per line for point-driven 4-axis controllers. Each cut move is split
/// into as many equal steps of t as its finer side needs, and both planes are sampled at the same
/// t, so every line is one position of the wire. U V are the upper point (absolute) or upper
/// minus lower (relativeUv). The profile's format settings apply to all four columns.
std::optional<PointOutput> emitPoints4(const Toolpath& toolpath, const SourceFile* source, const PointProfile& profile,
                                       const PointRequest& request, bool relativeUv, Diagnostics& diags);

/// The bp95d and points4 writers' options: the profile, the sampling and capacity, and for points4
/// how U V are written.
struct PointWriteOptions {
  PointProfile profile = bp95dProfile();
  PointRequest request;
  bool relativeUv = false;  ///< points4: U V as upper minus lower
};

/// `--to bp95d`: emitPoints with the profile, said as the writer table says it.
std::optional<EmitOutput> writeBp95d(const Toolpath& toolpath, const SourceFile* source,
                                     const PointWriteOptions& options, Diagnostics& diags);
/// `--to points4`: emitPoints4, said as the writer table says it.
std::optional<EmitOutput> writePoints4(const Toolpath& toolpath, const SourceFile* source,
                                       const PointWriteOptions& options, Diagnostics& diags);

}  // namespace kerf::converter
