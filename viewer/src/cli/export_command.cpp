// kerf export FILE -o part.vtp|.stl|.ply: the ruled surface for ParaView and CAD (VTK writers),
// its findings those kerf check reports for the same options.
#include "commands.h"
#include "draw.h"
#include "file_io.h"
#include "load.h"

#include "kerf/export/mesh_export.h"

#include <CLI/CLI.hpp>

#include <iostream>

namespace kerf::cli {

CLI::App* addExportCommand(CLI::App& app, ExportArgs& a) {
  CLI::App* cmd = app.add_subcommand("export", "the ruled surface as a .vtp, .stl or .ply mesh (VTK)");
  addCommonOptions(*cmd, a.common, false);
  cmd->add_option("-o,--output", a.output, "mesh file to write: .vtp, .stl or .ply")->required()->group("Mesh");
  addMeshOptions(*cmd, a.mesh, false);
  cmd->add_flag("--caps", a.caps, "close closed contours with flat caps (a solid for CAD)")->group("Mesh");
  return cmd;
}

int runExport(const ExportArgs& a) {
  const auto format = exporter::formatOfPath(a.output);
  if (!format) {
    reportError("-o must end in .vtp, .stl or .ply, not '" + a.output + "'");
    return kExitUsage;
  }
  std::optional<Loaded> in = loadOne(a.common);
  if (!in) return kExitUsage;
  const converter::Pipeline& p = in->pipeline;
  const exporter::SurfaceData data = exporter::surfaceData(p.toolpath, p.diags.all(), sceneOptionsOf(a.mesh), a.caps);
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
  return verdictExit(p);
}

}  // namespace kerf::cli
