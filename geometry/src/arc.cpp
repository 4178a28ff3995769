#include "kerf/geometry/arc.h"

#include <cmath>
#include <limits>

namespace kerf::geometry {

ArcTolerance ArcTolerance::forInch() {
  ArcTolerance t;
  t.radius = 0.00005 * 25.4;                                    // RADIUS_TOLERANCE_INCH
  t.centreAbsolute = 2.0 * 0.001 * std::numbers::sqrt2 * 25.4;  // CENTER_ARC_RADIUS_TOLERANCE_INCH
  return t;
}

ArcBuild arcFromRadius(const Vec2& start, const Vec2& end, double signedRadius, ArcDirection dir,
                       const ArcTolerance& tol) {
  ArcBuild out;
  const Vec2 chord = end - start;
  const double chordLength = chord.norm();
  out.halfChord = chordLength / 2;
  const double r = std::abs(signedRadius);
  if (r < tol.radius) {
    out.status = ArcStatus::ZeroRadius;
    return out;
  }
  if (chordLength <= tol.radius) {
    out.status = ArcStatus::FullCircleWithRadius;
    return out;
  }
  if (out.halfChord - r > tol.radius) {
    out.status = ArcStatus::RadiusTooSmall;
    return out;
  }
  // Distance from the chord midpoint to the centre; 0 when R is (within tolerance) half the chord.
  const double h2 = r * r - out.halfChord * out.halfChord;
  const double h = h2 > 0 ? std::sqrt(h2) : 0.0;
  const Vec2 mid = (start + end) / 2;
  const Vec2 left(-chord.y() / chordLength, chord.x() / chordLength);  // chord turned +90 degrees
  // For a counter-clockwise arc of at most 180 degrees the centre is left of the chord; a
  // clockwise one has it on the right; a negative R (the longer arc) swaps the side.
  double side = dir == ArcDirection::CounterClockwise ? 1.0 : -1.0;
  if (signedRadius < 0) side = -side;
  const Vec2 centre = mid + side * h * left;
  out.arc = Segment::arc(start, end, centre, dir);
  return out;
}

int seedSignFactor(ArcDirection dir, double signedRadius) {
  if (dir == ArcDirection::Clockwise) return signedRadius > 0 ? 1 : -1;
  return signedRadius < 0 ? 1 : -1;
}

Vec2 seedCentreFromRadius(const Vec2& start, const Vec2& end, double signedRadius, ArcDirection dir) {
  // Formulas (1) and (2) of the seed paper, term by term. P = start (Xp, Yp), K = end (Xk, Yk).
  const double xp = start.x(), yp = start.y(), xk = end.x(), yk = end.y();
  const double r = std::abs(signedRadius);
  const double zn = seedSignFactor(dir, signedRadius);
  const double d = xp * xp + xk * xk + yp * yp + yk * yk - 2 * xp * xk - 2 * yp * yk;  // |PK|^2
  const double disc = -xp * xp - xk * xk - yp * yp - yk * yk + 2 * xp * xk + 2 * yp * yk + 4 * r * r;
  if (d <= 0 || disc < 0) return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
  const double xs = (xp * xp * xp + xp * yp * yp + xp * yk * yk - xp * xp * xk - 2 * xp * yp * yk) / (2 * d) +
                    (xk * xk * xk + xk * yp * yp + xk * yk * yk - xp * xk * xk - 2 * xk * yp * yk) / (2 * d) -
                    std::sqrt((yp - yk) * (yp - yk) * disc) / (2 * std::sqrt(d)) * zn;
  const double ys = (yp * yp * yp + yp * xp * xp + yp * xk * xk - yp * yp * yk - 2 * yp * xp * xk) / (2 * d) +
                    (yk * yk * yk + yk * xp * xp + yk * xk * xk - yp * yk * yk - 2 * yk * xp * xk) / (2 * d) +
                    std::sqrt((xp - xk) * (xp - xk) * disc) / (2 * std::sqrt(d)) * zn;
  return {xs, ys};
}

Vec2 seedCentreFromRadiusSigned(const Vec2& start, const Vec2& end, double signedRadius, ArcDirection dir) {
  const double xp = start.x(), yp = start.y(), xk = end.x(), yk = end.y();
  const double r = std::abs(signedRadius);
  const double zn = seedSignFactor(dir, signedRadius);
  const double d = (xp - xk) * (xp - xk) + (yp - yk) * (yp - yk);
  const double disc = 4 * r * r - d;
  if (d <= 0 || disc < 0) return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
  // The first two fractions of (1) and (2) simplify to the chord midpoint.
  const double xs = (xp + xk) / 2 - (yp - yk) * std::sqrt(disc) / (2 * std::sqrt(d)) * zn;
  const double ys = (yp + yk) / 2 + (xp - xk) * std::sqrt(disc) / (2 * std::sqrt(d)) * zn;
  return {xs, ys};
}

ArcStatus centreVerdict(const Vec2& start, const Vec2& end, const Vec2& centre, const ArcTolerance& tol,
                        double* radiusError) {
  const double r0 = (start - centre).norm();
  const double r1 = (end - centre).norm();
  if (radiusError) *radiusError = r1 - r0;
  if (r0 < tol.radius || r1 < tol.radius) return ArcStatus::ZeroRadius;
  // LinuxCNC's rule: up to centreAbsolute always fine; up to 100x that, fine if the relative
  // difference is within centreRelative; beyond, always an error.
  const double delta = std::abs(r1 - r0);
  const bool ok = delta <= tol.centreAbsolute ||
                  (delta <= 100 * tol.centreAbsolute && delta / std::max(r0, r1) <= tol.centreRelative);
  return ok ? ArcStatus::Ok : ArcStatus::EndOffCircle;
}

ArcBuild arcFromCentre(const Vec2& start, const Vec2& end, const Vec2& centre, ArcDirection dir,
                       const ArcTolerance& tol) {
  ArcBuild out;
  out.status = centreVerdict(start, end, centre, tol, &out.radiusError);
  if (out.status == ArcStatus::Ok) out.arc = Segment::arc(start, end, centre, dir);
  return out;
}

}  // namespace kerf::geometry
