// Sections: 1. primitive intersections (line-line, line-arc, arc-arc)
//           2. classification of a pair within a path
//           3. the sweep over boxes
#include "kerf/geometry/intersection.h"

#include "angles.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace kerf::geometry {
namespace {

// ---- 1. primitive intersections -------------------------------------------------------------

void addPoint(SegmentIntersection& r, const Vec2& p, double tol) {
  for (int i = 0; i < r.count; ++i)
    if ((r.points[i] - p).norm() <= tol) return;
  if (r.count < 2) r.points[r.count++] = p;
}

SegmentIntersection lineLine(const Segment& a, const Segment& b, double tol) {
  SegmentIntersection r;
  const Vec2 p = a.start, q = b.start;
  const Vec2 ra = a.end - a.start, sb = b.end - b.start;
  const double la = ra.norm(), lb = sb.norm();
  const double denom = cross(ra, sb);
  const Vec2 qp = q - p;
  if (std::abs(denom) <= 1e-12 * la * lb) {
    // Parallel: only collinear ones can meet.
    if (std::abs(cross(qp, ra)) / la > tol) return r;
    const double t0 = qp.dot(ra) / (la * la);
    const double t1 = (b.end - p).dot(ra) / (la * la);
    const double lo = std::max(0.0, std::min(t0, t1));
    const double hi = std::min(1.0, std::max(t0, t1));
    if ((hi - lo) * la > tol) {
      r.overlap = true;
      addPoint(r, p + lo * ra, tol);
      addPoint(r, p + hi * ra, tol);
    } else if (hi - lo >= -tol / la) {
      addPoint(r, p + std::clamp((lo + hi) / 2, 0.0, 1.0) * ra, tol);
    }
    return r;
  }
  const double t = cross(qp, sb) / denom;
  const double u = cross(qp, ra) / denom;
  if (t < -tol / la || t > 1 + tol / la || u < -tol / lb || u > 1 + tol / lb) return r;
  addPoint(r, p + std::clamp(t, 0.0, 1.0) * ra, tol);
  return r;
}

SegmentIntersection lineArc(const Segment& line, const Segment& arc, double tol) {
  SegmentIntersection r;
  const Vec2 d = line.end - line.start;
  const double len2 = d.squaredNorm();
  const double len = std::sqrt(len2);
  const Vec2 f = line.start - arc.centre;
  const double t0 = -f.dot(d) / len2;  // foot of the perpendicular from the centre
  const double dist = (f + t0 * d).norm();
  if (dist > arc.radius + tol) return r;
  double ts[2];
  int n = 0;
  if (std::abs(dist - arc.radius) <= tol) {
    ts[n++] = t0;  // tangent
  } else {
    const double h = std::sqrt(std::max(0.0, arc.radius * arc.radius - dist * dist)) / len;
    ts[n++] = t0 - h;
    ts[n++] = t0 + h;
  }
  for (int i = 0; i < n; ++i) {
    if (ts[i] < -tol / len || ts[i] > 1 + tol / len) continue;
    const Vec2 pt = line.start + std::clamp(ts[i], 0.0, 1.0) * d;
    if (detail::onArc(arc, pt, tol)) addPoint(r, pt, tol);
  }
  return r;
}

/// A counter-clockwise angular interval [from, from + span].
struct AngleInterval {
  double from;
  double span;
};

AngleInterval ccwInterval(const Segment& arc) {
  if (arc.sweep >= 0) return {detail::wrapPositive(arc.startAngle), arc.sweep};
  return {detail::wrapPositive(arc.startAngle + arc.sweep), -arc.sweep};
}

SegmentIntersection arcArc(const Segment& a, const Segment& b, double tol) {
  SegmentIntersection r;
  const Vec2 dc = b.centre - a.centre;
  const double d = dc.norm();
  if (d <= tol && std::abs(a.radius - b.radius) <= tol) {
    // Same circle: shared stretches of the two angular intervals.
    const AngleInterval ia = ccwInterval(a), ib = ccwInterval(b);
    const double offset = detail::wrapPositive(ib.from - ia.from);
    double best = 0.0, bestFrom = 0.0, bestTo = 0.0;
    for (double o : {offset, offset - kTwoPi}) {
      const double lo = std::max(0.0, o), hi = std::min(ia.span, o + ib.span);
      if (hi - lo > best) {
        best = hi - lo;
        bestFrom = lo;
        bestTo = hi;
      }
    }
    if (best * a.radius > tol) {
      r.overlap = true;
      addPoint(r, a.centre + a.radius * direction(ia.from + bestFrom), tol);
      addPoint(r, a.centre + a.radius * direction(ia.from + bestTo), tol);
      return r;
    }
    // No shared stretch: they can still touch at end points.
    for (const Vec2& p : {b.start, b.end})
      if (detail::onArc(a, p, tol)) addPoint(r, p, tol);
    for (const Vec2& p : {a.start, a.end})
      if (detail::onArc(b, p, tol)) addPoint(r, p, tol);
    return r;
  }
  if (d > a.radius + b.radius + tol || d < std::abs(a.radius - b.radius) - tol || d == 0.0) return r;
  const double along = (a.radius * a.radius - b.radius * b.radius + d * d) / (2 * d);
  const double h2 = a.radius * a.radius - along * along;
  const Vec2 u = dc / d;
  const Vec2 base = a.centre + along * u;
  const Vec2 perp(-u.y(), u.x());
  const double h = h2 > 0 ? std::sqrt(h2) : 0.0;
  const Vec2 candidates[2] = {base + h * perp, base - h * perp};
  const int n = h <= tol ? 1 : 2;
  for (int i = 0; i < n; ++i)
    if (detail::onArc(a, candidates[i], tol) && detail::onArc(b, candidates[i], tol)) addPoint(r, candidates[i], tol);
  return r;
}

}  // namespace

