// The wire offset (geometry/offset.h, wireOffset): arc joins, concave corners, interference across
// the whole path, slots narrower than the wire, splits. The GEOS comparison on real drawings and
// random polygons is tests/data/offset_test.cpp.
#include "kerf/geometry/chain.h"
#include "kerf/geometry/offset.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <span>
#include <vector>

namespace {

using kerf::geometry::ArcDirection;
using kerf::geometry::Segment;
using kerf::geometry::signedArea;
using kerf::geometry::Vec2;
using kerf::geometry::wireOffset;
using kerf::geometry::WireOffsetOptions;
using kerf::geometry::WirePiece;

std::vector<Segment> polygon(const std::vector<Vec2>& p) {
  std::vector<Segment> s;
  for (std::size_t i = 0; i < p.size(); ++i) s.push_back(Segment::line(p[i], p[(i + 1) % p.size()]));
  return s;
}

std::vector<Segment> segments(const std::vector<WirePiece>& path) {
  std::vector<Segment> s;
  for (const WirePiece& p : path) s.push_back(p.segment);
  return s;
}

/// Every point of the path is |d| from the contour, and the path is connected and closed.
void expectExactDistance(const std::vector<Segment>& contour, const std::vector<WirePiece>& path, double d) {
  ASSERT_FALSE(path.empty());
  for (std::size_t i = 0; i < path.size(); ++i) {
    const Segment& s = path[i].segment;
    EXPECT_LT((s.end - path[(i + 1) % path.size()].segment.start).norm(), 1e-9) << "gap after piece " << i;
    for (int k = 0; k <= 10; ++k) {
      const Vec2 p = s.pointAt(k / 10.0);
      double nearest = 1e300;
      for (const Segment& c : contour) nearest = std::min(nearest, c.distanceTo(p));
      EXPECT_NEAR(nearest, std::abs(d), 1e-9) << "piece " << i << " at t " << k / 10.0;
    }
  }
}

TEST(wire_offset_test, a_square_outside_gets_arcs_at_its_corners_of_the_offset_radius) {
  const auto square = polygon({{0, 0}, {10, 0}, {10, 10}, {0, 10}});  // counter-clockwise
  const auto r = wireOffset(square, -1.0);                            // right of travel: outside
  ASSERT_EQ(r.paths.size(), 1u);
  const auto& path = r.paths[0];
  ASSERT_EQ(path.size(), 8u);
  int corners = 0;
  for (const WirePiece& p : path) {
    if (!p.corner) continue;
    ++corners;
    ASSERT_TRUE(p.segment.isArc());
    EXPECT_NEAR(p.segment.radius(), 1.0, 1e-12);
    EXPECT_GT(p.segment.sweep, 0) << "a right offset turns counter-clockwise round a convex corner";
    EXPECT_NEAR(std::abs(p.segment.sweep), std::numbers::pi / 2, 1e-12);
  }
  EXPECT_EQ(corners, 4);
  EXPECT_NEAR(signedArea(segments(path)), 100 + 40 + std::numbers::pi, 1e-9);
  expectExactDistance(square, path, 1.0);
  EXPECT_TRUE(r.lost.empty());
}

TEST(wire_offset_test, a_left_offset_rolls_clockwise_round_a_convex_corner) {
  const auto square = polygon({{0, 0}, {0, 10}, {10, 10}, {10, 0}});  // clockwise: left is outside
  const auto r = wireOffset(square, 1.0);
  ASSERT_EQ(r.paths.size(), 1u);
  for (const WirePiece& p : r.paths[0]) {
    if (p.corner) {
      EXPECT_LT(p.segment.sweep, 0);
    }
  }
  EXPECT_NEAR(std::abs(signedArea(segments(r.paths[0]))), 100 + 40 + std::numbers::pi, 1e-9);
}

TEST(wire_offset_test, inside_a_square_the_corners_stay_sharp) {
  const auto square = polygon({{0, 0}, {10, 0}, {10, 10}, {0, 10}});
  const auto r = wireOffset(square, 1.0);
  ASSERT_EQ(r.paths.size(), 1u);
  ASSERT_EQ(r.paths[0].size(), 4u);
  for (const WirePiece& p : r.paths[0]) EXPECT_FALSE(p.corner);
  EXPECT_NEAR(signedArea(segments(r.paths[0])), 64.0, 1e-9);
  EXPECT_NEAR(r.paths[0][0].segment.start.x(), 1.0, 1e-12);
  EXPECT_NEAR(r.paths[0][0].segment.start.y(), 1.0, 1e-12);
}

TEST(wire_offset_test, a_circle_grows_and_shrinks_and_vanishes_when_smaller_than_the_wire) {
  const Segment circle = Segment::arc({5, 0}, {5, 0}, {0, 0}, ArcDirection::CounterClockwise);
  const std::vector<Segment> c{circle};
  auto out = wireOffset(c, -0.5);
  ASSERT_EQ(out.paths.size(), 1u);
  EXPECT_NEAR(signedArea(segments(out.paths[0])), std::numbers::pi * 5.5 * 5.5, 1e-9);
  auto in = wireOffset(c, 0.5);
  ASSERT_EQ(in.paths.size(), 1u);
  EXPECT_NEAR(signedArea(segments(in.paths[0])), std::numbers::pi * 4.5 * 4.5, 1e-9);
  // Clockwise, with the offset's middle on the horizontal through the circle's start point.
  const std::vector<Segment> cw{circle.reversed()};
  auto inCw = wireOffset(cw, -0.5);
  ASSERT_EQ(inCw.paths.size(), 1u);
  EXPECT_NEAR(signedArea(segments(inCw.paths[0])), -std::numbers::pi * 4.5 * 4.5, 1e-9);
  auto gone = wireOffset(c, 6.0);
  EXPECT_TRUE(gone.paths.empty());
  ASSERT_EQ(gone.lost.size(), 1u);
}

TEST(wire_offset_test, a_corner_arc_shorter_than_the_link_tolerance_at_the_seam_stays_in_the_loop) {
  // A square whose first side leaves the start point 1e-5 rad off the last side's direction (a
  // closed curve fitted with biarcs has such a seam): the corner arc there is 5e-6 mm long, well
  // inside the linking tolerance, and must not be left over as a loop of its own.
  const std::vector<Vec2> v{{5, 0}, {10, 5e-5}, {10, 10}, {0, 10}, {0, 0}};
  std::vector<Segment> sq;
  for (std::size_t k = 0; k < v.size(); ++k) sq.push_back(Segment::line(v[k], v[(k + 1) % v.size()]));
  const auto out = wireOffset(sq, -0.5);
  ASSERT_EQ(out.paths.size(), 1u);
  EXPECT_NEAR(signedArea(segments(out.paths[0])), 100 + 4 * 10 * 0.5 + std::numbers::pi * 0.25, 1e-3);
}

TEST(wire_offset_test, a_slot_narrower_than_the_wire_disappears_and_is_named) {
  // A die 20 x 10 with a slot 0.2 wide and 4 long out of its top edge; wire offset 0.15 inside.
  const auto die = polygon({{0, 0}, {20, 0}, {20, 10}, {10.1, 10}, {10.1, 14}, {9.9, 14}, {9.9, 10}, {0, 10}});
  const auto r = wireOffset(die, 0.15);
  ASSERT_EQ(r.paths.size(), 1u);
  expectExactDistance(die, r.paths[0], 0.15);
  ASSERT_EQ(r.lost.size(), 1u);
  const auto& lost = r.lost[0];
  EXPECT_EQ(lost.first, 3u);  // the slot's walls and end
  EXPECT_EQ(lost.count, 3u);
  EXPECT_FALSE(lost.fillet);
  EXPECT_NEAR(lost.where.y(), 14.0, 1e-9);
  // The wire reaches into the mouth to where its arcs about the two mouth corners meet, at
  // (10, 10 - sqrt(0.15^2 - 0.1^2)), below the mouth; the slot's far corners stay that far away, less the offset.
  const double reach = 10 - std::sqrt(0.15 * 0.15 - 0.1 * 0.1);
  EXPECT_NEAR(lost.uncut, std::hypot(0.1, 14 - reach) - 0.15, 1e-9);
  // A slot wider than the wire is followed.
  const auto wide = polygon({{0, 0}, {20, 0}, {20, 10}, {10.2, 10}, {10.2, 14}, {9.8, 14}, {9.8, 10}, {0, 10}});
  EXPECT_TRUE(wireOffset(wide, 0.15).lost.empty());
}

TEST(wire_offset_test, a_contour_pinched_narrower_than_the_wire_splits_in_two) {
  // Two 10 x 10 squares joined by a neck 0.2 wide: inside at 0.15 the path is two loops.
  const auto dumbbell = polygon({{0, 0},
                                 {10, 0},
                                 {10, 4.9},
                                 {15, 4.9},
                                 {15, 0},
                                 {25, 0},
                                 {25, 10},
                                 {15, 10},
                                 {15, 5.1},
                                 {10, 5.1},
                                 {10, 10},
                                 {0, 10}});
  const auto r = wireOffset(dumbbell, 0.15);
  ASSERT_EQ(r.paths.size(), 2u);
  // Each loop is the square 9.7 x 9.7 and a bump into the neck's mouth between the arcs about its
  // two corners: 2 (0.15 * 0.1 - integral of sqrt(0.15^2 - u^2) over [0, 0.1]).
  const double a = 0.1, rr = 0.15;
  const double bump = 2 * (rr * a - 0.5 * (a * std::sqrt(rr * rr - a * a) + rr * rr * std::asin(a / rr)));
  for (const auto& p : r.paths) {
    expectExactDistance(dumbbell, p, 0.15);
    EXPECT_NEAR(signedArea(segments(p)), 9.7 * 9.7 + bump, 1e-9);
  }
}

TEST(wire_offset_test, an_inside_fillet_smaller_than_the_wire_is_reported_as_such) {
  // An L with a 0.1 fillet in its inside corner; outside offset 0.15 (the fillet is concave there).
  std::vector<Segment> l;
  l.push_back(Segment::line({0, 0}, {10, 0}));
  l.push_back(Segment::line({10, 0}, {10, 2}));
  l.push_back(Segment::line({10, 2}, {2.1, 2}));
  l.push_back(Segment::arc({2.1, 2}, {2, 2.1}, {2.1, 2.1}, ArcDirection::Clockwise));
  l.push_back(Segment::line({2, 2.1}, {2, 10}));
  l.push_back(Segment::line({2, 10}, {0, 10}));
  l.push_back(Segment::line({0, 10}, {0, 0}));
  const auto r = wireOffset(l, -0.15);
  ASSERT_EQ(r.paths.size(), 1u);
  expectExactDistance(l, r.paths[0], 0.15);
  ASSERT_EQ(r.lost.size(), 1u);
  EXPECT_EQ(r.lost[0].first, 3u);
  EXPECT_TRUE(r.lost[0].fillet);
}

TEST(wire_offset_test, arcs_that_turn_inside_out_are_removed_not_followed) {
  // A rounded square (corner radius 1) offset inside by 2: the corners vanish, sharp, as a square.
  std::vector<Segment> s;
  const double r = 1.0;
  s.push_back(Segment::line({r, 0}, {10 - r, 0}));
  s.push_back(Segment::arc({10 - r, 0}, {10, r}, {10 - r, r}, ArcDirection::CounterClockwise));
  s.push_back(Segment::line({10, r}, {10, 10 - r}));
  s.push_back(Segment::arc({10, 10 - r}, {10 - r, 10}, {10 - r, 10 - r}, ArcDirection::CounterClockwise));
  s.push_back(Segment::line({10 - r, 10}, {r, 10}));
  s.push_back(Segment::arc({r, 10}, {0, 10 - r}, {r, 10 - r}, ArcDirection::CounterClockwise));
  s.push_back(Segment::line({0, 10 - r}, {0, r}));
  s.push_back(Segment::arc({0, r}, {r, 0}, {r, r}, ArcDirection::CounterClockwise));
  const auto in = wireOffset(s, 2.0);
  ASSERT_EQ(in.paths.size(), 1u);
  EXPECT_NEAR(signedArea(segments(in.paths[0])), 36.0, 1e-9);
  expectExactDistance(s, in.paths[0], 2.0);
  const auto out = wireOffset(s, -2.0);
  ASSERT_EQ(out.paths.size(), 1u);
  expectExactDistance(s, out.paths[0], 2.0);
  EXPECT_EQ(out.paths[0].size(), 8u) << "tangent joints need no corner arc";
}

TEST(wire_offset_test, an_open_chain_keeps_its_order_and_gets_arcs_only_at_its_corners) {
  const std::vector<Segment> open = polygon({{0, 0}, {10, 0}, {10, 10}, {0, 10}});
  std::vector<Segment> chain(open.begin(), open.begin() + 3);
  WireOffsetOptions o;
  o.closed = false;
  const auto r = wireOffset(chain, -1.0, o);
  ASSERT_EQ(r.paths.size(), 1u);
  ASSERT_EQ(r.paths[0].size(), 5u);
  EXPECT_NEAR(r.paths[0].front().segment.start.y(), -1.0, 1e-12);
  EXPECT_NEAR(r.paths[0].back().segment.end.y(), 11.0, 1e-12);
}

TEST(wire_offset_test, random_stars_stay_exactly_at_the_distance) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> radius(3.0, 10.0);
  for (int trial = 0; trial < 30; ++trial) {
    std::vector<Vec2> pts;
    const int n = 5 + trial % 20;
    for (int k = 0; k < n; ++k) {
      const double a = 2 * std::numbers::pi * k / n;
      const double r = radius(rng);
      pts.emplace_back(r * std::cos(a), r * std::sin(a));
    }
    const auto star = polygon(pts);
    for (double d : {0.15, -0.15, 1.0, -1.0}) {
      const auto r = wireOffset(star, d);
      ASSERT_GE(r.paths.size(), 1u) << trial << " " << d;
      for (const auto& p : r.paths) expectExactDistance(star, p, d);
    }
  }
}

