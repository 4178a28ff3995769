// kerf view FILE: the window (GLFW + Dear ImGui), with the findings kerf check reports for the
// same options.
#include "commands.h"
#include "draw.h"
#include "load.h"

#include "window/window.h"

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
  cmd->add_flag("--color-by-slope,--colour-by-slope", a.colourBy, "start with the surface coloured by slope")->group(g);
  return cmd;
}

int runView(const ViewArgs& a) {
  window::WindowRequest request;
  if (!sizeOption(a.size, request.width, request.height)) return kExitUsage;
  if (a.screenshot && a.frames <= 0) {
    reportError("--screenshot needs --frames N: the window is saved after N frames");
    return kExitUsage;
  }
  const std::string& file = a.common.input.files.front();
  std::optional<Loaded> in = loadOne(a.common);
  if (!in) return kExitUsage;
  const converter::Pipeline& p = in->pipeline;
  request.reference = converter::referenceGeometry(p);
  const render::Scene scene = render::buildScene(p.toolpath, p.diags.all(), sceneOptionsOf(a.mesh), request.reference);
  request.source = p.source.get();
  request.toolpath = &p.toolpath;
  request.findings = p.diags.all();
  request.scene = &scene;
  request.sceneOptions = sceneOptionsOf(a.mesh);
  request.coarseFrames = a.coarse;
  request.annotation = annotationOf(file, p);
  request.annotation.legend = true;
  request.options.colourBySlope = a.colourBy;
  request.step = a.common.sampling.step.value_or(SamplingOptions::kDefaultStep);
  request.screenshot = a.screenshot;
  request.frames = a.frames;
  request.benchmark = a.benchmark;
  request.selectLine = a.line;
  request.playback = a.playback;
  request.inputs = in->inputs;
  std::string error;
  if (!window::runWindow(request, error)) {
    reportError(error);
    return kExitUsage;
  }
  return verdictExit(p);
}

}  // namespace kerf::cli
