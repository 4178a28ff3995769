// kerf export FILE -o part.dxf: the contours as a drawing (converter/formats/dxf/write_dxf.h); -o
// part.vtp|.stl|.ply: the ruled surface for ParaView and CAD, written with VTK by the drawing
// module (draw/export.cpp). Its findings are those kerf check reports for the same options.
#include "commands.h"
#include "draw_module.h"
#include "file_io.h"
#include "load.h"

#include "kerf/converter/formats/dxf/write_dxf.h"

#include <CLI/CLI.hpp>

#include <cctype>
#include <iostream>

namespace kerf::cli {

CLI::App* addExportCommand(CLI::App& app, ExportArgs& a) {
  CLI::App* cmd = app.add_subcommand(
      "export", "the ruled surface as a .vtp, .stl or .ply mesh (VTK), or the contours as a .dxf drawing");
  addCommonOptions(*cmd, a.common, false);
  cmd->add_option("-o,--output", a.output, "file to write: .vtp, .stl, .ply (a mesh) or .dxf (a drawing)")
      ->required()
      ->group("Output");
  addMeshOptions(*cmd, a.mesh, false);
  cmd->add_flag("--caps", a.caps, "close closed contours with flat caps (a solid for CAD)")->group("Mesh");
  cmd->add_option("--dxf", a.dxfVersion, "DXF version: r12 or r2000 (default)")->group("Drawing");
  cmd->add_flag("--rapids", a.rapids, "DXF: the rapids too, on layer RAPID")->group("Drawing");
  return cmd;
}

namespace {

bool endsWithDxf(const std::string& path) {
  if (path.size() < 4) return false;
  std::string ext = path.substr(path.size() - 4);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".dxf";
}

int runDxfExport(const ExportArgs& a) {
  const std::optional<converter::DxfVersion> version = converter::dxfVersionNamed(a.dxfVersion);
  if (!version) {
    reportError("--dxf must be r12 or r2000, not '" + a.dxfVersion + "'");
    return kExitUsage;
  }
  std::optional<Loaded> in = loadOne(a.common);
  if (!in) return kExitUsage;
  const converter::Pipeline& p = in->pipeline;
  converter::DxfWriteOptions options;
  options.version = *version;
  options.rapids = a.rapids;
  options.movePass = converter::movePasses(p.structure, p.toolpath.moves.size());
  if (p.comparison)  // --drawing: its elements out of tolerance on DEVIATION
    for (const converter::ElementDeviation& e : p.comparison->elements)
      if (e.deviation > p.comparison->tolerance) options.deviation.push_back(p.comparison->drawn[e.element]);
  converter::DxfWriteCounts counts;
  const std::string text = converter::writeDxf(p.toolpath, options, &counts);
  if (counts.lines + counts.arcs + counts.circles == 0) {
    reportError("nothing is cut, so there is no contour to export");
    return kExitErrors;
  }
  std::string error;
  if (!writeOutput(a.output, in->inputs, text, error)) {
    reportError(error);
    return kExitUsage;
  }
  std::cerr << "kerf: wrote " << counts.lines << " lines, " << counts.arcs << " arcs, " << counts.circles
            << " circles to " << a.output << " (DXF " << (*version == converter::DxfVersion::R12 ? "R12" : "R2000")
            << ")\n";
  return verdictExit(p);
}

}  // namespace

int runExport(const ExportArgs& a) {
  if (endsWithDxf(a.output)) return runDxfExport(a);
  if (a.rapids || a.dxfVersion != "r2000") {
    reportError("--dxf and --rapids are for a drawing: -o must end in .dxf");
    return kExitUsage;
  }
  std::string error;
  const DrawCommands* draw = loadDrawCommands(error);
  if (!draw) return drawModuleMissing(error);
  return draw->exportMesh(a);
}

}  // namespace kerf::cli
