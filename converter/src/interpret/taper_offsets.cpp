// After the last block: taper-angle contours as exact offsets of the programmed one, xyuv-rel
// contours from U V and K L, once the plane heights are known.
#include "interpreter_impl.h"

#include "kerf/geometry/corner.h"

#include <algorithm>
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
                  " mm on the " + plane + " plane is larger than this arc's radius " +
                  formatFixed(m.lower.radius(), 3) + " mm: there the arc shrinks to a sharp corner";
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
  std::size_t k = 0;
  while (k < taperRecords_.size()) {
    std::size_t e = k + 1;
    while (e < taperRecords_.size() && taperRecords_[e].index == taperRecords_[e - 1].index + 1 &&
           !taperRecords_[e].start && !taperRecords_[e - 1].end)
      ++e;
    resolveTaperRun(k, e);
    k = e;
  }
}

/// The run of taper records [k, e) (consecutive moves): the programmed contour without its rounded
/// corners offset on each plane with sharp corners, then each corner made on that plane by its model.
void Interpreter::resolveTaperRun(std::size_t k, std::size_t e) {
  const double zl = toolpath_.heights.planes.lower, zu = toolpath_.heights.planes.upper;
  const double zp = toolpath_.heights.programZ;
  const std::vector<TaperCorner> corners = cornersOfRun(k, e);
  std::vector<Segment> chain;
  std::vector<double> up, down;
  std::vector<std::size_t> moveOf;
  auto corner = corners.begin();
  for (std::size_t q = k; q < e; ++q) {
    const std::size_t m = taperRecords_[q].index;
    while (corner != corners.end() && corner->move < m) ++corner;
    if (corner != corners.end() && corner->move == m) continue;  // made on each plane below
    chain.push_back(toolpath_.moves[m].lower);
    up.push_back(taperRecords_[q].tanLeft * (zu - zp));
    down.push_back(taperRecords_[q].tanLeft * (zl - zp));
    moveOf.push_back(m);
  }
  geometry::OffsetChainOptions opts;
  opts.anchorStart = taperRecords_[k].start;
  opts.anchorEnd = taperRecords_[e - 1].end;
  const geometry::OffsetChainResult upper = geometry::offsetChain(chain, up, opts);
  reportOffsetIssues(upper, moveOf, up, "upper");
  for (std::size_t q = 0; q < chain.size(); ++q) toolpath_.upper[moveOf[q]] = upper.segments[q];
  for (const TaperCorner& c : corners) makeTaperCorner(c, k, zu, true);
  if (zp != zl) {
    const geometry::OffsetChainResult lower = geometry::offsetChain(chain, down, opts);
    reportOffsetIssues(lower, moveOf, down, "lower");
    for (std::size_t q = 0; q < chain.size(); ++q) toolpath_.moves[moveOf[q]].lower = lower.segments[q];
    for (const TaperCorner& c : corners) makeTaperCorner(c, k, zl, false);
  }
}

