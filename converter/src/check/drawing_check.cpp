#include "kerf/converter/check/drawing_check.h"

#include "finding.h"
#include "kerf/converter/nc/number_format.h"
#include "kerf/geometry/chain.h"
#include "kerf/geometry/deviation.h"

#include <algorithm>
#include <set>

namespace kerf::converter {

namespace {

/// The moves of the part edge (see the header), in order.
std::vector<std::size_t> edgeMoves(const Toolpath& tp, const Structure& structure) {
  std::set<std::size_t> moves;
  for (const Contour& c : structure.contours) {
    const Pass* last = nullptr;
    for (const Pass& p : c.passes)
      if (!p.cutOff) last = &p;
    for (const Pass& p : c.passes)
      if (&p == last || p.cutOff)
        for (std::size_t i = p.alongFirst; i < p.alongEnd && i < tp.moves.size(); ++i)
          if (tp.moves[i].isCut()) moves.insert(i);
  }
  return {moves.begin(), moves.end()};
}

/// Move i as programmed: the contour the program wrote where a wire offset was applied.
geometry::Segment programmedOf(const Toolpath& tp, std::size_t i) {
  return i < tp.programmed.size() ? tp.programmed[i] : tp.moves[i].lower;
}

/// "LINE", "ARC", "arc of an LWPOLYLINE".
std::string elementName(const DrawnElement& e) {
  if (e.entity == "LINE" || e.entity == "ARC" || e.entity == "CIRCLE") return e.entity;
  return std::string(e.segment.isArc() ? "arc" : "line") + (e.entity.empty() ? "" : " of the " + e.entity);
}

std::string um(double mm) { return formatFixed(mm * 1000.0, 1) + " µm"; }

/// K0631: closed contours of the drawing that no move comes near (every element off by more than
/// the tolerance). Their elements are said once, as the contour.
std::set<std::size_t> reportUncut(const std::vector<DrawnElement>& drawing, const DrawingComparison& out,
                                  const SourceFile* drawingSource, Diagnostics& diags) {
  std::set<std::size_t> said;
  std::vector<geometry::Segment> segments;
  for (const DrawnElement& e : drawing) segments.push_back(e.segment);
  for (const geometry::Chain& chain : geometry::chainSegments(segments, {})) {
    if (!chain.closed) continue;
    const bool allOff = std::all_of(chain.elements.begin(), chain.elements.end(),
                                    [&](std::size_t k) { return out.elements[k].deviation > out.tolerance; });
    if (!allOff) continue;
    geometry::Box box;
    for (const geometry::Segment& s : chain.path) box.add(s.bounds());
    const DrawnElement& first = drawing[chain.elements.front()];
    const geometry::Vec2 centre = 0.5 * (box.min + box.max);
    diags.error(Code::DrawingContourNotCut, drawingSource, first.span,
                "the drawing's contour around " + formatPoint(centre) + " (" + std::to_string(chain.elements.size()) +
                    (chain.elements.size() == 1 ? " element" : " elements") +
                    ") is not cut: no move comes within the tolerance of it",
                "a hole or an outline the program forgot, or a drawing placed elsewhere (--drawing-origin)");
    said.insert(chain.elements.begin(), chain.elements.end());
  }
  return said;
}

}  // namespace

DrawingComparison compareWithDrawing(const Toolpath& tp, const Structure& structure,
                                     const std::vector<DrawnElement>& drawing, const DrawingCheckOptions& options,
                                     const SourceFile* program, const SourceFile* drawingSource, Diagnostics& diags) {
  DrawingComparison out;
  out.drawing = drawingSource ? drawingSource->name() : std::string();
  out.tolerance = options.tolerance;
  const std::vector<std::size_t> moves = edgeMoves(tp, structure);
  std::vector<geometry::Segment> edge;
  for (const std::size_t i : moves) edge.push_back(programmedOf(tp, i));
  std::vector<geometry::Segment> drawn;
  for (const DrawnElement& e : drawing) {
    geometry::Segment s = e.segment;
    s.start -= options.origin;
    s.end -= options.origin;
    s.centre -= options.origin;
    drawn.push_back(s);
  }
  const geometry::DeviationSet edgeSet(edge), drawnSet(drawn);
  for (std::size_t k = 0; k < drawn.size(); ++k) {
    const geometry::Farthest f = geometry::farthestFrom(drawn[k], edgeSet, options.precision);
    const std::size_t move = moves.empty() ? 0 : moves[f.nearest];
    out.elements.push_back({k, f.distance, f.at, move, drawing[k].line, moves.empty() ? 0 : tp.moves[move].line});
    out.worst = std::max(out.worst, f.distance);
  }
  for (std::size_t j = 0; j < edge.size(); ++j) {
    const geometry::Farthest f = geometry::farthestFrom(edge[j], drawnSet, options.precision);
    out.edge.push_back({moves[j], f.distance, f.at});
    out.worst = std::max(out.worst, f.distance);
  }
  const std::set<std::size_t> uncut = reportUncut(drawing, out, drawingSource, diags);
  for (const ElementDeviation& e : out.elements) {
    if (e.deviation <= options.tolerance) continue;
    ++out.outOfTolerance;
    if (uncut.count(e.element) || moves.empty()) continue;
    const DrawnElement& d = drawing[e.element];
    diags.report(
        finding(Severity::Error, Code::DrawingElementOff, program, tp.moves[e.move], e.move, {e.at.x(), e.at.y(), 0.0},
                "the drawing's " + elementName(d) + " (" + (drawingSource ? drawingSource->name() : "drawing") +
                    " line " + std::to_string(d.line) + ") is cut " + um(e.deviation) + " off at " + formatPoint(e.at) +
                    ", more than the tolerance " + um(options.tolerance) + ": this block is the nearest",
                "a radius or a coordinate typed wrong, or an offset applied twice; --drawing-tolerance sets the "
                "tolerance"));
  }
  // Moves that cut what the drawing does not have, one finding per run of them.
  for (std::size_t j = 0; j < out.edge.size();) {
    if (out.edge[j].deviation <= options.tolerance) {
      ++j;
      continue;
    }
    std::size_t k = j;
    double worst = 0.0;
    while (k < out.edge.size() && out.edge[k].deviation > options.tolerance)
      worst = std::max(worst, out.edge[k++].deviation);
    const EdgeDeviation& e = out.edge[j];
    diags.report(finding(Severity::Warning, Code::CutNotInDrawing, program, tp.moves[e.move], e.move,
                         {e.at.x(), e.at.y(), 0.0},
                         std::to_string(k - j) + (k - j == 1 ? " move cuts" : " moves cut") + " up to " + um(worst) +
                             " from every element of the drawing, from " + formatPoint(e.at)));
    j = k;
  }
  return out;
}

}  // namespace kerf::converter
