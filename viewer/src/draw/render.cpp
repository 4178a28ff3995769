// kerf render FILE -o part.png, in the drawing module: a headless picture (no display, no GPU),
// with the findings kerf check reports for the same options.
#include "draw.h"
#include "file_io.h"
#include "load.h"

#include "kerf/converter/interpret/machine.h"
#include "kerf/converter/nc/number_format.h"
#include "kerf/converter/report/construction.h"
#include "kerf/headless/context.h"
#include "kerf/render/construction_scene.h"
#include "kerf/render/scene.h"
#include "ui/picture.h"

#include <iostream>
#include <limits>

namespace kerf::cli {

std::optional<render::Scene> pictureScene(const converter::Pipeline& p, const std::string& file,
                                          const MeshOptions& mesh, const std::string& colourBy,
                                          ui::PictureRequest& request, render::SceneOptions& so) {
  request.options.colourBySlope = colourBy == "slope";
  request.options.colourByPass = colourBy == "pass";
  const std::vector<geometry::Segment> reference = converter::referenceGeometry(p);
  // No mesh piece is forced narrower than a pixel, and no line follows its arc closer than a
  // quarter of one (half a pixel shows the surface's edge beside the line): finer shows nothing
  // (docs/rendering.md).
  so = sceneOptionsOf(mesh);
  if (!guidesShowable(p, so)) return std::nullopt;
  if (p.comparisonUpper) so.referenceUpper = p.comparisonUpper->drawn;
  so.minForcedPieceLength = ui::picturePixelMm(p.toolpath, so, request);
  so.lineTolerance = 0.25 * so.minForcedPieceLength;
  if (request.options.colourByPass) {
    so.movePass = converter::movePasses(p.structure, p.toolpath.moves.size());
    so.passLines = true;
  }
  request.annotation = annotationOf(file, p);
  if (colourBy == "deviation" && !colourByDeviation(p, so, request.annotation)) return std::nullopt;
  render::Scene scene = render::buildScene(p.toolpath, p.diags.all(), so, reference);
  request.annotation.legend = request.options.colourBySlope;
  if (request.options.colourByPass)
    for (std::size_t k = 1; k <= std::min(scene.passes, render::kPassColours); ++k)
      request.annotation.passLegend.push_back("pass " + std::to_string(k) + (k == 1 ? " (rough)" : ""));
  return scene;
}

int drawRender(const RenderArgs& a) {
  ui::PictureRequest request;
  if (!sizeOption(a.size, request.width, request.height)) return kExitUsage;
  request.view = *render::parseView(a.view);
  request.backend = *headless::parseBackend(a.backend);
  request.samples = a.samples;
  request.options.highlightFindings = a.highlight;
  const std::string& file = a.common.input.files.front();
  std::optional<Loaded> in = loadOne(a.common, {.centreWords = a.explainLine.has_value()});
  if (!in) return kExitUsage;
  const converter::Pipeline& p = in->pipeline;
  render::SceneOptions so;
  std::optional<render::Scene> built = pictureScene(p, file, a.mesh, a.colourBy.value_or(""), request, so);
  if (!built) return kExitUsage;
  render::Scene& scene = *built;
  request.annotation.labels = a.highlight;
  render::ConstructionScene construction;
  if (a.explainLine) {
    const std::optional<std::size_t> move = moveOnLine(p, *a.explainLine, "--explain-line");
    if (!move) return kExitUsage;
    const converter::Construction c =
        converter::constructionOf(*p.source, p.toolpath, &p.structure, a.common.sampling.sampling(), *move,
                                  converter::parseOptionsFor(p.machine));
    construction = render::constructionScene(c, scene.planes, so.lineTolerance > 0 ? so.lineTolerance : so.tolerance);
    request.annotation.construction = &construction;
    // The picture frames the construction (with the part's heights), not the whole part.
    geometry::Vec3 lo = geometry::Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    render::extendBounds(construction, lo, hi);
    if (lo.allFinite() && hi.allFinite()) {
      lo.z() = std::min(lo.z(), scene.boundsMin.z());
      hi.z() = std::max(hi.z(), scene.boundsMax.z());
      scene.boundsMin = lo;
      scene.boundsMax = hi;
    }
    // The figure's key, for a worksheet: what the picture says, as text.
    std::cout << "line " << c.line << ": " << c.block << "\n";
    for (const converter::ConstructionMark& m : c.marks)
      if (!m.label.empty()) std::cout << "  " << m.label << "\n";
  }
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
