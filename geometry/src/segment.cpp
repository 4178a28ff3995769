#include "kerf/geometry/segment.h"

#include "angles.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace kerf::geometry {

Segment Segment::arc(const Vec2& start, const Vec2& end, const Vec2& centre, ArcDirection dir) {
  Segment s;
  s.kind = SegmentKind::Arc;
  s.start = start;
  s.end = end;
  s.centre = centre;
  const Vec2 a = start - centre, e = end - centre;
  // The turn from a to e counter-clockwise, in [0, 2 pi]: one atan2 of the pair, which is also
  // nearer the true angle than the difference of the two directions' angles.
  double ccw = std::atan2(cross(a, e), a.dot(e));
  if (ccw < 0) ccw += kTwoPi;
  const bool full = (end - start).norm() <= 1e-12 * std::max(1.0, a.norm());
  double w = dir == ArcDirection::CounterClockwise ? ccw : (ccw == 0.0 ? 0.0 : kTwoPi - ccw);
  if (full || w == 0.0) w = kTwoPi;
  s.sweep = dir == ArcDirection::CounterClockwise ? w : -w;
  return s;
}

Vec2 Segment::pointAt(double t) const {
  if (kind == SegmentKind::Line) return start + t * (end - start);
  if (t <= 0.0) return start;
  if (t >= 1.0) return end;
  return centre + radius() * geometry::direction(startAngle() + t * sweep);
}

Vec2 Segment::tangentAt(double t) const {
  if (kind == SegmentKind::Line) {
    const Vec2 d = end - start;
    const double n = d.norm();
    return n > 0 ? Vec2(d / n) : Vec2(Vec2::Zero());
  }
  const double a = startAngle() + t * sweep;
  const Vec2 radial = geometry::direction(a);
  // Counter-clockwise travel is the radial direction turned by +90 degrees.
  return sweep >= 0 ? Vec2(-radial.y(), radial.x()) : Vec2(radial.y(), -radial.x());
}

Box Segment::arcBounds() const {
  Box b{start.cwiseMin(end), start.cwiseMax(end)};
  // Axis extremes (0, 90, 180, 270 degrees) that the arc passes through. The directions are exact
  // (cos and sin of q pi/2 are not: cos(pi/2) is 6e-17). Which ones, from the quadrants of the
  // ends, counter-clockwise from the end a clockwise arc stops at; where those disagree with the
  // sweep, from the angles (an atan2: the sweeps make every segment's box).
  static constexpr double kAxis[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  const Vec2 a = start - centre, e = end - centre;
  const double w = std::abs(sweep);
  auto addAxis = [&](int q, double r) { b.add(centre + r * Vec2(kAxis[q][0], kAxis[q][1])); };
  if (w < kTwoPi) {
    const bool ccw = sweep >= 0;
    const int qf = detail::quadrantOf(ccw ? a : e);
    if (const int n = detail::axesPassed(qf, ccw ? e : a, w); n >= 0) {
      if (n > 0) {
        const double r = a.norm();
        for (int k = 1; k <= n; ++k) addAxis((qf + k) % 4, r);
      }
      return b;
    }
  }
  const double a0 = angleOf(a), r = a.norm();
  for (int q = 0; q < 4; ++q)
    if (detail::angleAlong(a0, sweep, q * kPi / 2) <= w) addAxis(q, r);
  return b;
}

Segment Segment::reversed() const {
  if (kind == SegmentKind::Line) return line(end, start);
  Segment s = *this;
  s.start = end;
  s.end = start;
  s.sweep = -sweep;  // the circle is the one through the new start (radius() and startAngle() follow it)
  return s;
}

double Segment::parameterOf(const Vec2& p) const {
  if (kind == SegmentKind::Line) {
    const Vec2 d = end - start;
    const double len2 = d.squaredNorm();
    return len2 > 0 ? std::clamp((p - start).dot(d) / len2, 0.0, 1.0) : 0.0;
  }
  if (sweep == 0.0) return 0.0;
  const double along = detail::angleAlong(*this, angleOf(p - centre));
  if (along <= std::abs(sweep)) return along / std::abs(sweep);
  // Off the arc: the nearer end.
  return (p - start).norm() <= (p - end).norm() ? 0.0 : 1.0;
}

double Segment::distanceTo(const Vec2& p) const { return (pointAt(parameterOf(p)) - p).norm(); }

}  // namespace kerf::geometry
