// The commands of the kerf program: each declares its own options (besides the common groups of
// options.h) and runs through the pipeline; main() only dispatches and returns the exit code.
#pragma once

#include "options.h"

#include <cstdint>
#include <optional>
#include <string>

namespace CLI {
class App;
}

namespace kerf::cli {

struct CheckArgs {
  CommonOptions common;
  std::string format = "text";  ///< --format text|json|sarif|junit
  bool json = false;            ///< --json: --format json
  bool trace = false;
};
CLI::App* addCheckCommand(CLI::App& app, CheckArgs& args);
int runCheck(const CheckArgs& args);

struct ExplainArgs {
  CommonOptions common;
  bool json = false;
};
CLI::App* addExplainCommand(CLI::App& app, ExplainArgs& args);
int runExplain(const ExplainArgs& args);

struct ConvertArgs {
  CommonOptions common;
  std::string to;
  std::optional<std::string> plane;
  std::string uv = "absolute";
  std::string output = "-";
  std::optional<std::size_t> maxPoints;
  std::optional<std::string> profile;
  std::optional<std::uint32_t> startBlock;
  bool force = false;
  bool list = false;
  std::optional<std::string> target;  ///< --for
  std::optional<int> decimals;
  bool compact = false;
  std::string end = "dd";
  std::string polarXOut = "diameter";
  std::string pass = "all";  ///< --pass N: only each contour's Nth pass (1: the rough cut)
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
  std::string dxfVersion = "r2000";  ///< -o .dxf: r12 or r2000
  bool rapids = false;               ///< -o .dxf: the rapids too, on layer RAPID
};
CLI::App* addExportCommand(CLI::App& app, ExportArgs& args);
int runExport(const ExportArgs& args);

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

struct CamArgs {
  CommonOptions common;  ///< the drawing, --machine, --offset, --side, --start (the start vertex)
  std::string to = "iso";
  std::string output = "-";
  std::optional<std::size_t> contour;
  std::optional<std::string> entry;  ///< X,Y
  double leadIn = 2.0;
  std::string offsetBy = "kerf";         ///< kerf | controller
  std::optional<std::string> direction;  ///< cw | ccw: overrides the wire on the right
  std::optional<std::string> shift;      ///< DX,DY
  std::optional<int> decimals;
  bool compact = false;
  std::string end = "dd";
  std::optional<std::size_t> maxPoints;
  bool openPaths = false;
};
CLI::App* addCamCommand(CLI::App& app, CamArgs& args);
int runCam(const CamArgs& args);

struct MachinesArgs {
  std::optional<std::string> show;
};
CLI::App* addMachinesCommand(CLI::App& app, MachinesArgs& args);
int runMachines(const MachinesArgs& args);

}  // namespace kerf::cli