TEST(wire_offset_test, loops_around_counts_what_asking_every_loop_counts) {
  // Random squares, circles (two arcs) and rotated triangles, many nested: for each loop's probe,
  // the loops round it from the box tree against windingNumber over every loop.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<std::vector<Segment>> shapes;
  for (int k = 0; k < 300; ++k) {
    const Vec2 c(100 * u(rng), 100 * u(rng));
    const double r = 0.5 + 30 * u(rng) * u(rng);
    if (k % 3 == 0) {
      shapes.push_back(polygon({c + Vec2(-r, -r), c + Vec2(r, -r), c + Vec2(r, r), c + Vec2(-r, r)}));
    } else if (k % 3 == 1) {
      const Vec2 a = c + Vec2(r, 0), b = c - Vec2(r, 0);
      shapes.push_back({Segment::arc(a, b, c, ArcDirection::CounterClockwise),
                        Segment::arc(b, a, c, ArcDirection::CounterClockwise)});
    } else {
      const double t = 6.28 * u(rng);
      shapes.push_back(
          polygon({c + r * Vec2(std::cos(t), std::sin(t)), c + r * Vec2(std::cos(t + 2.1), std::sin(t + 2.1)),
                   c + r * Vec2(std::cos(t + 4.2), std::sin(t + 4.2))}));
    }
  }
  std::vector<std::span<const Segment>> loops(shapes.begin(), shapes.end());
  std::vector<Vec2> probes;
  std::vector<std::size_t> self;
  for (std::size_t l = 0; l < loops.size(); ++l) {
    probes.push_back(loops[l].front().pointAt(0.5));
    self.push_back(l);
  }
  const std::vector<int> fast = kerf::geometry::loopsAround(loops, probes, self);
  int nested = 0;
  for (std::size_t i = 0; i < probes.size(); ++i) {
    int all = 0;
    for (std::size_t l = 0; l < loops.size(); ++l)
      all += l != self[i] && kerf::geometry::windingNumber(loops[l], probes[i]) != 0;
    EXPECT_EQ(fast[i], all) << "probe " << i;
    nested += all > 0;
  }
  EXPECT_GT(nested, 50);  // many probes lie inside other loops, so the counts mean something
}

