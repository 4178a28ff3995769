// Vectors and angles shared by every geometry routine.
//
// Units: millimetres and radians. Angles are measured counter-clockwise from +X, as seen
// from +Z (the usual mathematical sense), unless a function says otherwise.
#pragma once

#include <Eigen/Core>

#include <cmath>
#include <numbers>

namespace kerf::geometry {

/// A point or a vector in a plane, mm. Not aligned to 16 bytes (Eigen::DontAlign): a segment of
/// three of them and its sweep is then 57 bytes, and a move that holds one 72, not 80 (the
/// operations are the same, on unaligned loads).
using Vec2 = Eigen::Matrix<double, 2, 1, Eigen::DontAlign>;
using Vec3 = Eigen::Vector3d;

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kTwoPi = 2.0 * std::numbers::pi;
/// Degrees per radian: an angle in radians times this is the angle in degrees.
inline constexpr double kDegreesPerRadian = 180.0 / kPi;

/// z component of the 3D cross product of (a, 0) and (b, 0).
inline double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

/// v turned +90 degrees (counter-clockwise): the left normal of a direction, as long as v.
inline Vec2 leftNormal(const Vec2& v) { return {-v.y(), v.x()}; }

/// Angle of v from +X in (-pi, pi].
inline double angleOf(const Vec2& v) { return std::atan2(v.y(), v.x()); }

/// Unit vector at angle a.
inline Vec2 direction(double a) { return {std::cos(a), std::sin(a)}; }

/// Axis-aligned box; empty when min > max.
struct Box {
  Vec2 min{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  Vec2 max{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};

  void add(const Vec2& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  void add(const Box& b) {
    min = min.cwiseMin(b.min);
    max = max.cwiseMax(b.max);
  }
  [[nodiscard]] bool empty() const { return min.x() > max.x(); }
  [[nodiscard]] bool overlaps(const Box& b, double tol) const {
    return min.x() <= b.max.x() + tol && b.min.x() <= max.x() + tol && min.y() <= b.max.y() + tol &&
           b.min.y() <= max.y() + tol;
  }
};

}  // namespace kerf::geometry
