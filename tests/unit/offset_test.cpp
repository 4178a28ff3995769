// Exact offsets of line/arc chains (geometry/offset.h).
#include "kerf/geometry/offset.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

using kerf::geometry::ArcDirection;
using kerf::geometry::offsetChain;
using kerf::geometry::OffsetChainOptions;
using kerf::geometry::OffsetProblem;
using kerf::geometry::offsetSegment;
using kerf::geometry::Segment;
using kerf::geometry::Vec2;

/// Distance from p to the carrier of s (infinite line or full circle).
double carrierDistance(const Segment& s, const Vec2& p) {
  if (s.isArc()) return std::abs((p - s.centre).norm() - s.radius());
  const Vec2 d = (s.end - s.start).normalized();
  return std::abs(kerf::geometry::cross(d, p - s.start));
}

TEST(offset_test, line_moves_left_by_the_distance) {
  const auto o = offsetSegment(Segment::line({0, 0}, {10, 0}), 2.0);
  ASSERT_TRUE(o);
  EXPECT_NEAR(o->start.y(), 2.0, 1e-15);
  EXPECT_NEAR(o->end.y(), 2.0, 1e-15);
  const auto r = offsetSegment(Segment::line({0, 0}, {10, 0}), -2.0);
  EXPECT_NEAR(r->start.y(), -2.0, 1e-15);
}

TEST(offset_test, arcs_stay_concentric_and_collapse_at_their_radius) {
  const Segment ccw = Segment::arc({5, 0}, {0, 5}, {0, 0}, ArcDirection::CounterClockwise);
  EXPECT_NEAR(offsetSegment(ccw, 1.0)->radius(), 4.0, 1e-15);  // left of CCW is the centre
  EXPECT_NEAR(offsetSegment(ccw, -1.0)->radius(), 6.0, 1e-15);
  EXPECT_EQ(offsetSegment(ccw, 1.0)->centre, ccw.centre);
  EXPECT_FALSE(offsetSegment(ccw, 5.0).has_value());   // radius 0: collapsed
  EXPECT_TRUE(offsetSegment(ccw, 4.999).has_value());  // near miss
  const Segment cw = ccw.reversed();
  EXPECT_NEAR(offsetSegment(cw, 1.0)->radius(), 6.0, 1e-15);
}

