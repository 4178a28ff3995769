// kerf view FILE: its options. The window (GLFW + Dear ImGui) is in the drawing module
// (draw/view.cpp, loaded by draw_module.h only when a command draws).
#include "commands.h"
#include "draw_module.h"

#include <CLI/CLI.hpp>

namespace kerf::cli {

CLI::App* addViewCommand(CLI::App& app, ViewArgs& a) {
  CLI::App* cmd = app.add_subcommand("view", "the interactive window: program text, 3D part and findings");
  addCommonOptions(*cmd, a.common, false);
  const std::string g = "Window";
  cmd->add_option("--screenshot", a.screenshot, "save the window as PNG after --frames frames, then close")->group(g);
  cmd->add_option("--frames", a.frames, "draw this many frames, then close")->check(CLI::Range(1, 1000000))->group(g);
  cmd->add_option("--size", a.size, "window size WIDTHxHEIGHT (default 1280x800)")->group(g);
  cmd->add_flag("--benchmark", a.benchmark, "print frame times when closing")->group(g);
  cmd->add_option("--line", a.line, "select the move on this source line")->group(g);
  cmd->add_option("--playback", a.playback, "show the wire at this fraction of the path, 0 to 1")
      ->check(CLI::Range(0.0, 1.0))
      ->group(g);
  cmd->add_flag("--coarse", a.coarse, "draw every frame as while the view moves (with --benchmark)")->group(g);
  addMeshOptions(*cmd, a.mesh, true);
  // Spelt as render spells it; the earlier flag --color-by-slope stays, hidden, for scripts.
  cmd->add_option("--color-by,--colour-by", a.colourByName,
                  "start with the surface coloured by the wire slope, or by pass (rough cut, skims), or the part edge "
                  "by its deviation from --drawing")
      ->check(CLI::IsMember({"slope", "pass", "deviation"}))
      ->group(g);
  cmd->add_flag("--color-by-slope,--colour-by-slope", a.colourBy, "the same as --color-by slope")->group("");
  return cmd;
}

int runView(const ViewArgs& a) {
  std::string error;
  const DrawCommands* draw = loadDrawCommands(error);
  if (!draw) return drawModuleMissing(error);
  ViewArgs args = a;
  args.colourBy = a.colourBy || a.colourByName == "slope";
  return draw->view(args);
}

}  // namespace kerf::cli
