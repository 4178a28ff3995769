// The commands of the kerf program: each declares its own options (besides the common groups of
// options.h) and runs through the pipeline; main() only dispatches and returns the exit code.
#pragma once

#include "options.h"

#include "kerf/converter/convert.h"

#include <cstdint>
#include <optional>
#include <string>

namespace CLI {
class App;
}

namespace kerf::cli {

struct CheckArgs {
  CommonOptions common;
  std::string format = "text";  ///< --format text|json|sarif|junit|html
  bool json = false;            ///< --json: --format json
  bool trace = false;
  std::string output;  ///< -o DIR: the html report's folder
};
CLI::App* addCheckCommand(CLI::App& app, CheckArgs& args);
int runCheck(const CheckArgs& args);

struct ExplainArgs {
  CommonOptions common;
  bool json = false;
};
CLI::App* addExplainCommand(CLI::App& app, ExplainArgs& args);
int runExplain(const ExplainArgs& args);

/// kerf convert: the library's request, bound by the options; the files they name, and where the
/// output goes.
struct ConvertArgs {
  CommonOptions common;
  converter::ConvertRequest request;
  std::optional<std::string> profile;  ///< --profile FILE: a point-file profile
  std::optional<std::string> target;   ///< --for NAME or FILE
  std::string output = "-";
  bool list = false;
};
CLI::App* addConvertCommand(CLI::App& app, ConvertArgs& args);
int runConvert(const ConvertArgs& args);

struct RenderArgs {
  CommonOptions common;
  std::string output;
  std::string view = "iso";
  std::string size = "800x600";
  std::optional<std::string> colourBy;
  bool highlight = false;
  std::optional<std::uint32_t> explainLine;  ///< --explain-line: that block's construction drawn
  std::string backend = "auto";
  int samples = 0;
  MeshOptions mesh;
  bool timings = false;
};
CLI::App* addRenderCommand(CLI::App& app, RenderArgs& args);
int runRender(const RenderArgs& args);

struct ExportArgs {
  CommonOptions common;
  std::string output;
  MeshOptions mesh;
  bool caps = false;
  std::string dxfVersion = "r2000";          ///< -o .dxf: r12 or r2000
  bool rapids = false;                       ///< -o .dxf: the rapids too, on layer RAPID
  std::optional<std::size_t> pageTriangles;  ///< -o .html: above this, the part is sent coarse
};
CLI::App* addExportCommand(CLI::App& app, ExportArgs& args);
int runExport(const ExportArgs& args);

/// kerf check --format html, in the drawing module: each program's pictures and 3D page, written
/// into the report's new folder before it is put in place (check_command.cpp).
struct ReportArgs {
  const CommonOptions* common = nullptr;  ///< the check's options
  std::vector<std::string> files;         ///< the programs, as checked
  std::vector<std::string> names;         ///< their names on the pages
  std::vector<std::string> stems;         ///< each program's stem in the folder (ReportAssets)
  std::string folder;
};

/// The files of a program in the report's folder beside its page <stem>.html.
struct ReportAssets {
  std::string thumbnail, top, iso, page3d;
  explicit ReportAssets(const std::string& stem)
      : thumbnail(stem + ".thumb.png"), top(stem + ".top.png"), iso(stem + ".iso.png"), page3d(stem + ".3d.html") {}
};

struct ViewArgs {
  CommonOptions common;
  std::optional<std::string> screenshot;
  int frames = 0;
  std::string size = "1280x800";
  bool benchmark = false;
  std::optional<std::size_t> line;
  double playback = -1;
  MeshOptions mesh;
  bool colourBy = false;     ///< start with the surface coloured by slope
  std::string colourByName;  ///< --color-by slope|pass, as render spells it
  bool coarse = false;
};
CLI::App* addViewCommand(CLI::App& app, ViewArgs& args);
int runView(const ViewArgs& args);

/// kerf cam: the library's request, bound by the options (the common ones give the drawing,
/// --machine, --offset, --side and --start, the start vertex), and where the output goes.
struct CamArgs {
  CommonOptions common;
  converter::CamRequest request;
  std::string output = "-";
};
CLI::App* addCamCommand(CLI::App& app, CamArgs& args);
int runCam(const CamArgs& args);

struct MachinesArgs {
  std::optional<std::string> show;
};
CLI::App* addMachinesCommand(CLI::App& app, MachinesArgs& args);
int runMachines(const MachinesArgs& args);

}  // namespace kerf::cli
