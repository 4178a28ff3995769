// Private helpers for angles on arcs.
#pragma once

#include "kerf/geometry/segment.h"

#include <cmath>

namespace kerf::geometry::detail {

/// a reduced into [0, 2 pi).
[[gnu::always_inline]] inline double wrapPositive(double a) {
  // Within two turns either way (nearly every angle a program gives), fmod(a, 2 pi) is a, a - 2 pi
  // or a + 2 pi, and those differences are exact (Sterbenz: |a| <= 2 * 2 pi), so the fast path
  // gives fmod's result bit for bit without the library call (a bounding box takes four).
  // The turns' end points themselves (signed zeros) go to fmod.
  double r;
  if (a >= 0 && a < kTwoPi)
    return a;
  else if (a > kTwoPi && a < 2 * kTwoPi)
    r = a - kTwoPi;
  else if (a < 0 && a > -kTwoPi)
    r = a;
  else if (a < -kTwoPi && a > -2 * kTwoPi)
    r = a + kTwoPi;
  else
    r = std::fmod(a, kTwoPi);
  if (r < 0) r += kTwoPi;
  if (r >= kTwoPi) r -= kTwoPi;
  return r;
}

/// How far along an arc that starts at the angle `startAngle` and turns by `sweep` (radians, >= 0,
/// in the direction of travel) the angle phi lies from the start. Values above |sweep| mean off
/// the arc. A caller that asks for several angles of one arc takes its startAngle() once.
[[gnu::always_inline]] inline double angleAlong(double startAngle, double sweep, double phi) {
  return sweep >= 0 ? wrapPositive(phi - startAngle) : wrapPositive(startAngle - phi);
}
inline double angleAlong(const Segment& arc, double phi) { return angleAlong(arc.startAngle(), arc.sweep, phi); }

/// Is the point p (assumed on the arc's circle) on the arc, within tol mm along the circle?
inline bool onArc(const Segment& arc, const Vec2& p, double tol) {
  const double along = angleAlong(arc, angleOf(p - arc.centre));
  const double r = arc.radius();
  const double angTol = r > 0 ? tol / r : 0.0;
  return along <= std::abs(arc.sweep) + angTol || along >= kTwoPi - angTol;
}

/// The quadrant of v: 0 for the angles [0, pi/2), 1 for [pi/2, pi), 2 for [pi, 3 pi/2), 3 for
/// [3 pi/2, 2 pi) (and for the zero vector): the axis direction q pi/2 opens quadrant q.
inline int quadrantOf(const Vec2& v) {
  if (v.x() > 0 && v.y() >= 0) return 0;
  if (v.x() <= 0 && v.y() > 0) return 1;
  if (v.x() < 0 && v.y() <= 0) return 2;
  return 3;
}

/// How many axis directions an arc passes, counted counter-clockwise from a direction in quadrant
/// qf (not counting the axis it may lie on) to `to` (counting the axis it lies on), the arc turning
/// by w (radians, 0 <= w < 2 pi); -1 when the quadrants of the two disagree with w (an end a
/// rounding away from an axis, or off its circle), so that the caller measures angles instead.
inline int axesPassed(int qf, const Vec2& to, double w) {
  int n = (quadrantOf(to) - qf + 4) % 4;
  if (n == 0 && w > kPi) n = 4;  // round past every axis back into the quadrant it left
  // The first axis after `from` lies (0, pi/2] on, so w passes m or m + 1 of them.
  const int m = static_cast<int>(w / (kPi / 2));
  return n == m || n == m + 1 ? n : -1;
}

}  // namespace kerf::geometry::detail
