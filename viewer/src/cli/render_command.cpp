// kerf render FILE -o part.png: its options. The picture itself is drawn by the drawing module
// (draw/render.cpp, loaded by draw_module.h only when a command draws).
#include "commands.h"
#include "draw_module.h"

#include <CLI/CLI.hpp>

namespace kerf::cli {

CLI::App* addRenderCommand(CLI::App& app, RenderArgs& a) {
  CLI::App* cmd = app.add_subcommand("render", "a picture of the part as PNG, with no display and no GPU");
  addCommonOptions(*cmd, a.common, false);
  const std::string g = "Picture";
  cmd->add_option("-o,--output", a.output, "PNG file to write")->required()->group(g);
  cmd->add_option("--view", a.view, "iso (default), top, front or side")
      ->check(CLI::IsMember({"iso", "top", "front", "side"}))
      ->group(g);
  cmd->add_option("--size", a.size, "WIDTHxHEIGHT in pixels (default 800x600)")->group(g);
  cmd->add_option("--color-by,--colour-by", a.colourBy,
                  "colour the surface by the wire slope, the surface and contours by pass (rough cut, skims), or "
                  "the part edge by its deviation from --drawing (with a legend)")
      ->check(CLI::IsMember({"slope", "pass", "deviation"}))
      ->group(g);
  cmd->add_flag("--highlight-findings", a.highlight, "tint moves with findings and label the findings")->group(g);
  cmd->add_option("--explain-line", a.explainLine,
                  "draw how the block on line N follows from its words (as kerf explain says it, at --step), "
                  "with its words and modes, and print the marks' labels")
      ->check(CLI::Range(1u, 0xFFFFFFFFu))
      ->group(g);
  cmd->add_option("--backend", a.backend, "headless OpenGL: auto (OSMesa, then EGL), osmesa or egl")
      ->check(CLI::IsMember({"auto", "osmesa", "egl"}))
      ->group(g);
  cmd->add_option("--samples", a.samples,
                  "multisampling (1: none; default 4, or 1 when the triangles outnumber half the pixels)")
      ->check(CLI::Range(1, 16))
      ->group(g);
  cmd->add_flag("--timings", a.timings, "print the time of each stage")->group(g);
  addMeshOptions(*cmd, a.mesh, true);
  return cmd;
}

int runRender(const RenderArgs& a) {
  std::string error;
  const DrawCommands* draw = loadDrawCommands(error);
  if (!draw) return drawModuleMissing(error);
  return draw->render(a);
}

}  // namespace kerf::cli
