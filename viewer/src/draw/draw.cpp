#include "draw.h"
#include "file_io.h"
#include "load.h"

#include "kerf/converter/interpret/dialect.h"
#include "kerf/converter/report/construction.h"

#include <algorithm>

namespace kerf::cli {

ui::Annotation annotationOf(const std::string& input, const converter::Pipeline& p) {
  ui::Annotation a;
  const std::string name = displayName(input);
  const auto slash = name.find_last_of('/');
  a.title = slash == std::string::npos ? name : name.substr(slash + 1);
  const converter::Toolpath& tp = p.toolpath;
  const std::size_t errors = p.diags.errorCount(), warnings = p.diags.warningCount();
  a.findings = errors + warnings;
  a.subtitle =
      std::string(tp.isTaper() ? converter::dialectName(tp.dialect) : "2-axis") + " | " +
      std::to_string(tp.moves.size()) + " moves | " +
      (errors ? std::to_string(errors) + (errors == 1 ? " error" : " errors") : std::string("no errors")) +
      (warnings ? ", " + std::to_string(warnings) + (warnings == 1 ? " warning" : " warnings") : std::string());
  // The wire path drawn beside what it was made from (converter::referenceGeometry).
  if (p.drawing && !p.wires.empty())
    a.subtitle += " | wire path; dashed: the drawing";
  else if (!tp.programmed.empty())
    a.subtitle += " | wire centre; dashed: as programmed";
  return a;
}

bool colourByDeviation(const converter::Pipeline& p, render::SceneOptions& so, ui::Annotation& legend) {
  if (!p.comparison) {
    reportError("--color-by deviation needs --drawing: the drawing the program should cut");
    return false;
  }
  const converter::DrawingComparison& c = *p.comparison;
  double worst = c.worst;
  auto fill = [&worst](const converter::DrawingComparison& comparison, render::SceneOptions::DeviationEdge& edge) {
    for (const converter::EdgeDeviation& e : comparison.edge) {
      edge.pieces.push_back(e.segment);
      edge.deviations.push_back(e.deviation);
    }
    worst = std::max(worst, comparison.worst);
  };
  fill(c, so.deviationLower);
  if (p.comparisonUpper) fill(*p.comparisonUpper, so.deviationUpper);
  so.deviationScale = std::max(2.0 * c.tolerance, worst);
  legend.deviationScaleUm = so.deviationScale * 1000.0;
  legend.toleranceUm = c.tolerance * 1000.0;
  return true;
}

std::optional<std::size_t> moveOnLine(const converter::Pipeline& p, std::size_t line, const std::string& option) {
  if (line <= UINT32_MAX)
    if (const auto move = converter::moveOnLine(p.toolpath, static_cast<std::uint32_t>(line))) return move;
  std::optional<std::uint32_t> before, after;
  for (const converter::Move& m : p.toolpath.moves) {
    if (m.line < line && (!before || m.line > *before)) before = m.line;
    if (m.line > line && (!after || m.line < *after)) after = m.line;
  }
  std::string nearest;
  if (before) nearest += "line " + std::to_string(*before);
  if (after) nearest += (nearest.empty() ? "line " : " or line ") + std::to_string(*after);
  reportError(option + " " + std::to_string(line) + ": no move is programmed on that line" +
              (nearest.empty() ? std::string(": the program has no moves") : "; the nearest moves are on " + nearest));
  return std::nullopt;
}

render::SceneOptions sceneOptionsOf(const MeshOptions& mesh) {
  render::SceneOptions so;
  if (mesh.tolerance) so.tolerance = *mesh.tolerance;
  if (mesh.generators) so.generators = *mesh.generators;
  so.showGuides = std::find(mesh.show.begin(), mesh.show.end(), "guides") != mesh.show.end();
  return so;
}

bool guidesShowable(const converter::Pipeline& p, const render::SceneOptions& so) {
  if (!so.showGuides || (p.toolpath.heights.guides && p.toolpath.heights.known)) return true;
  reportError(p.toolpath.isTaper()
                  ? "--show guides: no guide heights are given (--guides LOWER_Z,UPPER_Z, cnc3's M100 P Q, or a "
                    "profile's guides)"
                  : "--show guides: a 2-axis program's wire stands upright; the guides matter to a taper program");
  return false;
}

}  // namespace kerf::cli
