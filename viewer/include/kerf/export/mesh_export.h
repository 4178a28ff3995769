// The ruled surface as a mesh file for ParaView and CAD, written with VTK's writers:
//   .vtp  VTK XML poly data, with cell data "move", "line", "slope" and "findings" and point
//         data "slope", so ParaView can colour by any of them;
//   .stl  binary STL (geometry only);  .ply  binary PLY (geometry only).
// The namespace is kerf::exporter because `export` is a C++ keyword.
#pragma once

#include "kerf/converter/check/drawing_check.h"
#include "kerf/converter/nc/diagnostics.h"
#include "kerf/converter/toolpath.h"
#include "kerf/render/scene.h"

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace kerf::exporter {

enum class MeshFormat { Vtp, Stl, Ply };
/// From the file name's extension (any case); nothing for another extension.
std::optional<MeshFormat> formatOfPath(std::string_view path);

/// Bits of the "findings" array: the cell's move has a finding of this severity.
inline constexpr int kFindingError = 1, kFindingWarning = 2, kFindingNote = 4;

struct SurfaceData {
  render::CutSurface surface;
  std::vector<int> cellMove;      ///< index into Toolpath::moves (-1: a cap)
  std::vector<int> cellLine;      ///< source line of the move (0: a cap)
  std::vector<float> cellSlope;   ///< degrees, mean of the cell's vertices
  std::vector<int> cellFindings;  ///< kFinding* bits
  std::vector<int> cellPass;      ///< the move's pass in its contour (1: the rough cut; 0: none, or a cap)
  /// mm: the largest deviation from --drawing of the move's part edge (NaN: not on the part edge,
  /// or no drawing). Written only when some cell has one.
  std::vector<float> cellDeviation;
};

/// Meshes the cut surface (closed contours capped when caps) and computes the cell data; the pass
/// of each cell from options.movePass (0 everywhere when it is empty).
SurfaceData surfaceData(const converter::Toolpath& toolpath, std::span<const converter::Diagnostic> findings,
                        const render::SceneOptions& options, bool caps);

/// Per move: the largest deviation of its pieces of the part edge from the drawing, mm; NaN for a
/// move that is not on the part edge.
std::vector<float> moveDeviations(const converter::DrawingComparison& comparison, std::size_t moves);

/// Writes the file at exactly `path` (the caller writes to a temporary name and renames).
/// False with a message when VTK could not write it.
bool writeMesh(const SurfaceData& data, MeshFormat format, const std::string& path, std::string& error);

}  // namespace kerf::exporter
