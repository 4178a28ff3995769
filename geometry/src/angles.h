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

}  // namespace kerf::geometry::detail