/// The corners of the run of taper records [k, e) made again on each plane, in move order: the ones
/// corner words (and corner-rounded) made, and, where corner-cylindrical was in force, each arc
/// that meets both its neighbours tangent (a programmed fillet) as an equal-radius corner of its
/// own radius. Only corners with a neighbour on both sides inside the run.
std::vector<TaperCorner> Interpreter::cornersOfRun(std::size_t k, std::size_t e) const {
  const std::size_t firstMove = taperRecords_[k].index, endMove = taperRecords_[e - 1].index + 1;
  auto inside = [&](std::size_t m) { return m > firstMove && m + 1 < endMove; };
  auto byMove = [](const TaperCorner& c, std::size_t m) { return c.move < m; };
  const auto from = std::lower_bound(taperCorners_.begin(), taperCorners_.end(), firstMove, byMove);
  const auto to = std::lower_bound(from, taperCorners_.end(), endMove, byMove);
  std::vector<TaperCorner> out;
  for (auto c = from; c != to; ++c)
    if (inside(c->move)) out.push_back(*c);
  const MoveList& moves = toolpath_.moves;
  auto tangent = [](const geometry::Vec2& a, const geometry::Vec2& b) {
    return std::abs(geometry::cross(a, b)) <= 1e-9 && a.dot(b) > 0;
  };
  const std::size_t made = out.size();
  for (std::size_t q = k; q < e; ++q) {
    const std::size_t m = taperRecords_[q].index;
    if (!taperRecords_[q].cylindricalArcs || !inside(m) || !moves[m].lower.isArc()) continue;
    if (std::any_of(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(made),
                    [&](const TaperCorner& c) { return c.move == m; }))
      continue;
    const Segment& arc = moves[m].lower;
    if (!tangent(moves[m - 1].lower.tangentAt(1.0), arc.tangentAt(0.0)) ||
        !tangent(arc.tangentAt(1.0), moves[m + 1].lower.tangentAt(0.0)))
      continue;
    out.push_back({m, CodeEffect::CornerEqual, arc.radius(), std::nullopt, false, arc.sweep > 0});
  }
  std::sort(out.begin(), out.end(), [](const TaperCorner& a, const TaperCorner& b) { return a.move < b.move; });
  return out;
}

/// One rounded (or chamfered) corner of a taper on the plane at z, between its neighbours' offsets
/// there (which meet sharp): the size its model gives at z (docs/taper.md, "Corners"). A conical
/// corner whose offset swallows its radius is a point; a corner that does not fit is an error
/// (K0240) and stays sharp.
void Interpreter::makeTaperCorner(const TaperCorner& c, std::size_t runFirst, double z, bool upperPlane) {
  const double zp = toolpath_.heights.programZ, zu = toolpath_.heights.planes.upper;
  auto segmentOf = [&](std::size_t m) -> Segment& {
    return upperPlane ? toolpath_.upper[m] : toolpath_.moves[m].lower;
  };
  Segment& a = segmentOf(c.move - 1);
  Segment& made = segmentOf(c.move);
  Segment& b = segmentOf(c.move + 1);
  const std::size_t first = taperRecords_[runFirst].index;
  const double dPrev = taperRecords_[runFirst + (c.move - 1 - first)].tanLeft * (z - zp);
  const double dNext = taperRecords_[runFirst + (c.move + 1 - first)].tanLeft * (z - zp);
  double size = c.size;
  switch (c.model) {
    case CodeEffect::CornerConicalMin:
    case CodeEffect::CornerConicalMean:
    case CodeEffect::CornerConicalMax: {
      const double p = std::abs(dPrev), n = std::abs(dNext);
      const double t = c.model == CodeEffect::CornerConicalMin    ? std::min(p, n)
                       : c.model == CodeEffect::CornerConicalMean ? (p + n) / 2
                                                                  : std::max(p, n);
      const double d = (dPrev + dNext >= 0 ? 1.0 : -1.0) * t;  // left positive, as the neighbours lean
      size = c.size - (c.leftTurn ? d : -d);                   // an offset towards the fillet's centre shrinks it
      break;
    }
    default:
      if (c.upperSize) size = c.size + (*c.upperSize - c.size) * (z - zp) / (zu - zp);
      break;
  }
  if (size <= 1e-9) {  // the cone's apex: the corner is a point on this plane
    made = Segment::line(a.end, a.end);
    return;
  }
  const geometry::Corner m = c.chamfer ? geometry::chamferCorner(a, b, size) : geometry::roundCorner(a, b, size);
  if (m.status != geometry::CornerStatus::Ok) {
    const Move& mv = toolpath_.moves[c.move];
    diags_.error(Code::CornerNotMade, src_, mv.span,
                 std::string("on the ") + (upperPlane ? "upper" : "lower") + " plane the corner's " +
                     (c.chamfer ? "chamfer " : "radius ") + formatFixed(size, 3) +
                     " mm does not fit between the taper's offset elements: it is left sharp there");
    made = Segment::line(a.end, a.end);
    return;
  }
  a = m.first;
  made = m.corner;
  b = m.second;
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