TEST(offset_test, sharp_corners_meet_at_the_offset_lines_intersection) {
  // Square, counter-clockwise, offset inwards by 1: corners at (1,1), (9,1), ...
  const std::vector<Segment> sq = {Segment::line({0, 0}, {10, 0}), Segment::line({10, 0}, {10, 10}),
                                   Segment::line({10, 10}, {0, 10}), Segment::line({0, 10}, {0, 0})};
  OffsetChainOptions opt;
  opt.closed = true;
  const auto r = offsetChain(sq, std::vector<double>(4, 1.0), opt);
  EXPECT_TRUE(r.issues.empty());
  ASSERT_EQ(r.segments.size(), 4u);
  EXPECT_NEAR((r.segments[0].start - Vec2(1, 1)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((r.segments[1].start - Vec2(9, 1)).norm(), 0.0, 1e-12);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR((r.segments[i].end - r.segments[(i + 1) % 4].start).norm(), 0, 1e-12);
}

TEST(offset_test, every_corner_lies_on_both_neighbour_carriers_under_rigid_motions) {
  // A punch outline with line-arc, arc-line and line-line corners, offset by 0.7.
  const std::vector<Segment> base = {
      Segment::line({0, -10}, {7, -10}), Segment::arc({7, -10}, {10, -7}, {7, -7}, ArcDirection::CounterClockwise),
      Segment::line({10, -7}, {10, 7}), Segment::line({10, 7}, {-10, 12}), Segment::line({-10, 12}, {0, -10})};
  for (const auto& m : kerf::test::someMotions()) {
    std::vector<Segment> chain;
    for (const Segment& s : base) chain.push_back(m.apply(s));
    const double d = m.mirror ? -0.7 : 0.7;  // a mirror turns left into right
    OffsetChainOptions opt;
    opt.closed = true;
    const auto r = offsetChain(chain, std::vector<double>(chain.size(), d), opt);
    ASSERT_TRUE(r.issues.empty());
    for (std::size_t i = 0; i < chain.size(); ++i) {
      const auto carrier = offsetSegment(chain[i], d);
      EXPECT_LT(carrierDistance(*carrier, r.segments[i].start), 1e-9);
      EXPECT_LT(carrierDistance(*carrier, r.segments[i].end), 1e-9);
      EXPECT_LT((r.segments[i].end - r.segments[(i + 1) % chain.size()].start).norm(), 1e-12);
    }
  }
}

TEST(offset_test, anchored_ends_stay_on_the_programmed_points) {
  const std::vector<Segment> chain = {Segment::line({0, -5}, {0, 0}), Segment::line({0, 0}, {10, 0}),
                                      Segment::line({10, 0}, {10, -5})};
  OffsetChainOptions opt;
  opt.anchorStart = opt.anchorEnd = true;
  const auto r = offsetChain(chain, std::vector<double>(3, 1.0), opt);
  EXPECT_EQ(r.segments.front().start, Vec2(0, -5));
  EXPECT_EQ(r.segments.back().end, Vec2(10, -5));
  EXPECT_NEAR((r.segments[1].start - Vec2(-1, 1)).norm(), 0, 1e-12);
}

TEST(offset_test, a_tab_narrower_than_twice_the_offset_is_swallowed) {
  // A 2 mm tab's end: offsets of its sides (inwards by 1.2 each) cross before reaching it.
  const std::vector<Segment> tab = {Segment::line({0, -1}, {5, -1}), Segment::line({5, -1}, {5, 1}),
                                    Segment::line({5, 1}, {0, 1})};
  const auto bad = offsetChain(tab, std::vector<double>(3, 1.2));
  ASSERT_EQ(bad.issues.size(), 1u);
  EXPECT_EQ(bad.issues[0].problem, OffsetProblem::Reversed);
  EXPECT_EQ(bad.issues[0].index, 1u);
  EXPECT_TRUE(offsetChain(tab, std::vector<double>(3, 0.99)).issues.empty());  // near miss
}

TEST(offset_test, a_collapsed_corner_arc_becomes_the_sharp_corner) {
  const std::vector<Segment> corner = {Segment::line({0, -10}, {8, -10}),
                                       Segment::arc({8, -10}, {10, -8}, {8, -8}, ArcDirection::CounterClockwise),
                                       Segment::line({10, -8}, {10, 0})};
  const auto r = offsetChain(corner, std::vector<double>(3, 3.0));
  ASSERT_EQ(r.issues.size(), 1u);
  EXPECT_EQ(r.issues[0].problem, OffsetProblem::Collapsed);
  EXPECT_NEAR((r.segments[1].start - Vec2(7, -7)).norm(), 0, 1e-12);
  EXPECT_NEAR(r.segments[1].length(), 0, 1e-12);
  EXPECT_NEAR((r.segments[0].end - Vec2(7, -7)).norm(), 0, 1e-12);
}

TEST(offset_test, parallel_lines_with_different_distances_have_no_corner) {
  const std::vector<Segment> straight = {Segment::line({0, 0}, {5, 0}), Segment::line({5, 0}, {10, 0})};
  const auto r = offsetChain(straight, std::vector<double>{1.0, 2.0});
  ASSERT_EQ(r.issues.size(), 1u);
  EXPECT_EQ(r.issues[0].problem, OffsetProblem::NoCorner);
  EXPECT_TRUE(offsetChain(straight, std::vector<double>{1.0, 1.0}).issues.empty());
}

}  // namespace
