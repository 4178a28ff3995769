// The placement search (geometry/align.h): a shape with no symmetry (an L with one rounded corner
// and a hole off its axes) placed by a known turn, shift and mirror is found again; a shape that
// fits as placed stays where it is; an empty set gives no placement.
#include "kerf/geometry/align.h"
#include "kerf/geometry/deviation.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace kerf::geometry;

namespace {

std::vector<Segment> shape() {
  return {Segment::line({0, 0}, {40, 0}),    Segment::line({40, 0}, {40, 10}),
          Segment::line({40, 10}, {15, 10}), Segment::arc({15, 10}, {10, 15}, {15, 15}, ArcDirection::Clockwise),
          Segment::line({10, 15}, {10, 30}), Segment::line({10, 30}, {0, 30}),
          Segment::line({0, 30}, {0, 0}),    Segment::arc({5, 4}, {5, 4}, {4, 4}, ArcDirection::CounterClockwise)};
}

/// The largest distance from the placed set's elements to the target (certified, deviation.h).
double worst(const std::vector<Segment>& from, const Placement& p, const std::vector<Segment>& to) {
  const DeviationSet target(to);
  double w = 0;
  for (const Segment& s : from) w = std::max(w, farthestFrom(p.apply(s), target).distance);
  return w;
}

TEST(align_test, a_turn_and_a_shift_are_found_again) {
  const Placement moved{false, 0.7, Vec2(12.5, -4.0)};
  std::vector<Segment> target;
  for (const Segment& s : shape()) target.push_back(moved.apply(s));
  const Alignment a = align(shape(), target);
  EXPECT_FALSE(a.placement.mirror);
  EXPECT_NEAR(a.placement.angle, 0.7, 1e-9);
  EXPECT_NEAR((a.placement.shift - moved.shift).norm(), 0.0, 1e-8);
  EXPECT_LE(worst(shape(), a.placement, target), 1e-6);
}

TEST(align_test, a_mirror_is_found_and_turns_arcs_round) {
  const Placement moved{true, -2.0, Vec2(-30, 7)};
  std::vector<Segment> target;
  for (const Segment& s : shape()) target.push_back(moved.apply(s));
  EXPECT_LT(target[3].sweep * shape()[3].sweep, 0) << "a mirrored arc turns the other way";
  const Alignment a = align(shape(), target);
  EXPECT_TRUE(a.placement.mirror);
  EXPECT_NEAR(std::remainder(a.placement.angle + 2.0, 2 * kPi), 0.0, 1e-9);
  EXPECT_LE(worst(shape(), a.placement, target), 1e-6);
  AlignOptions noMirror;
  noMirror.allowMirror = false;
  EXPECT_GT(align(shape(), target, noMirror).rms, 0.5) << "without a mirror nothing fits";
}

TEST(align_test, a_shape_that_fits_stays_as_placed) {
  const Alignment a = align(shape(), shape());
  EXPECT_FALSE(a.placement.mirror);
  EXPECT_NEAR(a.placement.angle, 0.0, 1e-12);
  EXPECT_NEAR(a.placement.shift.norm(), 0.0, 1e-10);
  EXPECT_LE(a.rms, 1e-4);
}

TEST(align_test, an_empty_set_has_no_placement) {
  EXPECT_TRUE(std::isinf(align({}, shape()).rms));
  EXPECT_TRUE(std::isinf(align(shape(), {}).rms));
}

}  // namespace