SegmentIntersection intersect(const Segment& a, const Segment& b, double tol) {
  if (!a.isArc() && !b.isArc()) return lineLine(a, b, tol);
  if (!a.isArc()) return lineArc(a, b, tol);
  if (!b.isArc()) return lineArc(b, a, tol);
  return arcArc(a, b, tol);
}

namespace {

// ---- 2. classification ----------------------------------------------------------------------

bool near(const Vec2& p, const Vec2& q, double tol) { return (p - q).norm() <= tol; }
bool atEnd(const Segment& s, const Vec2& p, double tol) { return near(s.start, p, tol) || near(s.end, p, tol); }

/// Do a and b run the same way along their shared stretch?
bool sameDirection(const Segment& a, const Segment& b, const Vec2& at) {
  auto tangentNear = [](const Segment& s, const Vec2& p) {
    if (!s.isArc()) return s.tangentAt(0.0);
    const Vec2 radial = (p - s.centre).normalized();
    return s.sweep >= 0 ? Vec2(-radial.y(), radial.x()) : Vec2(radial.y(), -radial.x());
  };
  return tangentNear(a, at).dot(tangentNear(b, at)) > 0;
}

/// Appends the contacts of the pair (i, j), i < j.
void classifyPair(std::span<const Segment> path, std::size_t i, std::size_t j, bool adjacentForward, bool adjacentWrap,
                  double tol, std::vector<Contact>& out) {
  const Segment& a = path[i];
  const Segment& b = path[j];
  const SegmentIntersection x = intersect(a, b, tol);
  if (x.count == 0) return;
  const bool adjacent = adjacentForward || adjacentWrap;
  Contact c;
  c.first = i;
  c.second = j;
  c.adjacent = adjacent;
  if (x.overlap) {
    c.kind = ContactKind::Overlap;
    c.point = (x.points[0] + x.points[1]) / 2;
    c.opposite = !sameDirection(a, b, c.point);
    out.push_back(c);
    return;
  }
  for (int k = 0; k < x.count; ++k) {
    const Vec2& p = x.points[k];
    if (adjacentForward && near(p, a.end, tol) && near(p, b.start, tol)) continue;  // shared vertex
    if (adjacentWrap && near(p, b.end, tol) && near(p, a.start, tol)) continue;
    const bool endA = atEnd(a, p, tol), endB = atEnd(b, p, tol);
    // End meets end: a vertex visited twice (lead-in and lead-out), or two neighbours that
    // close a loop between them (two half circles). Neither cuts through anything.
    if (endA && endB) continue;
    c.kind = (endA || endB) ? ContactKind::Touch : ContactKind::Crossing;
    c.point = p;
    out.push_back(c);
  }
}

}  // namespace

// ---- 3. sweep ---------------------------------------------------------------------------------

SelfIntersectionResult findSelfIntersections(std::span<const Segment> path, const SelfIntersectionOptions& options) {
  SelfIntersectionResult result;
  const double tol = options.tolerance;
  const std::size_t n = path.size();
  std::vector<Box> boxes(n);
  // Sorting (min x, index) pairs directly is much faster than sorting indices through boxes.
  std::vector<std::pair<double, std::size_t>> byMinX;
  byMinX.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (path[i].length() <= tol) continue;  // zero-length moves are reported elsewhere
    boxes[i] = path[i].bounds();
    byMinX.emplace_back(boxes[i].min.x(), i);
  }
  std::sort(byMinX.begin(), byMinX.end());

  // Neighbours skip over zero-length segments: they share a vertex just the same.
  std::vector<std::size_t> rank(n, n);
  {
    std::size_t k = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (path[i].length() > tol) rank[i] = k++;
  }
  const std::size_t live = byMinX.size();

  std::vector<std::size_t> active;
  for (const auto& [minX, idx] : byMinX) {
    const Box& box = boxes[idx];
    std::size_t w = 0;
    for (std::size_t r = 0; r < active.size(); ++r) {
      const std::size_t other = active[r];
      if (boxes[other].max.x() < box.min.x() - tol) continue;  // leaves the sweep
      active[w++] = other;
      if (!boxes[other].overlaps(box, tol)) continue;
      ++result.candidatePairs;
      const std::size_t i = std::min(idx, other), j = std::max(idx, other);
      const bool forward = rank[j] == rank[i] + 1 && near(path[i].end, path[j].start, tol);
      const bool wrap =
          options.closed && live > 2 && rank[i] == 0 && rank[j] == live - 1 && near(path[j].end, path[i].start, tol);
      classifyPair(path, i, j, forward, wrap, tol, result.contacts);
      if (result.contacts.size() >= options.maxContacts) {
        result.truncated = true;
        result.contacts.resize(options.maxContacts);
        std::sort(result.contacts.begin(), result.contacts.end(), [](const Contact& l, const Contact& r2) {
          return l.first != r2.first ? l.first < r2.first : l.second < r2.second;
        });
        return result;
      }
    }
    active.resize(w);
    active.push_back(idx);
  }
  std::sort(result.contacts.begin(), result.contacts.end(), [](const Contact& l, const Contact& r) {
    return l.first != r.first ? l.first < r.first : l.second < r.second;
  });
  return result;
}

}  // namespace kerf::geometry
