// After the last block: taper-angle contours as exact offsets of the programmed one, xyuv-rel
// contours from U V and K L, once the plane heights are known.
#include "interpreter_impl.h"

#include <cmath>

namespace kerf::converter::interp {

void Interpreter::reportOffsetIssues(const geometry::OffsetChainResult& r, const std::vector<std::size_t>& moveOf,
                                     const std::vector<double>& distance, const char* plane) {
  for (const geometry::OffsetIssue& issue : r.issues) {
    const std::size_t mi = moveOf[issue.index];
    const Move& m = toolpath_.moves[mi];
    std::string message;
    switch (issue.problem) {
      case geometry::OffsetProblem::Collapsed:
        message = std::string("the taper offset of ") + formatFixed(std::abs(distance[issue.index]), 3) +
                  " mm on the " + plane + " plane is larger than this arc's radius " + formatFixed(m.lower.radius, 3) +
                  " mm: there the arc shrinks to a sharp corner";
        break;
      case geometry::OffsetProblem::Reversed:
        message = std::string("the taper offset of ") + formatFixed(std::abs(distance[issue.index]), 3) +
                  " mm on the " + plane + " plane swallows this move: between its corners it would run backwards";
        break;
      case geometry::OffsetProblem::NoCorner:
        message = std::string("on the ") + plane +
                  " plane the offsets of this move and the next never meet (parallel, with different angles)";
        break;
    }
    Diagnostic d;
    d.severity = issue.problem == geometry::OffsetProblem::Collapsed ? Severity::Warning : Severity::Error;
    d.code = Code::OffsetCollapses;
    d.source = src_;
    d.span = m.span;
    d.message = std::move(message);
    d.move = mi;
    d.point = geometry::Vec3(m.lower.start.x(), m.lower.start.y(), toolpath_.heights.programZ);
    diags_.report(std::move(d));
  }
}

/// taper-angle: each run of leaning moves becomes an offset chain on each plane.
void Interpreter::resolveTaperAngle() {
  if (!toolpath_.heights.known) return;  // the upper contour stays vertical; an error says why
  const double zl = toolpath_.heights.planes.lower, zu = toolpath_.heights.planes.upper;
  const double zp = toolpath_.heights.programZ;
  std::size_t k = 0;
  while (k < taperRecords_.size()) {
    std::size_t e = k + 1;
    while (e < taperRecords_.size() && taperRecords_[e].index == taperRecords_[e - 1].index + 1 &&
           !taperRecords_[e].start && !taperRecords_[e - 1].end)
      ++e;
    std::vector<Segment> chain;
    std::vector<double> up, down;
    std::vector<std::size_t> moveOf;
    for (std::size_t q = k; q < e; ++q) {
      chain.push_back(toolpath_.moves[taperRecords_[q].index].lower);
      up.push_back(taperRecords_[q].tanLeft * (zu - zp));
      down.push_back(taperRecords_[q].tanLeft * (zl - zp));
      moveOf.push_back(taperRecords_[q].index);
    }
    geometry::OffsetChainOptions opts;
    opts.anchorStart = taperRecords_[k].start;
    opts.anchorEnd = taperRecords_[e - 1].end;
    const geometry::OffsetChainResult upper = geometry::offsetChain(chain, up, opts);
    reportOffsetIssues(upper, moveOf, up, "upper");
    for (std::size_t q = 0; q < chain.size(); ++q) toolpath_.upper[moveOf[q]] = upper.segments[q];
    if (zp != zl) {
      const geometry::OffsetChainResult lower = geometry::offsetChain(chain, down, opts);
      reportOffsetIssues(lower, moveOf, down, "lower");
      for (std::size_t q = 0; q < chain.size(); ++q) toolpath_.moves[moveOf[q]].lower = lower.segments[q];
    }
    k = e;
  }
}

/// xyuv-rel: the programmed contour and the U V offsets give both planes. With the program
/// plane on the lower plane (the default) the heights are not needed.
void Interpreter::resolveRel() {
  const PlaneHeights& h = toolpath_.heights;
  double f = 0.0;  // lower = programmed - f * offset, upper = programmed + (1 - f) * offset
  if (h.programZ != h.planes.lower) {
    if (!h.known) return;
    f = (h.programZ - h.planes.lower) / h.planes.height();
  }
  const double g = 1.0 - f;
  for (const RelRecord& r : relRecords_) {
    Move& m = toolpath_.moves[r.index];
    const Segment p = m.lower;
    const Vec2 us = p.start + g * r.offsetStart, ue = p.end + g * r.offsetEnd;
    const Vec2 ls = p.start - f * r.offsetStart, le = p.end - f * r.offsetEnd;
    if (!p.isArc()) {
      toolpath_.upper[r.index] = Segment::line(us, ue);
      m.lower = Segment::line(ls, le);
      continue;
    }
    const geometry::ArcBuild upper =
        geometry::arcFromCentre(us, ue, p.centre + g * r.centreShift, p.direction(), r.tolerance);
    if (upper.status != geometry::ArcStatus::Ok) {
      diags_.error(Code::UpperArcOffCircle, src_, m.span,
                   "the upper arc (from U V and K L) ends " + formatFixed(std::abs(upper.radiusError), 3) +
                       " mm off the circle through its start",
                   "K L give the vector from the lower arc's centre to the upper arc's centre");
      toolpath_.upper[r.index] = Segment::line(us, ue);
    } else {
      toolpath_.upper[r.index] = upper.arc;
    }
    if (f != 0.0) {
      const geometry::ArcBuild lower =
          geometry::arcFromCentre(ls, le, p.centre - f * r.centreShift, p.direction(), r.tolerance);
      if (lower.status == geometry::ArcStatus::Ok) m.lower = lower.arc;
    }
  }
}

}  // namespace kerf::converter::interp
