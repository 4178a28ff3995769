// Helpers shared by the unit tests.
#pragma once

#include "kerf/geometry/parallel.h"
#include "kerf/geometry/segment.h"

#include <Eigen/Geometry>

#include <random>
#include <string>

namespace kerf::test {

/// Sets the workers of geometry/parallel.h for one test and restores the count after.
class ScopedThreads {
 public:
  explicit ScopedThreads(unsigned workers) : old_(geometry::workerCount()) { geometry::setWorkerCount(workers); }
  ~ScopedThreads() { geometry::setWorkerCount(old_); }
  ScopedThreads(const ScopedThreads&) = delete;
  ScopedThreads& operator=(const ScopedThreads&) = delete;

 private:
  unsigned old_;
};

using geometry::Segment;
using geometry::Vec2;

/// A rigid motion of the plane (rotation then translation), optionally mirrored in X.
struct Motion2 {
  double angle = 0.0;
  Vec2 shift{0, 0};
  bool mirror = false;

  [[nodiscard]] Vec2 apply(const Vec2& p) const {
    Vec2 q = mirror ? Vec2(-p.x(), p.y()) : p;
    return Eigen::Rotation2Dd(angle) * q + shift;
  }
  /// Mirroring reverses the sense of rotation.
  [[nodiscard]] geometry::ArcDirection apply(geometry::ArcDirection d) const {
    if (!mirror) return d;
    return d == geometry::ArcDirection::Clockwise ? geometry::ArcDirection::CounterClockwise
                                                  : geometry::ArcDirection::Clockwise;
  }
  [[nodiscard]] Segment apply(const Segment& s) const {
    if (!s.isArc()) return Segment::line(apply(s.start), apply(s.end));
    return Segment::arc(apply(s.start), apply(s.end), apply(s.centre), apply(s.direction()));
  }
};

inline std::vector<Motion2> someMotions() {
  return {{0.0, {0, 0}, false},
          {0.7, {13.5, -4.25}, false},
          {-2.1, {-100, 250}, false},
          {1.3, {3, 3}, true},
          {3.14159, {0.001, -0.002}, false}};
}

}  // namespace kerf::test
