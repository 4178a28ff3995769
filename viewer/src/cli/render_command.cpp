// kerf render FILE -o part.png: a headless picture (no display, no GPU), with the findings kerf
// check reports for the same options.
#include "commands.h"
#include "draw.h"
#include "file_io.h"
#include "load.h"

#include "kerf/converter/points.h"
#include "kerf/headless/context.h"
#include "kerf/render/scene.h"
#include "ui/picture.h"

#include <CLI/CLI.hpp>

#include <iostream>

namespace kerf::cli {

CLI::App* addRenderCommand(CLI::App& app, RenderArgs& a) {
  CLI::App* cmd = app.add_subcommand("render", "a picture of the part as PNG, with no display and no GPU");
  addCommonOptions(*cmd, a.common, false);
  const std::string g = "Picture";
  cmd->add_option("-o,--output", a.output, "PNG file to write")->required()->group(g);
  cmd->add_option("--view", a.view, "iso, top, front or side")
      ->check(CLI::IsMember({"iso", "top", "front", "side"}))
      ->group(g);
  cmd->add_option("--size", a.size, "WIDTHxHEIGHT in pixels (default 800x600)")->group(g);
  cmd->add_option("--color-by,--colour-by", a.colourBy, "colour the surface by the wire slope")
      ->check(CLI::IsMember({"slope"}))
      ->group(g);
  cmd->add_flag("--highlight-findings", a.highlight, "tint moves with findings and label the findings")->group(g);
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
  ui::PictureRequest request;
  if (!sizeOption(a.size, request.width, request.height)) return kExitUsage;
  request.view = *render::parseView(a.view);
  request.backend = *headless::parseBackend(a.backend);
  request.samples = a.samples;
  request.options.colourBySlope = a.colourBy.has_value();
  request.options.highlightFindings = a.highlight;
  const std::string& file = a.common.input.files.front();
  std::optional<Loaded> in = loadOne(a.common);
  if (!in) return kExitUsage;
  const converter::Pipeline& p = in->pipeline;
  const std::vector<geometry::Segment> reference = converter::referenceGeometry(p);
  const render::Scene scene = render::buildScene(p.toolpath, p.diags.all(), sceneOptionsOf(a.mesh), reference);
  request.annotation = annotationOf(file, p);
  request.annotation.legend = request.options.colourBySlope;
  request.annotation.labels = a.highlight;
  const ui::PictureResult result = ui::renderPicture(scene, request);
  if (result.png.empty()) {
    reportError(result.error);
    return kExitUsage;
  }
  std::string error;
  if (!writeOutput(a.output, in->inputs, result.png, error)) {
    reportError(error);
    return kExitUsage;
  }
  std::cerr << "kerf: wrote " << request.width << "x" << request.height << " " << render::viewName(request.view)
            << " view (" << scene.triangles() << " triangles) to " << a.output << "\n";
  if (a.timings)
    std::cerr << "kerf: " << result.context << "; context " << converter::formatFixed(result.contextSeconds, 3)
              << " s, upload " << converter::formatFixed(result.uploadSeconds, 3) << " s, draw+read "
              << converter::formatFixed(result.drawSeconds, 3) << " s, PNG "
              << converter::formatFixed(result.encodeSeconds, 3) << " s\n";
  return verdictExit(p);
}

}  // namespace kerf::cli
