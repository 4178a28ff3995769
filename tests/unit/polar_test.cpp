// Polar coordinates of a mill-turn face (geometry/polar.h, seed 002, docs/polar.md): the writer's
// subdivision and the reader's spirals, checked against the spiral sampled densely here.
#include "kerf/geometry/polar.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace kerf::geometry;

namespace {

/// The machine's spiral between two polar points at u in [0, 1], computed here on its own.
Vec2 spiralAt(const PolarPoint& a, const PolarPoint& b, double u) {
  const double r = a.radius + u * (b.radius - a.radius), c = (a.c + u * (b.c - a.c)) / kDegreesPerRadian;
  return {r * std::cos(c), r * std::sin(c)};
}

/// The largest distance from the spiral (sampled 20,000 times) to the nearest piece.
double farthest(const PolarPoint& a, const PolarPoint& b, const std::vector<Segment>& pieces) {
  double worst = 0.0;
  for (int k = 0; k <= 20000; ++k) {
    const Vec2 p = spiralAt(a, b, k / 20000.0);
    double best = 1e300;
    for (const Segment& s : pieces) best = std::min(best, s.distanceTo(p));
    worst = std::max(worst, best);
  }
  return worst;
}

TEST(unwrap_degrees_test, takes_the_value_nearest_the_previous) {
  EXPECT_DOUBLE_EQ(unwrapDegrees(-135.0, 180.0), 225.0);
  EXPECT_DOUBLE_EQ(unwrapDegrees(10.0, 725.0), 730.0);
  EXPECT_DOUBLE_EQ(unwrapDegrees(-154.231, -480.0), -514.231);  // seed 002's O31 end, one turn on
}

TEST(spiral_as_arcs_test, constant_radius_is_exact_arcs_about_the_centre) {
  const PolarPoint a{20.0, 10.0}, b{20.0, 100.0};
  const SpiralPieces s = spiralAsArcs(a, b, 1e-4, 1000);
  ASSERT_FALSE(s.overBudget);
  ASSERT_EQ(s.pieces.size(), 2u);  // 90 degrees: two pieces of at most 45
  for (const Segment& p : s.pieces) {
    ASSERT_TRUE(p.isArc());
    EXPECT_NEAR(p.centre.norm(), 0.0, 1e-9);
    EXPECT_NEAR(p.radius(), 20.0, 1e-9);
    EXPECT_GT(p.sweep, 0.0);  // C increasing: counter-clockwise
  }
  EXPECT_NEAR(s.pieces.front().start.x(), 20 * std::cos(10 / kDegreesPerRadian), 1e-12);
  EXPECT_NEAR(s.pieces.back().end.x(), 20 * std::cos(100 / kDegreesPerRadian), 1e-12);
  EXPECT_NEAR(s.pieces.back().end.y(), 20 * std::sin(100 / kDegreesPerRadian), 1e-12);
  EXPECT_LE(farthest(a, b, s.pieces), 1e-9);
}

TEST(spiral_as_arcs_test, a_growing_spiral_stays_within_the_tolerance_in_both_directions) {
  for (const double tol : {1e-3, 1e-4, 1e-5}) {
    for (const auto& [a, b] : {std::pair{PolarPoint{5.0, 0.0}, PolarPoint{40.0, 300.0}},
                               std::pair{PolarPoint{40.0, 300.0}, PolarPoint{5.0, 0.0}},
                               std::pair{PolarPoint{-3.0, 20.0}, PolarPoint{12.0, -70.0}}}) {
      const SpiralPieces s = spiralAsArcs(a, b, tol, 100000);
      ASSERT_FALSE(s.overBudget);
      ASSERT_FALSE(s.pieces.empty());
      EXPECT_LE(farthest(a, b, s.pieces), tol * 1.05) << "tolerance " << tol;
      EXPECT_LE(s.maxDeviation, tol);
      for (std::size_t i = 1; i < s.pieces.size(); ++i)
        EXPECT_LE((s.pieces[i].start - s.pieces[i - 1].end).norm(), 1e-9);  // one chain
      // Arcs, not chords: 300 degrees of a 40 mm spiral at 0.1 um takes few pieces.
      if (tol == 1e-4 && a.c == 0.0) {
        EXPECT_LE(s.pieces.size(), 60u) << s.pieces.size();
      }
    }
  }
}

TEST(spiral_as_arcs_test, a_turn_far_off_is_refused_before_it_is_expanded) {
  const SpiralPieces s = spiralAsArcs({10.0, 0.0}, {10.0, 3.6e9}, 1e-4, 100000);
  EXPECT_TRUE(s.overBudget);
  EXPECT_TRUE(s.pieces.empty());
  EXPECT_TRUE(spiralAsArcs({10.0, 0.0}, {10.0, std::nan("")}, 1e-4, 100000).overBudget);
}

TEST(subdivide_for_polar_test, a_full_circle_about_the_centre_turns_the_table_a_whole_turn) {
  const Segment circle = Segment::arc({10, 0}, {10, 0}, {0, 0}, ArcDirection::CounterClockwise);
  const PolarSubdivision s = subdivideForPolar(circle, 0.0, 1e-3, 1000);
  ASSERT_FALSE(s.points.empty());
  EXPECT_NEAR(s.points.back().c, 360.0, 1e-9);
  for (std::size_t i = 1; i < s.points.size(); ++i) {
    EXPECT_GT(s.points[i].c, s.points[i - 1].c);  // unwrapped: never back through -180
    EXPECT_LE(s.points[i].c - s.points[i - 1].c, 45.0 + 1e-9);
  }
}

TEST(subdivide_for_polar_test, a_clockwise_circle_off_the_centre_keeps_c_continuous) {
  const Segment circle = Segment::arc({30, 0}, {30, 0}, {20, 0}, ArcDirection::Clockwise);
  const PolarSubdivision s = subdivideForPolar(circle, 0.0, 1e-3, 100000);
  ASSERT_FALSE(s.points.empty());
  double previous = 0.0;
  for (const PolarPoint& p : s.points) {
    EXPECT_LE(std::abs(p.c - previous), 45.0 + 1e-9);
    previous = p.c;
  }
  EXPECT_NEAR(s.points.back().c, 0.0, 1e-9);  // the centre is outside: C comes back, no turn
  EXPECT_LE(s.maxDeviation, 1e-3);
}

}  // namespace
