// Rounded and chamfered corners (geometry/corner.h): each result checked by what a fillet is —
// tangent to both elements at its ends, its radius r — not by the figures the code computes.
#include "kerf/geometry/corner.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using kerf::geometry::ArcDirection;
using kerf::geometry::chamferCorner;
using kerf::geometry::Corner;
using kerf::geometry::CornerStatus;
using kerf::geometry::roundCorner;
using kerf::geometry::Segment;
using kerf::geometry::Vec2;

/// The fillet's ends lie on the trimmed elements' ends, its radius is r, and its tangents there are
/// the elements' tangents (G1 continuity).
void expectTangentFillet(const Corner& c, double r) {
  ASSERT_EQ(c.status, CornerStatus::Ok);
  ASSERT_TRUE(c.corner.isArc());
  EXPECT_NEAR(c.corner.radius(), r, 1e-12);
  EXPECT_NEAR((c.first.end - c.corner.start).norm(), 0.0, 1e-12);
  EXPECT_NEAR((c.corner.end - c.second.start).norm(), 0.0, 1e-12);
  EXPECT_NEAR((c.first.tangentAt(1.0) - c.corner.tangentAt(0.0)).norm(), 0.0, 1e-9);
  EXPECT_NEAR((c.corner.tangentAt(1.0) - c.second.tangentAt(0.0)).norm(), 0.0, 1e-9);
}

TEST(corner_test, a_right_angle_between_lines_is_rounded_by_a_quarter_circle) {
  const Segment a = Segment::line({0, 0}, {10, 0}), b = Segment::line({10, 0}, {10, 10});
  const Corner c = roundCorner(a, b, 2.0);
  expectTangentFillet(c, 2.0);
  EXPECT_NEAR((c.corner.centre - Vec2(8, 2)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(std::abs(c.corner.sweep), M_PI / 2, 1e-12);
  EXPECT_NEAR((c.sharp - Vec2(10, 0)).norm(), 0.0, 0.0);
}

TEST(corner_test, a_right_turn_is_rounded_clockwise) {
  const Segment a = Segment::line({0, 0}, {10, 0}), b = Segment::line({10, 0}, {10, -10});
  const Corner c = roundCorner(a, b, 1.0);
  expectTangentFillet(c, 1.0);
  EXPECT_EQ(c.corner.direction(), ArcDirection::Clockwise);
}

TEST(corner_test, arcs_on_both_sides_are_joined_tangent_to_both) {
  // Two arcs meeting at (10, 0) at an angle: the fillet's centre lies r from both circles.
  const Segment a = Segment::arc({0, 0}, {10, 0}, {5, -5}, ArcDirection::Clockwise);
  const Segment b = Segment::arc({10, 0}, {20, 0}, {15, -5}, ArcDirection::Clockwise);
  const Corner c = roundCorner(a, b, 1.5);
  expectTangentFillet(c, 1.5);
  const double ra = (a.start - a.centre).norm(), rb = (b.start - b.centre).norm();
  EXPECT_NEAR(std::abs((c.corner.centre - a.centre).norm() - ra), 1.5, 1e-9);
  EXPECT_NEAR(std::abs((c.corner.centre - b.centre).norm() - rb), 1.5, 1e-9);
}

TEST(corner_test, a_chamfer_cuts_c_from_each_line) {
  const Segment a = Segment::line({0, 0}, {10, 0}), b = Segment::line({10, 0}, {10, 10});
  const Corner c = chamferCorner(a, b, 1.5);
  ASSERT_EQ(c.status, CornerStatus::Ok);
  EXPECT_NEAR((c.corner.start - Vec2(8.5, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((c.corner.end - Vec2(10, 1.5)).norm(), 0.0, 1e-12);
}

TEST(corner_test, what_cannot_be_made_says_why) {
  const Segment a = Segment::line({0, 0}, {10, 0});
  EXPECT_EQ(roundCorner(a, Segment::line({10, 0}, {20, 0}), 1.0).status, CornerStatus::Tangent);
  EXPECT_EQ(roundCorner(a, Segment::line({10, 0}, {5, 0}), 1.0).status, CornerStatus::Reversal);
  EXPECT_EQ(roundCorner(a, Segment::line({11, 0}, {11, 5}), 1.0).status, CornerStatus::NotJoined);
  // r = 3 needs 3 mm of the second line, which has 2.
  EXPECT_EQ(roundCorner(a, Segment::line({10, 0}, {10, 2}), 3.0).status, CornerStatus::DoesNotFit);
  EXPECT_EQ(chamferCorner(a, Segment::line({10, 0}, {10, 2}), 3.0).status, CornerStatus::DoesNotFit);
  EXPECT_EQ(roundCorner(a, Segment::line({10, 0}, {10, 2}), 0.0).status, CornerStatus::DoesNotFit);
}

}  // namespace
