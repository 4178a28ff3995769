// 3B geometry shared by the reader and the writer (three_b.h).
#include "three_b.h"

#include <algorithm>
#include <cmath>

namespace kerf::converter {

namespace three_b {

using geometry::kPi;
using geometry::Vec2;

Vec2 quadrantSigns(int q) {
  switch (q) {
    case 1: return {1, 1};
    case 2: return {-1, 1};
    case 3: return {-1, -1};
    default: return {1, -1};
  }
}

int lineQuadrant(double dx, double dy) {
  if (dy == 0) return dx > 0 ? 1 : 3;
  if (dx == 0) return dy > 0 ? 2 : 4;
  if (dx > 0) return dy > 0 ? 1 : 4;
  return dy > 0 ? 2 : 3;
}

Axis lineAxis(double dx, double dy) {
  const double ax = std::abs(dx), ay = std::abs(dy);
  if (ax > ay) return Axis::X;
  if (ay > ax) return Axis::Y;
  const int q = lineQuadrant(dx, dy);
  return (q == 1 || q == 3) ? Axis::Y : Axis::X;
}

int arcQuadrant(double sx, double sy, bool ccw) {
  if (sy == 0 && sx == 0) return 1;
  if (ccw) {
    if (sx > 0 && sy >= 0) return 1;  // +X moves into quadrant 1
    if (sx <= 0 && sy > 0) return 2;  // +Y into 2
    if (sx < 0 && sy <= 0) return 3;  // -X into 3
    return 4;                         // -Y into 4
  }
  if (sx >= 0 && sy > 0) return 1;  // +Y moves clockwise into quadrant 1
  if (sx < 0 && sy >= 0) return 2;  // -X into 2
  if (sx <= 0 && sy < 0) return 3;  // -Y into 3
  return 4;                         // +X into 4
}

Axis arcAxis(double ex, double ey) { return std::abs(ex) > std::abs(ey) ? Axis::Y : Axis::X; }

namespace {

/// The coordinate's extremes lie at offset + k pi; its value there is r (-1)^k.
double extremeOffset(Axis axis) { return axis == Axis::X ? 0.0 : kPi / 2; }
double extremeValue(double r, long long k) { return (k % 2 == 0) ? r : -r; }
/// The index k of the first extreme strictly after angle a in direction dir.
long long firstExtreme(double a, double dir, Axis axis) {
  const double u = (a - extremeOffset(axis)) / kPi;
  return dir > 0 ? static_cast<long long>(std::floor(u + 1e-12)) + 1 : static_cast<long long>(std::ceil(u - 1e-12)) - 1;
}

}  // namespace

double arcCount(double a0, double sweep, double r, Axis axis, double startValue, double endValue) {
  const double dir = sweep >= 0 ? 1.0 : -1.0;
  const double a1 = a0 + sweep;
  double total = 0.0, v = startValue;
  for (long long k = firstExtreme(a0, dir, axis);; k += static_cast<long long>(dir)) {
    const double e = extremeOffset(axis) + static_cast<double>(k) * kPi;
    if (dir * (e - a1) >= -1e-12) break;  // at or past the end
    const double ext = extremeValue(r, k);
    total += std::abs(ext - v);
    v = ext;
  }
  return total + std::abs(endValue - v);
}

bool arcEnd(const Vec2& startRel, bool ccw, Axis axis, double count, double slack, Vec2& endRel, double& sweep) {
  const double dir = ccw ? 1.0 : -1.0;
  const double r = startRel.norm();
  if (!(r > 0)) return false;  // no circle to walk
  const double a0 = std::atan2(startRel.y(), startRel.x());
  const int ax = axis == Axis::X ? 0 : 1;
  double remaining = count, v = startRel[ax], theta = a0;
  long long k = firstExtreme(a0, dir, axis);
  for (;;) {
    double e = extremeOffset(axis) + static_cast<double>(k) * kPi;
    double ext = extremeValue(r, k);
    const bool last = dir * (e - (a0 + dir * 2 * kPi)) >= -1e-12;
    if (last) {  // the piece that closes the circle
      e = a0 + dir * 2 * kPi;
      ext = startRel[ax];
    }
    const double travel = std::abs(ext - v);
    if (remaining <= travel) {
      // The piece from theta to e lies between the extremes n and n + 1, where the coordinate is
      // r (-1)^n cos(t - E_n): solved in closed form. The other coordinate follows the circle,
      // from the count coordinate (better conditioned near an extreme than r sin t).
      const double target = v + (ext >= v ? remaining : -remaining);
      const long long n = dir > 0 ? k - 1 : k;
      const double base = extremeOffset(axis) + static_cast<double>(n) * kPi;
      const double c = std::clamp((n % 2 == 0 ? 1.0 : -1.0) * target / r, -1.0, 1.0);
      const double t = std::clamp(base + std::acos(c), std::min(theta, e), std::max(theta, e));
      const double other = std::sqrt(std::max(0.0, r * r - target * target));
      const double otherSign = (axis == Axis::X ? std::sin(t) : std::cos(t)) < 0 ? -1.0 : 1.0;
      endRel = axis == Axis::X ? Vec2(target, otherSign * other) : Vec2(otherSign * other, target);
      sweep = t - a0;
      if (remaining == travel && last) {  // exactly a full circle
        endRel = startRel;
        sweep = dir * 2 * kPi;
      }
      return true;
    }
    remaining -= travel;
    if (last) {
      if (remaining > slack) return false;
      endRel = startRel;
      sweep = dir * 2 * kPi;
      return true;
    }
    theta = e;
    v = ext;
    k += static_cast<long long>(dir);
  }
}

}  // namespace three_b

}  // namespace kerf::converter
