// kerf view FILE, in the drawing module: the window (GLFW + Dear ImGui), with the findings kerf
// check reports for the same options.
#include "draw.h"
#include "load.h"

#include "window/window.h"

#include "kerf/converter/interpret/machine.h"

namespace kerf::cli {

int drawView(const ViewArgs& a) {
  window::WindowRequest request;
  if (!sizeOption(a.size, request.width, request.height)) return kExitUsage;
  if (a.screenshot && a.frames <= 0) {
    reportError("--screenshot needs --frames N: the window is saved after N frames");
    return kExitUsage;
  }
  const std::string& file = a.common.input.files.front();
  std::optional<Loaded> in = loadOne(a.common, {.centreWords = true});  // the block panel says how arcs were written
  if (!in) return kExitUsage;
  const converter::Pipeline& p = in->pipeline;
  if (a.line && !moveOnLine(p, *a.line, "--line")) return kExitUsage;
  request.reference = converter::referenceGeometry(p);
  render::SceneOptions so = sceneOptionsOf(a.mesh);
  if (!guidesShowable(p, so)) return kExitUsage;
  if (p.comparisonUpper) so.referenceUpper = p.comparisonUpper->drawn;
  so.movePass = converter::movePasses(p.structure, p.toolpath.moves.size());  // the window's colour by pass
  request.annotation = annotationOf(file, p);
  if (a.colourByName == "deviation" && !colourByDeviation(p, so, request.annotation)) return kExitUsage;
  const render::Scene scene = render::buildScene(p.toolpath, p.diags.all(), so, request.reference);
  request.structure = &p.structure;
  request.source = p.source.get();
  request.parse = converter::parseOptionsFor(p.machine);
  request.toolpath = &p.toolpath;
  request.findings = p.diags.all();
  request.scene = &scene;
  request.sceneOptions = so;
  request.coarseFrames = a.coarse;
  request.comparison = p.comparison ? &*p.comparison : nullptr;
  request.comparisonUpper = p.comparisonUpper ? &*p.comparisonUpper : nullptr;
  request.annotation.legend = true;
  request.options.colourBySlope = a.colourBy;
  request.options.colourByPass = a.colourByName == "pass";
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