TEST(wire_offset_test, too_many_pieces_is_refused_before_work) {
  const auto square = polygon({{0, 0}, {10, 0}, {10, 10}, {0, 10}});
  WireOffsetOptions o;
  o.maxPieces = 5;
  EXPECT_TRUE(wireOffset(square, 1.0, o).refused);
}

TEST(wire_offset_test, past_the_budget_of_exact_tests_the_offset_is_refused_after_bounded_work) {
  // A star of 2,000 thin spikes (radii 100 and 40): nearly every spike's box overlaps most others,
  // so the box tree's candidate pairs grow as the square of the spikes.
  std::vector<Vec2> pts;
  const int n = 2000;
  for (int i = 0; i < 2 * n; ++i) {
    const double a = std::numbers::pi * i / n, r = i % 2 ? 40.0 : 100.0;
    pts.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  const auto star = polygon(pts);
  const auto full = wireOffset(star, -0.001);
  ASSERT_FALSE(full.refused);
  EXPECT_FALSE(full.tooMuchWork);
  ASSERT_EQ(full.paths.size(), 1u);
  EXPECT_GT(full.tests, 500'000u);  // quadratic: 4,000 pieces, more than half a million tests
  WireOffsetOptions o;
  o.maxTests = full.tests / 2;
  const auto cut = wireOffset(star, -0.001, o);
  EXPECT_TRUE(cut.refused);
  EXPECT_TRUE(cut.tooMuchWork);
  EXPECT_TRUE(cut.paths.empty());
  EXPECT_EQ(cut.tests, o.maxTests + 1);  // it stopped at the first test past the budget
  o.maxTests = full.tests;               // exactly enough
  const auto enough = wireOffset(star, -0.001, o);
  EXPECT_FALSE(enough.refused);
  EXPECT_EQ(enough.paths.size(), 1u);
  EXPECT_EQ(enough.tests, full.tests);
}

}  // namespace
