// kerf export FILE -o part.dxf: the contours as a drawing (converter/formats/dxf/write_dxf.h); -o
// part.vtp|.stl|.ply: the ruled surface for ParaView and CAD, written with VTK by the drawing
// module (draw/export.cpp); -o part.html: the 3D page that teaches (draw/page.cpp). Its findings
// are those kerf check reports for the same options.
#include "commands.h"
#include "draw_module.h"
#include "file_io.h"
#include "load.h"

#include "kerf/converter/convert.h"

#include <CLI/CLI.hpp>

#include <cctype>
#include <iostream>
#include <string_view>

namespace kerf::cli {

CLI::App* addExportCommand(CLI::App& app, ExportArgs& a) {
  CLI::App* cmd = app.add_subcommand(
      "export",
      "the ruled surface as a .vtp, .stl or .ply mesh (VTK), the contours as a .dxf drawing, or the part in 3D "
      "beside the program as one .html page");
  addCommonOptions(*cmd, a.common, false);
  cmd->add_option("-o,--output", a.output,
                  "file to write: .vtp, .stl, .ply (a mesh), .dxf (a drawing) or .html (a 3D page)")
      ->required()
      ->group("Output");
  addMeshOptions(*cmd, a.mesh, false);
  cmd->add_flag("--caps", a.caps, "close closed contours with flat caps (a solid for CAD)")->group("Mesh");
  cmd->add_option("--page-triangles", a.pageTriangles,
                  "3D page: above this many triangles the part is sent at the coarse level the window draws "
                  "while it moves (default 250000)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{100'000'000}))
      ->group("Page");
  cmd->add_option("--dxf", a.dxfVersion, "DXF version: r12 or r2000 (default)")->group("Drawing");
  cmd->add_flag("--rapids", a.rapids, "DXF: the rapids too, on layer RAPID")->group("Drawing");
  return cmd;
}

namespace {

/// The path ends in `ext` (lower case, with its dot), in any case.
bool endsWith(const std::string& path, std::string_view ext) {
  if (path.size() < ext.size()) return false;
  std::string tail = path.substr(path.size() - ext.size());
  for (char& c : tail) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return tail == ext;
}

int runDxfExport(const ExportArgs& a) {
  const std::optional<converter::DxfVersion> version = converter::dxfVersionNamed(a.dxfVersion);
  if (!version) {
    reportError("--dxf must be r12 or r2000, not '" + a.dxfVersion + "'");
    return kExitUsage;
  }
  std::optional<Loaded> in = load(a.common, a.common.input.files.front());
  if (!in) return kExitUsage;
  const converter::Pipeline& p = in->pipeline;
  // Through the writer table, as kerf convert --to dxf: a drawing says what the program does, errors
  // and all (as a picture does).
  converter::ConvertRequest request;
  request.format = "dxf";
  request.force = true;
  request.emit.dxf.version = *version;
  request.emit.dxf.rapids = a.rapids;
  const converter::Conversion c = converter::convert(p, request);
  printDiagnostics(c.diags, a.common);
  if (c.status != converter::WriteStatus::Written) return kExitErrors;
  std::string error;
  if (!writeOutput(a.output, in->inputs, c.output->text, error)) {
    reportError(error);
    return kExitUsage;
  }
  std::cerr << "kerf: wrote " << c.output->what << " to " << a.output << c.output->detail << "\n";
  return verdictExit(p);
}

}  // namespace

int runExport(const ExportArgs& a) {
  if (endsWith(a.output, ".dxf")) return runDxfExport(a);
  if (a.pageTriangles && !endsWith(a.output, ".html")) {
    reportError("--page-triangles is for a 3D page: -o must end in .html");
    return kExitUsage;
  }
  if (a.rapids || a.dxfVersion != "r2000") {
    reportError("--dxf and --rapids are for a drawing: -o must end in .dxf");
    return kExitUsage;
  }
  std::string error;
  const DrawCommands* draw = loadDrawCommands(error);
  if (!draw) return drawModuleMissing(error);
  return endsWith(a.output, ".html") ? draw->exportPage(a) : draw->exportMesh(a);
}

}  // namespace kerf::cli
