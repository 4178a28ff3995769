// In the drawing module: `kerf export FILE -o part.html` (the 3D page, export/part_page.h) and the
// pictures and 3D pages of `kerf check --format html` (ReportArgs). Their findings are those kerf
// check reports for the same options.
#include "draw.h"
#include "file_io.h"
#include "load.h"

#include "kerf/converter/interpret/machine.h"
#include "kerf/export/part_page.h"
#include "kerf/headless/context.h"

#include <filesystem>
#include <iostream>

namespace kerf::cli {
namespace {

/// The page's options for the command's: the scene as kerf render builds it, with the passes and
/// the drawing's deviations, and the constructions at the check's step.
exporter::PartPageOptions partPageOptions(const converter::Pipeline& p, const CommonOptions& common,
                                          const MeshOptions& mesh) {
  exporter::PartPageOptions o;
  o.scene = sceneOptionsOf(mesh);
  o.scene.movePass = converter::movePasses(p.structure, p.toolpath.moves.size());
  if (p.comparisonUpper) o.scene.referenceUpper = p.comparisonUpper->drawn;
  if (p.comparison) {
    ui::Annotation legend;  // the page draws its own
    colourByDeviation(p, o.scene, legend);
  }
  o.sampling = common.sampling.sampling();
  o.parse = converter::parseOptionsFor(p.machine);
  return o;
}

/// One picture of the report, as kerf render draws it; empty (said) when it cannot be drawn.
std::string reportPicture(const converter::Pipeline& p, const std::string& file, render::View view, int width,
                          int height, bool annotated) {
  ui::PictureRequest request;
  request.view = view;
  request.width = width;
  request.height = height;
  render::SceneOptions so;
  const std::optional<render::Scene> scene = pictureScene(p, file, {}, exporter::tellingColouring(p), request, so);
  if (!scene) return {};
  if (!annotated) request.annotation = {};
  ui::PictureResult result = ui::renderPicture(*scene, request);
  if (result.png.empty()) std::cerr << "kerf: " << displayName(file) << ": no picture: " << result.error << "\n";
  return std::move(result.png);
}

bool writeInFolder(const std::string& folder, const std::string& name, const std::string& bytes) {
  if (bytes.empty()) return false;
  std::string error;
  if (writeFileIn(folder, name, bytes, error)) return true;
  reportError(error);
  return false;
}

}  // namespace

int drawExportPage(const ExportArgs& a) {
  if (a.caps) {
    reportError("--caps closes a mesh for CAD: the 3D page shows the surface the wire cuts");
    return kExitUsage;
  }
  const std::string& file = a.common.input.files.front();
  std::optional<Loaded> in = loadOne(a.common, {.centreWords = true});
  if (!in) return kExitUsage;
  const converter::Pipeline& p = in->pipeline;
  exporter::PartPageOptions options = partPageOptions(p, a.common, a.mesh);
  if (a.pageTriangles) options.triangleBudget = *a.pageTriangles;
  if (!guidesShowable(p, options.scene)) return kExitUsage;
  const converter::Diagnostics shown = shownDiagnostics(p.diags, a.common.checks);
  const exporter::PartPage page = exporter::partPage(p, displayName(file), shown.all(), options);
  std::string error;
  if (!writeOutput(a.output, in->inputs, page.html, error)) {
    reportError(error);
    return kExitUsage;
  }
  std::cerr << "kerf: wrote the 3D page (" << page.triangles << " triangles"
            << (page.coarse ? ", coarse: more than " + std::to_string(options.triangleBudget) + " at the tolerance"
                            : std::string())
            << "; the construction of " << page.constructions << (page.constructions == 1 ? " block" : " blocks")
            << ", " << page.html.size() / 1024 << " KiB) to " << a.output << "\n";
  return verdictExit(p);
}

std::size_t drawReportPictures(const ReportArgs& a) {
  // The 3D pages share one copy of their scripts (three.js is most of a page).
  for (const exporter::PageScript& script : exporter::partPageScripts())
    if (!writeInFolder(a.folder, script.file, std::string(script.text))) return 0;
  std::size_t drawn = 0;
  for (std::size_t i = 0; i < a.files.size(); ++i) {
    // Read again here: the program and the module share no object (draw_module.h), so the check's
    // pipelines stay on the program's side.
    std::string failure;
    std::optional<Loaded> in = loadQuietly(*a.common, a.files[i], {.centreWords = true}, failure);
    if (!in || !in->pipeline.read) continue;  // its row says why
    const converter::Pipeline& p = in->pipeline;
    const ReportAssets names(a.stems[i]);
    bool all =
        writeInFolder(a.folder, names.thumbnail, reportPicture(p, a.files[i], render::View::Iso, 160, 120, false));
    all = writeInFolder(a.folder, names.top, reportPicture(p, a.files[i], render::View::Top, 480, 360, true)) && all;
    all = writeInFolder(a.folder, names.iso, reportPicture(p, a.files[i], render::View::Iso, 480, 360, true)) && all;
    const converter::Diagnostics shown = shownDiagnostics(p.diags, a.common->checks);
    exporter::PartPageOptions options = partPageOptions(p, *a.common, {});
    options.scriptFiles = true;
    const exporter::PartPage page = exporter::partPage(p, a.names[i], shown.all(), options);
    all = writeInFolder(a.folder, names.page3d, page.html) && all;
    drawn += all;
  }
  return drawn;
}

}  // namespace kerf::cli
