#include "kerf/geometry/intersection.h"
#include "kerf/geometry/contour.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <random>

using namespace kerf::geometry;

namespace {

std::vector<Segment> polyline(std::initializer_list<Vec2> pts) {
  std::vector<Segment> out;
  const Vec2* prev = nullptr;
  for (const Vec2& p : pts) {
    if (prev) out.push_back(Segment::line(*prev, p));
    prev = &p;
  }
  return out;
}

std::vector<Segment> moved(const std::vector<Segment>& path, const kerf::test::Motion2& m) {
  std::vector<Segment> out;
  for (const Segment& s : path) out.push_back(m.apply(s));
  return out;
}

std::vector<Segment> reversedPath(const std::vector<Segment>& path) {
  std::vector<Segment> out;
  for (auto it = path.rbegin(); it != path.rend(); ++it) out.push_back(it->reversed());
  return out;
}

/// The verdict of a path, as a multiset of contact kinds (indices change under reversal).
std::vector<ContactKind> kinds(const std::vector<Segment>& path, bool closed) {
  SelfIntersectionOptions o;
  o.closed = closed;
  std::vector<ContactKind> k;
  for (const Contact& c : findSelfIntersections(path, o).contacts) k.push_back(c.kind);
  std::sort(k.begin(), k.end());
  return k;
}

void expectSameVerdictUnderMotions(const std::vector<Segment>& path, bool closed) {
  const auto base = kinds(path, closed);
  for (const auto& m : kerf::test::someMotions()) EXPECT_EQ(kinds(moved(path, m), closed), base);
  EXPECT_EQ(kinds(reversedPath(path), closed), base);
}

TEST(intersect, crossing_lines) {
  const auto x = intersect(Segment::line({0, 0}, {10, 10}), Segment::line({0, 10}, {10, 0}), 1e-9);
  ASSERT_EQ(x.count, 1);
  EXPECT_NEAR((x.points[0] - Vec2(5, 5)).norm(), 0, 1e-12);
}

TEST(intersect, collinear_overlap) {
  const auto x = intersect(Segment::line({0, 0}, {10, 0}), Segment::line({4, 0}, {20, 0}), 1e-9);
  EXPECT_TRUE(x.overlap);
}

TEST(intersect, line_through_arc_twice) {
  const Segment arc = Segment::arc({10, 0}, {10, 0}, {0, 0}, ArcDirection::CounterClockwise);
  const auto x = intersect(Segment::line({-20, 0}, {20, 0}), arc, 1e-9);
  EXPECT_EQ(x.count, 2);
}

TEST(intersect, line_misses_the_arc_part_of_its_circle) {
  const Segment upper = Segment::arc({10, 0}, {-10, 0}, {0, 0}, ArcDirection::CounterClockwise);
  EXPECT_EQ(intersect(Segment::line({-20, -5}, {20, -5}), upper, 1e-9).count, 0);
  EXPECT_EQ(intersect(Segment::line({-20, 5}, {20, 5}), upper, 1e-9).count, 2);
}

TEST(intersect, arcs_on_the_same_circle_overlap) {
  const Segment a = Segment::arc({10, 0}, {0, 10}, {0, 0}, ArcDirection::CounterClockwise);
  const Segment b =
      Segment::arc({7.0710678118654755, 7.0710678118654755}, {-10, 0}, {0, 0}, ArcDirection::CounterClockwise);
  EXPECT_TRUE(intersect(a, b, 1e-9).overlap);
  const Segment c = Segment::arc({0, 10}, {-10, 0}, {0, 0}, ArcDirection::CounterClockwise);
  const auto touch = intersect(a, c, 1e-9);
  EXPECT_FALSE(touch.overlap);
  EXPECT_EQ(touch.count, 1);
}

TEST(intersect, tangent_circles_touch_once) {
  const Segment a = Segment::arc({5, 0}, {5, 0}, {0, 0}, ArcDirection::CounterClockwise);
  const Segment b = Segment::arc({15, 0}, {15, 0}, {10, 0}, ArcDirection::CounterClockwise);
  EXPECT_EQ(intersect(a, b, 1e-9).count, 1);
}

TEST(self_intersection, square_is_clean) {
  const auto sq = polyline({{0, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0}});
  SelfIntersectionOptions o;
  o.closed = true;
  EXPECT_TRUE(findSelfIntersections(sq, o).contacts.empty());
  expectSameVerdictUnderMotions(sq, true);
}

TEST(self_intersection, bow_tie_crosses) {
  const auto bow = polyline({{0, 0}, {10, 10}, {10, 0}, {0, 10}, {0, 0}});
  SelfIntersectionOptions o;
  o.closed = true;
  const auto r = findSelfIntersections(bow, o);
  ASSERT_EQ(r.contacts.size(), 1u);
  EXPECT_EQ(r.contacts[0].kind, ContactKind::Crossing);
  EXPECT_NEAR((r.contacts[0].point - Vec2(5, 5)).norm(), 0, 1e-9);
  expectSameVerdictUnderMotions(bow, true);
}

TEST(self_intersection, near_miss_bow_is_clean) {
  // Same shape, but the second diagonal stops 0.01 mm short of the first.
  const auto open = polyline({{0, 0}, {10, 10}, {10, 0}, {5.01, 4.99}});
  EXPECT_TRUE(findSelfIntersections(open).contacts.empty());
}

TEST(self_intersection, t_junction_touches) {
  const auto t = polyline({{0, 0}, {10, 0}, {10, 5}, {5, 5}, {5, 0}});
  const auto r = findSelfIntersections(t);
  ASSERT_EQ(r.contacts.size(), 1u);
  EXPECT_EQ(r.contacts[0].kind, ContactKind::Touch);
  expectSameVerdictUnderMotions(t, false);
}

TEST(self_intersection, fold_back_overlaps_its_neighbour) {
  const auto f = polyline({{0, 0}, {10, 0}, {4, 0}});
  const auto r = findSelfIntersections(f);
  ASSERT_EQ(r.contacts.size(), 1u);
  EXPECT_EQ(r.contacts[0].kind, ContactKind::Overlap);
  EXPECT_TRUE(r.contacts[0].adjacent);
  expectSameVerdictUnderMotions(f, false);
}

TEST(self_intersection, lead_out_over_lead_in_is_an_opposite_overlap) {
  auto p = polyline({{-5, 0}, {0, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0}, {-5, 0}});
  const auto r = findSelfIntersections(p);
  ASSERT_EQ(r.contacts.size(), 1u);
  EXPECT_EQ(r.contacts[0].kind, ContactKind::Overlap);
  EXPECT_TRUE(r.contacts[0].opposite);
  EXPECT_EQ(r.contacts[0].first, 0u);
  EXPECT_EQ(r.contacts[0].second, 5u);
}

TEST(self_intersection, vertex_revisited_is_not_a_contact) {
  // A lead-in that ends where the loop starts and ends.
  auto p = polyline({{-5, 0}, {0, 0}, {10, 0}, {10, 10}, {0, 0}});
  EXPECT_TRUE(findSelfIntersections(p).contacts.empty());
}

TEST(self_intersection, arc_crossing_a_line) {
  std::vector<Segment> p;
  p.push_back(Segment::line({0, 0}, {20, 0}));
  p.push_back(Segment::line({20, 0}, {20, 5}));
  // Clockwise from (20, 5) about (10, 5) goes down through (10, -5): it crosses y = 0 twice.
  p.push_back(Segment::arc({20, 5}, {0, 5}, {10, 5}, ArcDirection::Clockwise));
  const auto r = findSelfIntersections(p);
  ASSERT_FALSE(r.contacts.empty());
  EXPECT_EQ(r.contacts[0].kind, ContactKind::Crossing);
  expectSameVerdictUnderMotions(p, false);
}

TEST(self_intersection, sweep_matches_all_pairs_on_random_paths) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> step(-3, 3);
  for (int trial = 0; trial < 60; ++trial) {
    std::vector<Segment> path;
    Vec2 p(0, 0);
    for (int i = 0; i < 40; ++i) {
      const Vec2 q = p + Vec2(step(rng), step(rng));
      if (i % 3 == 2) {
        const Vec2 mid = (p + q) / 2, n(-(q - p).y(), (q - p).x());
        path.push_back(
            Segment::arc(p, q, mid + 0.3 * n, i % 2 ? ArcDirection::Clockwise : ArcDirection::CounterClockwise));
        // The arc starts at p by construction; its end is off that circle unless the centre is
        // equidistant, which mid + t n is.
      } else {
        path.push_back(Segment::line(p, q));
      }
      p = q;
    }
    SelfIntersectionOptions o;
    o.maxContacts = 100000;
    const auto fast = findSelfIntersections(path, o);
    // All pairs, brute force, through the same pair classification (boxes ignored).
    std::size_t brute = 0;
    for (std::size_t i = 0; i < path.size(); ++i)
      for (std::size_t j = i + 1; j < path.size(); ++j) {
        std::vector<Segment> two = {path[i], path[j]};
        // Classification needs the neighbour relation of the full path, so count raw meetings
        // of non-neighbours instead and compare with the sweep's non-neighbour contacts.
        if (j == i + 1) continue;
        const auto x = intersect(path[i], path[j], o.tolerance);
        if (x.overlap)
          ++brute;
        else
          for (int k = 0; k < x.count; ++k) {
            const bool endA = (x.points[k] - path[i].start).norm() <= o.tolerance ||
                              (x.points[k] - path[i].end).norm() <= o.tolerance;
            const bool endB = (x.points[k] - path[j].start).norm() <= o.tolerance ||
                              (x.points[k] - path[j].end).norm() <= o.tolerance;
            if (!(endA && endB)) ++brute;
          }
      }
    std::size_t sweepNonAdjacent = 0;
    for (const Contact& c : fast.contacts)
      if (!c.adjacent) ++sweepNonAdjacent;
    EXPECT_EQ(sweepNonAdjacent, brute) << "trial " << trial;
  }
}

TEST(closure, loop_after_lead_in) {
  auto p = polyline({{-5, 0}, {0, 0}, {10, 0}, {10, 10}, {0, 0}});
  const ClosureReport c = analyseClosure(p, 1e-6);
  ASSERT_TRUE(c.loopFrom.has_value());
  EXPECT_EQ(*c.loopFrom, 1u);
  EXPECT_EQ(*c.loopTo, 3u);
  EXPECT_FALSE(c.endsAtStart);
}

TEST(closure, open_path_has_no_loop) {
  auto p = polyline({{0, 0}, {10, 0}, {10, 10}});
  const ClosureReport c = analyseClosure(p, 1e-6);
  EXPECT_FALSE(c.loopFrom.has_value());
  EXPECT_NEAR(c.gap, std::sqrt(200.0), 1e-12);
}

TEST(closure, full_circle_closes_itself) {
  std::vector<Segment> p = {Segment::arc({5, 0}, {5, 0}, {0, 0}, ArcDirection::Clockwise)};
  EXPECT_TRUE(analyseClosure(p, 1e-6).loopFrom.has_value());
}

}  // namespace
