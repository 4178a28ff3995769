#include "kerf/geometry/offset.h"

#include "angles.h"

#include <cmath>

namespace kerf::geometry {
namespace {

/// Points where the carriers (infinite line, full circle) of a and b meet; at most two.
int carrierIntersections(const Segment& a, const Segment& b, Vec2 out[2]) {
  if (!a.isArc() && !b.isArc()) {
    const Vec2 da = a.end - a.start, db = b.end - b.start;
    const double den = cross(da, db);
    if (std::abs(den) <= 1e-14 * da.norm() * db.norm()) return 0;
    const double u = cross(b.start - a.start, db) / den;
    out[0] = a.start + u * da;
    return 1;
  }
  if (a.isArc() != b.isArc()) {
    const Segment& line = a.isArc() ? b : a;
    const Segment& arc = a.isArc() ? a : b;
    const Vec2 d = line.end - line.start;
    const double len = d.norm();
    if (len == 0.0) return 0;
    const Vec2 u = d / len;
    const Vec2 foot = line.start + u * u.dot(arc.centre - line.start);
    const double h2 = arc.radius() * arc.radius() - (foot - arc.centre).squaredNorm();
    if (h2 < 0) return 0;
    const double h = std::sqrt(h2);
    out[0] = foot - h * u;
    out[1] = foot + h * u;
    return h == 0.0 ? 1 : 2;
  }
  const Vec2 d = b.centre - a.centre;
  const double dist = d.norm();
  if (dist == 0.0) return 0;
  const double x = (dist * dist + a.radius() * a.radius() - b.radius() * b.radius()) / (2 * dist);
  const double h2 = a.radius() * a.radius() - x * x;
  if (h2 < 0) return 0;
  const Vec2 u = d / dist;
  const Vec2 mid = a.centre + x * u;
  const double h = std::sqrt(h2);
  out[0] = mid - h * leftNormal(u);
  out[1] = mid + h * leftNormal(u);
  return h == 0.0 ? 1 : 2;
}

/// Signed angle from a to b along the arc's direction of travel, in (-pi, pi].
double alongDelta(const Segment& arc, const Vec2& from, const Vec2& to) {
  double d = angleOf(to - arc.centre) - angleOf(from - arc.centre);
  if (arc.sweep < 0) d = -d;
  while (d > kPi) d -= kTwoPi;
  while (d <= -kPi) d += kTwoPi;
  return d;
}

/// The offset element trimmed (or extended) to run from s to e; false when that reverses it.
bool trim(const Segment& offset, const Vec2& s, const Vec2& e, Segment& out) {
  if (!offset.isArc()) {
    out = Segment::line(s, e);
    const Vec2 d = offset.end - offset.start;
    return d.squaredNorm() == 0.0 || (e - s).dot(d) > 0.0;
  }
  const double magnitude =
      std::abs(offset.sweep) - alongDelta(offset, offset.start, s) + alongDelta(offset, offset.end, e);
  out = offset;
  out.start = s;
  out.end = e;
  out.sweep = offset.sweep < 0 ? -magnitude : magnitude;
  return magnitude > 0.0;
}

}  // namespace

std::optional<Segment> offsetSegment(const Segment& s, double d) {
  if (!s.isArc()) {
    const Vec2 dir = s.end - s.start;
    const double len = dir.norm();
    if (len == 0.0) return s;
    const Vec2 shift = leftNormal(dir / len) * d;
    return Segment::line(s.start + shift, s.end + shift);
  }
  // Left of a counter-clockwise arc is towards the centre.
  const double r = s.sweep >= 0 ? s.radius() - d : s.radius() + d;
  if (r <= 0.0) return std::nullopt;
  Segment o = s;
  const double a0 = s.startAngle();
  o.start = s.centre + r * direction(a0);
  o.end = s.centre + r * direction(a0 + s.sweep);
  return o;
}

OffsetChainResult offsetChain(std::span<const Segment> chain, std::span<const double> distances,
                              const OffsetChainOptions& options) {
  OffsetChainResult result;
  const std::size_t n = chain.size();
  std::vector<Segment> raw(n);
  std::vector<bool> collapsed(n, false);
  for (std::size_t i = 0; i < n; ++i) {
    std::optional<Segment> o = offsetSegment(chain[i], i < distances.size() ? distances[i] : 0.0);
    if (!o) {
      result.issues.push_back({i, OffsetProblem::Collapsed});
      raw[i] = chain[i];
      collapsed[i] = true;
    } else {
      raw[i] = *o;
    }
  }
  // corner[i]: where element i ends and the next element that survives the offset starts. A
  // collapsed element shrinks to a point: the corner of its neighbours.
  auto nextAlive = [&](std::size_t i) -> std::optional<std::size_t> {
    for (std::size_t step = 1; step < n + 1; ++step) {
      const std::size_t j = i + step;
      if (j >= n && !options.closed) return std::nullopt;
      if (!collapsed[j % n]) return j % n;
    }
    return std::nullopt;
  };
  std::vector<Vec2> corner(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (collapsed[i]) continue;
    const std::optional<std::size_t> next = nextAlive(i);
    if (!next || *next == i) {
      corner[i] = raw[i].end;
      continue;
    }
    const Segment& a = raw[i];
    const Segment& b = raw[*next];
    if ((a.end - b.start).norm() <= options.tolerance) {
      corner[i] = 0.5 * (a.end + b.start);
      continue;
    }
    Vec2 candidates[2] = {Vec2::Zero(), Vec2::Zero()};
    const int count = carrierIntersections(a, b, candidates);
    if (count == 0) {
      result.issues.push_back({i, OffsetProblem::NoCorner});
      corner[i] = 0.5 * (a.end + b.start);
      continue;
    }
    const Vec2 near = 0.5 * (a.end + b.start);
    corner[i] = candidates[0];
    if (count == 2 && (candidates[1] - near).norm() < (candidates[0] - near).norm()) corner[i] = candidates[1];
  }
  // Collapsed elements take the corner of the survivor before them (or, at the open start, the
  // start of the first survivor).
  for (std::size_t i = 0; i < n; ++i) {
    if (!collapsed[i]) continue;
    std::optional<std::size_t> before;
    for (std::size_t step = 1; step <= n && !before; ++step) {
      if (step > i && !options.closed) break;
      const std::size_t j = (i + n - step) % n;
      if (!collapsed[j]) before = j;
    }
    if (before) {
      corner[i] = corner[*before];
    } else {
      const std::optional<std::size_t> next = nextAlive(i);
      corner[i] = next ? raw[*next].start : chain[i].end;
    }
  }
  result.segments.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (collapsed[i]) {
      result.segments[i] = Segment::line(corner[i], corner[i]);
      continue;
    }
    Vec2 s = i > 0 ? corner[i - 1] : options.closed ? corner[n - 1] : raw[0].start;
    Vec2 e = corner[i];
    if (i == 0 && options.anchorStart && !options.closed && !chain[0].isArc()) s = chain[0].start;
    if (i + 1 == n && options.anchorEnd && !options.closed && !chain[i].isArc()) e = chain[i].end;
    const bool anchored = (i == 0 && options.anchorStart) || (i + 1 == n && options.anchorEnd);
    if (anchored && !options.closed && !chain[i].isArc()) {
      result.segments[i] = Segment::line(s, e);
      continue;
    }
    if (!trim(raw[i], s, e, result.segments[i])) result.issues.push_back({i, OffsetProblem::Reversed});
  }
  return result;
}

}  // namespace kerf::geometry
