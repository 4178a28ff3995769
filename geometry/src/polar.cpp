#include "kerf/geometry/polar.h"

#include <algorithm>
#include <cmath>

namespace kerf::geometry {

namespace {
constexpr double kDeg = 180.0 / kPi;
}

double unwrapDegrees(double degrees, double previous) {
  return degrees + 360.0 * std::round((previous - degrees) / 360.0);
}

PolarPoint toPolar(const Vec2& p, double previousC) {
  PolarPoint q;
  q.radius = p.norm();
  q.c = q.radius == 0.0 ? previousC : unwrapDegrees(std::atan2(p.y(), p.x()) * kDeg, previousC);
  return q;
}

Vec2 fromPolar(const PolarPoint& q) { return {q.radius * std::cos(q.c / kDeg), q.radius * std::sin(q.c / kDeg)}; }

double spiralDeviation(const PolarPoint& a, const PolarPoint& b, const Segment& s, int samples) {
  double worst = 0.0;
  for (int k = 1; k <= samples; ++k) {
    const double u = static_cast<double>(k) / (samples + 1);
    const PolarPoint m{a.radius + u * (b.radius - a.radius), a.c + u * (b.c - a.c)};
    worst = std::max(worst, s.distanceTo(fromPolar(m)));
  }
  return worst;
}

PolarSubdivision subdivideForPolar(const Segment& s, double startC, double tolerance, std::size_t budget,
                                   double centreGap) {
  PolarSubdivision out;
  const double tc = s.parameterOf(Vec2(0, 0));
  const bool startsAtCentre = s.start.norm() < centreGap, endsAtCentre = s.end.norm() < centreGap;
  if (s.pointAt(tc).norm() < centreGap && !(startsAtCentre && tc < 0.5) && !(endsAtCentre && tc >= 0.5)) {
    out.throughCentre = true;
    return out;
  }
  PolarPoint first = toPolar(s.start, startC);
  if (startsAtCentre) {
    const Vec2 d = s.tangentAt(0.0);
    first = {0.0, unwrapDegrees(std::atan2(d.y(), d.x()) * kDeg, startC)};
    if (std::abs(first.c - startC) > 1e-9) {
      out.leadTurn = true;
      out.lead = first;
    }
  }
  // Depth-first bisection in t, left piece first, so the points come out in order.
  struct Piece {
    double t0, t1;
    PolarPoint a;
    int depth;
  };
  std::vector<Piece> stack;
  stack.push_back({0.0, 1.0, first, 0});
  while (!stack.empty()) {
    Piece p = stack.back();
    stack.pop_back();
    const Vec2 endPoint = p.t1 == 1.0 ? s.end : s.pointAt(p.t1);
    const PolarPoint b = toPolar(endPoint, p.a.c);
    const bool turnsTooFar = std::abs(b.c - p.a.c) > 45.0;
    const double dev = turnsTooFar ? 1e300 : spiralDeviation(p.a, b, s);
    if (dev > tolerance && p.depth < 60) {
      const double tm = 0.5 * (p.t0 + p.t1);
      const PolarPoint mid = toPolar(s.pointAt(tm), p.a.c);
      stack.push_back({tm, p.t1, mid, p.depth + 1});  // right half later
      stack.push_back({p.t0, tm, p.a, p.depth + 1});  // left half first
      continue;
    }
    out.maxDeviation = std::max(out.maxDeviation, turnsTooFar ? 0.0 : dev);
    out.points.push_back(b);
    if (out.points.size() > budget) {
      out.overBudget = true;
      return out;
    }
  }
  return out;
}

}  // namespace kerf::geometry
