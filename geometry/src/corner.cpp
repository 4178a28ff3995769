// Rounded and chamfered corners (corner.h).
#include "kerf/geometry/corner.h"

#include "kerf/geometry/offset.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

namespace kerf::geometry {
namespace {

/// Up to two points where two curves meet.
struct Meets {
  std::array<Vec2, 2> at{};
  int count = 0;
  void add(const Vec2& p) {
    if (count < 2) at[static_cast<std::size_t>(count++)] = p;
  }
};

/// Where the unbounded curves of two elements meet: lines as infinite lines, arcs as full circles.
Meets meet(const Segment& a, const Segment& b) {
  Meets m;
  if (!a.isArc() && !b.isArc()) {
    const Vec2 u = a.end - a.start, v = b.end - b.start;
    const double d = cross(u, v);
    if (std::abs(d) <= 1e-15 * u.norm() * v.norm()) return m;  // parallel
    m.add(a.start + u * (cross(b.start - a.start, v) / d));
    return m;
  }
  if (a.isArc() != b.isArc()) {
    const Segment& line = a.isArc() ? b : a;
    const Segment& arc = a.isArc() ? a : b;
    const Vec2 u = (line.end - line.start).normalized();
    const Vec2 foot = line.start + u * u.dot(arc.centre - line.start);
    const double h2 = arc.radius() * arc.radius() - (foot - arc.centre).squaredNorm();
    if (h2 < -1e-12 * arc.radius() * arc.radius()) return m;
    const double h = std::sqrt(std::max(0.0, h2));
    m.add(foot - u * h);
    if (h > 0) m.add(foot + u * h);
    return m;
  }
  const Vec2 d = b.centre - a.centre;
  const double dist = d.norm();
  if (dist <= 1e-15) return m;  // concentric
  const double x = (dist * dist + a.radius() * a.radius() - b.radius() * b.radius()) / (2 * dist);
  const double h2 = a.radius() * a.radius() - x * x;
  if (h2 < -1e-12 * a.radius() * a.radius()) return m;
  const double h = std::sqrt(std::max(0.0, h2));
  const Vec2 e = d / dist, n(-e.y(), e.x());
  m.add(a.centre + e * x - n * h);
  if (h > 0) m.add(a.centre + e * x + n * h);
  return m;
}

/// The point of s's line or circle nearest p (for an arc, on the radial through p).
Vec2 footOn(const Segment& s, const Vec2& p) {
  if (!s.isArc()) {
    const Vec2 u = (s.end - s.start).normalized();
    return s.start + u * u.dot(p - s.start);
  }
  const Vec2 r = p - s.centre;
  const double n = r.norm();
  return n > 0 ? Vec2(s.centre + r * (s.radius() / n)) : s.start;
}

/// s from its start to p (a point of s), or nothing when less than keep mm of it would remain or
/// p is not on s.
std::optional<Segment> upTo(const Segment& s, const Vec2& p, double keep) {
  if (s.distanceTo(p) > 1e-7 * std::max(1.0, s.length())) return std::nullopt;
  const Segment t = s.isArc() ? Segment::arc(s.start, p, s.centre, s.direction()) : Segment::line(s.start, p);
  if (t.length() <= keep || t.length() > s.length() - keep * 0.5 + 1e-9 * std::max(1.0, s.length()))
    return std::nullopt;
  if (!s.isArc() && (t.end - t.start).dot(s.end - s.start) <= 0) return std::nullopt;
  return t;
}

/// s from p (a point of s) to its end: s reversed, cut short, reversed back.
std::optional<Segment> from(const Segment& s, const Vec2& p, double keep) {
  const std::optional<Segment> back = upTo(s.reversed(), p, keep);
  if (!back) return std::nullopt;
  return back->reversed();
}

/// The checks both kinds of corner share: joined, not tangent, not reversed. Ok, or why not.
CornerStatus turnOf(const Segment& a, const Segment& b, double joinTolerance, double& turn) {
  if ((a.end - b.start).norm() > joinTolerance) return CornerStatus::NotJoined;
  const Vec2 ta = a.tangentAt(1.0), tb = b.tangentAt(0.0);
  turn = cross(ta, tb);
  const double along = ta.dot(tb);
  if (std::abs(turn) <= 1e-9) return along > 0 ? CornerStatus::Tangent : CornerStatus::Reversal;
  return CornerStatus::Ok;
}

/// What every corner checks before it is made: joined, not tangent, not turned straight back, a
/// size above 0. Status Ok when it may be made (turn: the cross product of the tangents there),
/// else why not; sharp is the corner either way.
Corner precheck(const Segment& a, const Segment& b, double size, double joinTolerance, double& turn) {
  Corner c;
  c.sharp = a.end;
  c.status = turnOf(a, b, joinTolerance, turn);
  if (c.status == CornerStatus::Ok && !(size > 0)) c.status = CornerStatus::DoesNotFit;
  return c;
}

/// Where the corner's segments say, or DoesNotFit when an element keeps too little.
Corner assemble(const Segment& a, const Segment& b, const Vec2& ta, const Vec2& tb, const Segment& corner,
                double keep) {
  Corner c;
  c.sharp = a.end;
  const std::optional<Segment> first = upTo(a, ta, keep);
  const std::optional<Segment> second = from(b, tb, keep);
  if (!first || !second) {
    c.status = CornerStatus::DoesNotFit;
    return c;
  }
  c.first = *first;
  c.second = *second;
  c.corner = corner;
  c.status = CornerStatus::Ok;
  return c;
}

}  // namespace

Corner roundCorner(const Segment& a, const Segment& b, double r, double joinTolerance, double keep) {
  double turn = 0.0;
  Corner fail = precheck(a, b, r, joinTolerance, turn);
  if (fail.status != CornerStatus::Ok) return fail;
  fail.status = CornerStatus::DoesNotFit;
  // The fillet's centre lies r inside the turn from both elements: on both offset curves.
  const double side = turn > 0 ? 1.0 : -1.0;
  const std::optional<Segment> oa = offsetSegment(a, side * r), ob = offsetSegment(b, side * r);
  if (!oa || !ob) return fail;
  const Meets m = meet(*oa, *ob);
  // Of the centres, the nearest the corner whose feet lie on both elements and leave each enough.
  Corner best = fail;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (int k = 0; k < m.count; ++k) {
    const Vec2 centre = m.at[static_cast<std::size_t>(k)];
    const double distance = (centre - a.end).norm();
    if (distance >= bestDistance) continue;
    const Vec2 ta = footOn(a, centre), tb = footOn(b, centre);
    const Segment fillet =
        Segment::arc(ta, tb, centre, side > 0 ? ArcDirection::CounterClockwise : ArcDirection::Clockwise);
    const Corner c = assemble(a, b, ta, tb, fillet, keep);
    if (c.status != CornerStatus::Ok) continue;
    best = c;
    bestDistance = distance;
  }
  return best;
}

Corner chamferCorner(const Segment& a, const Segment& b, double c, double joinTolerance, double keep) {
  double turn = 0.0;
  Corner fail = precheck(a, b, c, joinTolerance, turn);
  if (fail.status != CornerStatus::Ok) return fail;
  fail.status = CornerStatus::DoesNotFit;
  // The point of s at the straight distance c from its end (towards = -1) or start (+1).
  auto at = [&](const Segment& s, const Vec2& corner, double towards) -> std::optional<Vec2> {
    if (!s.isArc()) return corner + towards * c * (s.end - s.start).normalized();
    if (c >= 2 * s.radius()) return std::nullopt;
    const double step = 2 * std::asin(c / (2 * s.radius()));
    const double angle = angleOf(corner - s.centre) + towards * (s.sweep < 0 ? -step : step);
    return s.centre + s.radius() * direction(angle);
  };
  const std::optional<Vec2> ta = at(a, a.end, -1.0), tb = at(b, a.end, 1.0);
  if (!ta || !tb) return fail;
  return assemble(a, b, *ta, *tb, Segment::line(*ta, *tb), keep);
}

}  // namespace kerf::geometry
