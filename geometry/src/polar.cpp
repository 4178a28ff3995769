#include "kerf/geometry/polar.h"

#include <algorithm>
#include <cmath>

namespace kerf::geometry {

double unwrapDegrees(double degrees, double previous) {
  return degrees + 360.0 * std::round((previous - degrees) / 360.0);
}

PolarPoint toPolar(const Vec2& p, double previousC) {
  PolarPoint q;
  q.radius = p.norm();
  q.c = q.radius == 0.0 ? previousC : unwrapDegrees(std::atan2(p.y(), p.x()) * kDegreesPerRadian, previousC);
  return q;
}

Vec2 fromPolar(const PolarPoint& q) {
  return {q.radius * std::cos(q.c / kDegreesPerRadian), q.radius * std::sin(q.c / kDegreesPerRadian)};
}

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
    first = {0.0, unwrapDegrees(std::atan2(d.y(), d.x()) * kDegreesPerRadian, startC)};
    if (std::abs(first.c - startC) > 1e-9) {
      out.leadTurn = true;
      out.lead = first;
    }
  }
  // Depth-first bisection in t, left piece first, so the points come out in order and every piece
  // starts at the point accepted last: its C is unwrapped along the way, never against a point half
  // a turn away (where the nearest congruent value is ambiguous).
  struct Piece {
    double t0, t1;
    int depth;
  };
  std::vector<Piece> stack;
  stack.push_back({0.0, 1.0, 0});
  PolarPoint at = first;
  while (!stack.empty()) {
    const Piece p = stack.back();
    stack.pop_back();
    const Vec2 endPoint = p.t1 == 1.0 ? s.end : s.pointAt(p.t1);
    const PolarPoint b = toPolar(endPoint, at.c);
    // A piece of an arc also sweeps at most 90 degrees of it: a spiral near the piece then covers it
    // (a full circle about the centre has the same C at both ends, and its spiral would not move).
    const bool turnsTooFar =
        std::abs(b.c - at.c) > 45.0 + 1e-9 || (s.isArc() && std::abs(s.sweep) * (p.t1 - p.t0) > 0.5 * kPi + 1e-12);
    const double dev = turnsTooFar ? 1e300 : spiralDeviation(at, b, s);
    if (dev > tolerance && p.depth < 60) {
      const double tm = 0.5 * (p.t0 + p.t1);
      stack.push_back({tm, p.t1, p.depth + 1});  // right half later
      stack.push_back({p.t0, tm, p.depth + 1});  // left half first
      continue;
    }
    out.maxDeviation = std::max(out.maxDeviation, turnsTooFar ? 0.0 : dev);
    at = b;
    out.points.push_back(b);
    if (out.points.size() > budget) {
      out.overBudget = true;
      return out;
    }
  }
  return out;
}

namespace {

PolarPoint along(const PolarPoint& a, const PolarPoint& b, double u) {
  return {a.radius + u * (b.radius - a.radius), a.c + u * (b.c - a.c)};
}

/// The arc through p, m, q (a line when they are collinear or the circle is immense).
Segment throughThree(const Vec2& p, const Vec2& m, const Vec2& q) {
  const Vec2 u = m - p, v = q - p;
  const double cross = u.x() * v.y() - u.y() * v.x();
  const double chord = v.norm();
  if (chord < 1e-12 || std::abs(cross) <= 1e-12 * std::max(1.0, chord * chord)) return Segment::line(p, q);
  // Circumcentre relative to p.
  const double uu = u.squaredNorm(), vv = v.squaredNorm();
  const Vec2 rel((v.y() * uu - u.y() * vv) / (2 * cross), (u.x() * vv - v.x() * uu) / (2 * cross));
  if (rel.norm() > 1e7) return Segment::line(p, q);
  return Segment::arc(p, q, p + rel, cross > 0 ? ArcDirection::CounterClockwise : ArcDirection::Clockwise);
}

}  // namespace

SpiralPieces spiralAsArcs(const PolarPoint& a, const PolarPoint& b, double tolerance, std::size_t budget) {
  SpiralPieces out;
  const double turn = std::abs(b.c - a.c);
  const double least = std::max(1.0, std::ceil(turn / 45.0));
  if (!std::isfinite(turn) || !(least <= static_cast<double>(budget))) {  // refuse before expanding
    out.overBudget = true;
    return out;
  }
  const auto n0 = static_cast<std::size_t>(least);
  struct Piece {
    double u0, u1;
    int depth;
  };
  std::vector<Piece> stack;
  for (std::size_t k = n0; k-- > 0;)
    stack.push_back(
        {static_cast<double>(k) / static_cast<double>(n0), static_cast<double>(k + 1) / static_cast<double>(n0), 0});
  while (!stack.empty()) {
    const Piece p = stack.back();
    stack.pop_back();
    const Vec2 s = fromPolar(p.u0 == 0.0 ? a : along(a, b, p.u0)), e = fromPolar(p.u1 == 1.0 ? b : along(a, b, p.u1));
    const Segment seg = throughThree(s, fromPolar(along(a, b, 0.5 * (p.u0 + p.u1))), e);
    double dev = 0.0;
    for (int k = 1; k <= 9; ++k)
      dev = std::max(dev, seg.distanceTo(fromPolar(along(a, b, p.u0 + k * (p.u1 - p.u0) / 10))));
    if (dev > tolerance && p.depth < 40) {
      if (out.pieces.size() + stack.size() + 2 > budget) {
        out.overBudget = true;
        out.pieces.clear();
        return out;
      }
      const double um = 0.5 * (p.u0 + p.u1);
      stack.push_back({um, p.u1, p.depth + 1});
      stack.push_back({p.u0, um, p.depth + 1});
      continue;
    }
    out.maxDeviation = std::max(out.maxDeviation, dev);
    if ((e - s).norm() < 1e-12 && seg.kind != SegmentKind::Arc) continue;  // a turn at the centre
    out.pieces.push_back(seg);
  }
  return out;
}

}  // namespace kerf::geometry
