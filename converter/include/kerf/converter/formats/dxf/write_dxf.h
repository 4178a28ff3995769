// A toolpath as a DXF drawing (docs/dxf.md, "Writing"): `kerf export part.nc -o part.dxf`, so a
// verified program goes back to CAD.
//
// Layers: LOWER (the wire path on the lower plane: every cut move), UPPER (a taper program's upper
// contour, at the upper plane's height when the heights are known), PROGRAMMED (where G41/G42 was
// applied: the contour as programmed, beside the wire-centre path), on request RAPID, and, held
// against a drawing, DEVIATION (the drawing's elements cut out of tolerance, issue 43). Lines are
// LINE, arcs ARC (DXF arcs run counter-clockwise, so a clockwise move is written from its end
// angle to its start angle), full circles CIRCLE. Units: millimetres ($INSUNITS 4 in R2000).
//
// R12 (AC1009): HEADER, TABLES (LTYPE, LAYER), ENTITIES; no handles. R2000 (AC1015): the full
// structure a strict reader wants — handles and owners, the nine symbol tables, the model and
// paper space block records with their BLOCKS, subclass markers, and the OBJECTS section's root
// dictionary. Both are ASCII with CRLF line ends, as AutoCAD writes them.
#pragma once

#include "kerf/converter/formats/writer.h"
#include "kerf/converter/toolpath.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace kerf::converter {

enum class DxfVersion { R12, R2000 };

/// "r12" / "R12" / "ac1009", "r2000" / "ac1015"; nothing for another name.
std::optional<DxfVersion> dxfVersionNamed(std::string_view name);

struct DxfWriteOptions {
  DxfVersion version = DxfVersion::R2000;
  bool rapids = false;     ///< also the rapids, on layer RAPID
  bool programmed = true;  ///< where an offset was applied, the programmed contour on PROGRAMMED
  /// Each move's pass number in its contour (converter::movePasses). When some contour has more
  /// than one pass, the cut moves of pass k go on LOWER_PASSk and UPPER_PASSk instead of LOWER and
  /// UPPER. Empty: LOWER and UPPER.
  std::vector<std::uint8_t> movePass;
  /// The drawing's elements cut farther off than the tolerance (kerf check --drawing), in the
  /// program's frame, on layer DEVIATION. Empty: no such layer.
  std::vector<geometry::Segment> deviation;
};

struct DxfWriteCounts {
  std::size_t lines = 0, arcs = 0, circles = 0;
};

/// The drawing as DXF text. counts (when given) receives what was written.
std::string writeDxf(const Toolpath& toolpath, const DxfWriteOptions& options, DxfWriteCounts* counts = nullptr);

/// writeDxf as the writer table calls it (`kerf convert --to dxf`, `kerf export -o F.dxf`): what was
/// written counted; refused (K0813) when nothing is cut.
std::optional<EmitOutput> writeDxfProgram(const Toolpath& toolpath, const SourceFile* source,
                                          const DxfWriteOptions& options, Diagnostics& diags);

}  // namespace kerf::converter
