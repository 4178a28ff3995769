// kerf export FILE -o part.vtp|.stl|.ply, in the drawing module: the ruled surface for ParaView
// and CAD (VTK writers). Its findings are those kerf check reports for the same options.
#include "draw.h"
#include "file_io.h"
#include "load.h"

#include "kerf/export/mesh_export.h"

#include <iostream>
#include <limits>

namespace kerf::cli {

int drawExportMesh(const ExportArgs& a) {
  const auto format = exporter::formatOfPath(a.output);
  if (!format) {
    reportError("-o must end in .vtp, .stl, .ply or .dxf, not '" + a.output + "'");
    return kExitUsage;
  }
  std::optional<Loaded> in = loadOne(a.common);
  if (!in) return kExitUsage;
  const converter::Pipeline& p = in->pipeline;
  render::SceneOptions options = sceneOptionsOf(a.mesh);
  options.movePass = converter::movePasses(p.structure, p.toolpath.moves.size());
  exporter::SurfaceData data = exporter::surfaceData(p.toolpath, p.diags.all(), options, a.caps);
  if (p.comparison) {  // --drawing: each cell's move's deviation
    const std::vector<float> byMove = exporter::moveDeviations(*p.comparison, p.toolpath.moves.size());
    data.cellDeviation.assign(data.cellMove.size(), std::numeric_limits<float>::quiet_NaN());
    for (std::size_t t = 0; t < data.cellMove.size(); ++t)
      if (data.cellMove[t] >= 0) data.cellDeviation[t] = byMove[static_cast<std::size_t>(data.cellMove[t])];
  }
  if (data.surface.mesh.triangles.empty()) {
    reportError("nothing is cut, so there is no surface to export");
    return kExitErrors;
  }
  std::string error;
  const bool written = writeOutputVia(
      a.output, in->inputs,
      [&](const std::string& tmp, std::string& err) { return exporter::writeMesh(data, *format, tmp, err); }, error);
  if (!written) {
    reportError(error);
    return kExitUsage;
  }
  std::cerr << "kerf: wrote " << data.surface.mesh.triangles.size() << " triangles, "
            << data.surface.mesh.vertices.size() << " points to " << a.output
            << (data.surface.mesh.truncated ? " (incomplete: triangle limit reached)" : "") << "\n";
  if (data.surface.leadPatchesLeftOut > 0)
    std::cerr << "kerf: note: the solid is the closed contour, capped; " << data.surface.leadPatchesLeftOut
              << (data.surface.leadPatchesLeftOut == 1 ? " move" : " moves")
              << " of the lead-in and lead-out (wire paths, not the part) are left out\n";
  return verdictExit(p);
}

}  // namespace kerf::cli
