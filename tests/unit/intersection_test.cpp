#include "kerf/geometry/intersection.h"
#include "kerf/geometry/contour.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>
#include <string>
#include <tuple>

using namespace kerf::geometry;

namespace {

/// The same contacts: pairs, kinds and points. The results are sorted by pair; two contacts of one
/// pair (two crossing points) may come in either order.
bool samePairsAndPoints(const SelfIntersectionResult& a, const SelfIntersectionResult& b) {
  if (a.contacts.size() != b.contacts.size()) return false;
  auto sorted = [](std::vector<Contact> c) {
    std::sort(c.begin(), c.end(), [](const Contact& l, const Contact& r) {
      return std::tie(l.first, l.second, l.point.x(), l.point.y()) <
             std::tie(r.first, r.second, r.point.x(), r.point.y());
    });
    return c;
  };
  const std::vector<Contact> p = sorted(a.contacts), q = sorted(b.contacts);
  for (std::size_t k = 0; k < p.size(); ++k) {
    const Contact &x = p[k], &y = q[k];
    if (x.first != y.first || x.second != y.second || x.kind != y.kind || x.point != y.point ||
        x.adjacent != y.adjacent)
      return false;
  }
  return true;
}

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

TEST(intersect_test, crossing_lines) {
  const auto x = intersect(Segment::line({0, 0}, {10, 10}), Segment::line({0, 10}, {10, 0}), 1e-9);
  ASSERT_EQ(x.count, 1);
  EXPECT_NEAR((x.points[0] - Vec2(5, 5)).norm(), 0, 1e-12);
}

TEST(intersect_test, collinear_overlap) {
  const auto x = intersect(Segment::line({0, 0}, {10, 0}), Segment::line({4, 0}, {20, 0}), 1e-9);
  EXPECT_TRUE(x.overlap);
}

TEST(intersect_test, line_through_arc_twice) {
  const Segment arc = Segment::arc({10, 0}, {10, 0}, {0, 0}, ArcDirection::CounterClockwise);
  const auto x = intersect(Segment::line({-20, 0}, {20, 0}), arc, 1e-9);
  EXPECT_EQ(x.count, 2);
}

TEST(intersect_test, line_misses_the_arc_part_of_its_circle) {
  const Segment upper = Segment::arc({10, 0}, {-10, 0}, {0, 0}, ArcDirection::CounterClockwise);
  EXPECT_EQ(intersect(Segment::line({-20, -5}, {20, -5}), upper, 1e-9).count, 0);
  EXPECT_EQ(intersect(Segment::line({-20, 5}, {20, 5}), upper, 1e-9).count, 2);
}

TEST(intersect_test, arcs_on_the_same_circle_overlap) {
  const Segment a = Segment::arc({10, 0}, {0, 10}, {0, 0}, ArcDirection::CounterClockwise);
  const Segment b =
      Segment::arc({7.0710678118654755, 7.0710678118654755}, {-10, 0}, {0, 0}, ArcDirection::CounterClockwise);
  EXPECT_TRUE(intersect(a, b, 1e-9).overlap);
  const Segment c = Segment::arc({0, 10}, {-10, 0}, {0, 0}, ArcDirection::CounterClockwise);
  const auto touch = intersect(a, c, 1e-9);
  EXPECT_FALSE(touch.overlap);
  EXPECT_EQ(touch.count, 1);
}

// Two full circles on one circle share all of it: the stretch closes on itself and has one end.
// Its overlap contact lies on the circle; the second point, never set, was read uninitialised (a
// different "near" point from run to run: the fuzz target's two readings of one program disagreed).
TEST(intersect_test, two_full_circles_on_one_circle_overlap_with_one_end_on_the_circle) {
  const Segment a = Segment::arc({5, 0}, {5, 0}, {0, 0}, ArcDirection::CounterClockwise);
  const Segment b = Segment::arc({5, 0}, {5, 0}, {0, 0}, ArcDirection::Clockwise);
  const SegmentIntersection x = intersect(a, b, 1e-6);
  EXPECT_TRUE(x.overlap);
  ASSERT_EQ(x.count, 1);
  EXPECT_NEAR(x.points[0].norm(), 5.0, 1e-9);
  EXPECT_EQ(x.points[1], Vec2(0, 0));  // the point not set reads as zero
  // Through the checks' path: the circle cut twice, and the contact between the two turns.
  SelfIntersectionOptions o;
  o.closed = false;
  const auto r = findSelfIntersections(std::vector<Segment>{a, a}, o);
  ASSERT_FALSE(r.contacts.empty());
  for (const Contact& c : r.contacts) {
    EXPECT_EQ(c.kind, ContactKind::Overlap);
    EXPECT_NEAR(c.point.norm(), 5.0, 1e-9) << c.point.transpose();
  }
}

TEST(intersect_test, tangent_circles_touch_once) {
  const Segment a = Segment::arc({5, 0}, {5, 0}, {0, 0}, ArcDirection::CounterClockwise);
  const Segment b = Segment::arc({15, 0}, {15, 0}, {10, 0}, ArcDirection::CounterClockwise);
  EXPECT_EQ(intersect(a, b, 1e-9).count, 1);
}

TEST(self_intersection_test, square_is_clean) {
  const auto sq = polyline({{0, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0}});
  SelfIntersectionOptions o;
  o.closed = true;
  EXPECT_TRUE(findSelfIntersections(sq, o).contacts.empty());
  expectSameVerdictUnderMotions(sq, true);
}

TEST(self_intersection_test, bow_tie_crosses) {
  const auto bow = polyline({{0, 0}, {10, 10}, {10, 0}, {0, 10}, {0, 0}});
  SelfIntersectionOptions o;
  o.closed = true;
  const auto r = findSelfIntersections(bow, o);
  ASSERT_EQ(r.contacts.size(), 1u);
  EXPECT_EQ(r.contacts[0].kind, ContactKind::Crossing);
  EXPECT_NEAR((r.contacts[0].point - Vec2(5, 5)).norm(), 0, 1e-9);
  expectSameVerdictUnderMotions(bow, true);
}

TEST(self_intersection_test, near_miss_bow_is_clean) {
  // Same shape, but the second diagonal stops 0.01 mm short of the first.
  const auto open = polyline({{0, 0}, {10, 10}, {10, 0}, {5.01, 4.99}});
  EXPECT_TRUE(findSelfIntersections(open).contacts.empty());
}

TEST(self_intersection_test, t_junction_touches) {
  const auto t = polyline({{0, 0}, {10, 0}, {10, 5}, {5, 5}, {5, 0}});
  const auto r = findSelfIntersections(t);
  ASSERT_EQ(r.contacts.size(), 1u);
  EXPECT_EQ(r.contacts[0].kind, ContactKind::Touch);
  expectSameVerdictUnderMotions(t, false);
}

TEST(self_intersection_test, fold_back_overlaps_its_neighbour) {
  const auto f = polyline({{0, 0}, {10, 0}, {4, 0}});
  const auto r = findSelfIntersections(f);
  ASSERT_EQ(r.contacts.size(), 1u);
  EXPECT_EQ(r.contacts[0].kind, ContactKind::Overlap);
  EXPECT_TRUE(r.contacts[0].adjacent);
  expectSameVerdictUnderMotions(f, false);
}

TEST(self_intersection_test, lead_out_over_lead_in_is_an_opposite_overlap) {
  auto p = polyline({{-5, 0}, {0, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0}, {-5, 0}});
  const auto r = findSelfIntersections(p);
  ASSERT_EQ(r.contacts.size(), 1u);
  EXPECT_EQ(r.contacts[0].kind, ContactKind::Overlap);
  EXPECT_TRUE(r.contacts[0].opposite);
  EXPECT_EQ(r.contacts[0].first, 0u);
  EXPECT_EQ(r.contacts[0].second, 5u);
}

TEST(self_intersection_test, vertex_revisited_is_not_a_contact) {
  // A lead-in that ends where the loop starts and ends.
  auto p = polyline({{-5, 0}, {0, 0}, {10, 0}, {10, 10}, {0, 0}});
  EXPECT_TRUE(findSelfIntersections(p).contacts.empty());
}

TEST(self_intersection_test, arc_crossing_a_line) {
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

TEST(self_intersection_test, sweep_matches_all_pairs_on_random_paths) {
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

// Neighbours that are a line and an arc end to end at one point are most of the pairs a program's
// check tests, and classifyPair settles many of them without lineArc (meetOnlyAtVertex). Its answer
// must be lineArc's: random pairs, both orders, near tangent (down to 1e-10 rad off it) and far from
// the origin, arcs that end off their circle, at two tolerances, against intersect() classified as
// the sweep does.
TEST(self_intersection_test, a_line_and_an_arc_end_to_end_meet_where_intersect_says) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> unit(0, 1);
  auto logUniform = [&](double lo, double hi) { return lo * std::pow(hi / lo, unit(rng)); };
  auto dir = [](double a) { return Vec2(std::cos(a), std::sin(a)); };
  int withContacts = 0, checked = 0;
  for (const double tol : {1e-6, 1e-3}) {
    for (int trial = 0; trial < 4000; ++trial) {
      const Vec2 centre = unit(rng) < 0.5 ? Vec2(0, 0) : Vec2(logUniform(1, 1e4), -logUniform(1, 1e4));
      const double r = logUniform(1e-2, 1e3);
      const double at = 2 * kPi * unit(rng);
      const Vec2 v = centre + r * dir(at);
      const double sweep = (unit(rng) < 0.5 ? -1 : 1) * logUniform(1e-2, 2 * kPi - 1e-2);
      const ArcDirection arcDir = sweep < 0 ? ArcDirection::Clockwise : ArcDirection::CounterClockwise;
      // The line leaves v along the tangent turned by `off`: near 0 or pi it grazes the circle.
      const double off = (unit(rng) < 0.5 ? logUniform(1e-10, 1.0) : kPi * unit(rng)) * (unit(rng) < 0.5 ? -1 : 1) +
                         (unit(rng) < 0.5 ? 0.0 : kPi);
      const Vec2 other = v + logUniform(1e-2, 1e3) * dir(at + kPi / 2 + off);
      const bool lineFirst = trial % 2 == 0;
      std::vector<Segment> path;
      if (lineFirst) {
        path = {Segment::line(other, v), Segment::arc(v, centre + r * dir(at + sweep), centre, arcDir)};
      } else {
        // An arc may end off its circle (by its closing tolerance): then the line from its end
        // can meet it again just before, inside the circle or out.
        // Or it ends where the line, leaving outwards, meets the circle again about tol ahead:
        // the edge of what meetOnlyAtVertex settles.
        const double how = unit(rng);
        const Vec2 way = (other - v).normalized();
        Vec2 end = v;
        if (how < 0.3)
          end = v + logUniform(1e-9, 1e-2) * dir(2 * kPi * unit(rng));
        else if (how < 0.6 && way.dot(v - centre) > 0)
          end = v - tol * logUniform(0.5, 2.0) * way;
        path = {Segment::arc(centre + r * dir(at - sweep), end, centre, arcDir), Segment::line(end, other + (end - v))};
      }
      if (path[0].length() <= 10 * tol || path[1].length() <= 10 * tol) continue;
      SelfIntersectionOptions o;
      o.tolerance = tol;
      o.maxContacts = 100;
      const SelfIntersectionResult got = findSelfIntersections(path, o);
      // What classifyPair makes of intersect(): an overlap, or each point but the shared vertex
      // and ends that meet ends.
      const SegmentIntersection x = intersect(path[0], path[1], tol);
      std::vector<Vec2> expected;
      auto near = [&](const Vec2& p, const Vec2& q) { return (p - q).norm() <= tol; };
      if (x.overlap) {
        expected.push_back((x.points[0] + x.points[1]) / 2);
      } else {
        for (int k = 0; k < x.count; ++k) {
          const Vec2& p = x.points[k];
          if (near(p, path[0].end)) continue;
          const bool endA = near(p, path[0].start) || near(p, path[0].end);
          const bool endB = near(p, path[1].start) || near(p, path[1].end);
          if (!(endA && endB)) expected.push_back(p);
        }
      }
      ++checked;
      withContacts += !expected.empty();
      ASSERT_EQ(got.contacts.size(), expected.size()) << "tol " << tol << " trial " << trial;
      for (std::size_t k = 0; k < expected.size(); ++k)
        EXPECT_EQ(got.contacts[k].point, expected[k]) << "tol " << tol << " trial " << trial;
    }
  }
  EXPECT_GT(checked, 7000);
  EXPECT_GT(withContacts, 200);  // pairs that do meet elsewhere, near tangent among them
}

TEST(closure_test, loop_after_lead_in) {
  auto p = polyline({{-5, 0}, {0, 0}, {10, 0}, {10, 10}, {0, 0}});
  const ClosureReport c = analyseClosure(p, 1e-6);
  ASSERT_TRUE(c.loopFrom.has_value());
  EXPECT_EQ(*c.loopFrom, 1u);
  EXPECT_EQ(*c.loopTo, 3u);
  EXPECT_FALSE(c.endsAtStart);
}

TEST(closure_test, open_path_has_no_loop) {
  auto p = polyline({{0, 0}, {10, 0}, {10, 10}});
  const ClosureReport c = analyseClosure(p, 1e-6);
  EXPECT_FALSE(c.loopFrom.has_value());
  EXPECT_NEAR(c.gap, std::sqrt(200.0), 1e-12);
}

/// The first segment k whose end meets the start of a segment v <= k, and the earliest such v,
/// by comparing every pair: what analyseClosure must find.
std::pair<std::optional<std::size_t>, std::optional<std::size_t>> firstLoopOfEveryPair(const std::vector<Segment>& p,
                                                                                       double tol) {
  for (std::size_t k = 0; k < p.size(); ++k)
    for (std::size_t v = 0; v <= k; ++v)
      if ((p[v].start - p[k].end).norm() <= tol && !(v == k && p[k].length() <= tol)) return {v, k};
  return {};
}

TEST(closure_test, the_first_loop_is_the_one_a_search_of_every_pair_finds) {
  // Random walks on a coarse grid (so the walk comes back to where it was), jittered within the
  // tolerance, some of 20,000 steps: the table's answer (first end on an earlier start, earliest
  // such start) must be what comparing every pair gives.
  std::mt19937 rng(5);
  const double tol = 1e-3;
  std::uniform_int_distribution<int> step(-1, 1);
  std::uniform_real_distribution<double> jitter(-0.4 * tol, 0.4 * tol);
  int loops = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const int n = trial % 10 == 9 ? 20000 : 50 + trial * 20;
    const int spread = 2 + trial % 7;  // grid steps of 1..spread: small ones come back sooner
    std::vector<Segment> p;
    Vec2 at(0, 0);
    for (int k = 0; k < n; ++k) {
      Vec2 next = at + Vec2(step(rng) * (1 + trial % spread), step(rng) * (1 + k % spread));
      if (next == at) next.x() += 1;
      const Vec2 start = at + Vec2(jitter(rng), jitter(rng));
      p.push_back(Segment::line(start, next));
      at = next;
    }
    const auto [from, to] = firstLoopOfEveryPair(p, tol);
    const ClosureReport c = analyseClosure(p, tol);
    EXPECT_EQ(c.loopFrom, from) << "trial " << trial;
    EXPECT_EQ(c.loopTo, to) << "trial " << trial;
    loops += from.has_value();
  }
  EXPECT_GT(loops, 40);  // most walks do come back
}

TEST(closure_test, an_end_just_inside_or_outside_the_tolerance_of_a_start_anywhere_on_the_grid) {
  // Ends put at 0.999 or 1.001 tolerances from an earlier start, in every direction, at every
  // place relative to the table's cells (the points are spread over a few hundred cells): the
  // table's answer must be what comparing every pair gives.
  std::mt19937 rng(11);
  const double tol = 1e-3;
  std::uniform_real_distribution<double> where(-0.2, 0.2), turn(0, 2 * kPi), unit(0, 1);
  int loops = 0;
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Segment> p;
    const int n = 40;
    for (int k = 0; k < n; ++k) {
      const Vec2 start(where(rng), where(rng));
      Vec2 end(where(rng), where(rng));
      if (k > 0 && unit(rng) < 0.15) {  // near an earlier start, just inside or just outside
        std::uniform_int_distribution<int> pick(0, k - 1);
        const double r = tol * (unit(rng) < 0.5 ? 0.999 : 1.001), a = turn(rng);
        end = p[static_cast<std::size_t>(pick(rng))].start + r * Vec2(std::cos(a), std::sin(a));
      }
      p.push_back(Segment::line(start, end));
    }
    const auto [from, to] = firstLoopOfEveryPair(p, tol);
    const ClosureReport c = analyseClosure(p, tol);
    EXPECT_EQ(c.loopFrom, from) << "trial " << trial;
    EXPECT_EQ(c.loopTo, to) << "trial " << trial;
    loops += from.has_value();
  }
  EXPECT_GT(loops, 80);
  EXPECT_LT(loops, 200);
}

TEST(closure_test, full_circle_closes_itself) {
  std::vector<Segment> p = {Segment::arc({5, 0}, {5, 0}, {0, 0}, ArcDirection::Clockwise)};
  EXPECT_TRUE(analyseClosure(p, 1e-6).loopFrom.has_value());
}

}  // namespace

TEST(self_intersection_test, the_decision_sweep_agrees_with_the_box_sweep_on_random_simple_and_nearly_simple_polygons) {
  // Star-shaped polygons (sorted angles, random radii: simple), with arcs bulging from some edges,
  // axis-parallel and vertical edges, and in some trials one vertex pulled onto another edge
  // (a touch within the tolerance) or across it (a crossing). Whatever the case, the decision
  // sweep must find a contact exactly when the box sweep lists one. 3,000 trials; 120,000 with
  // seeds 12-15 passed once. Two faults were found this way: pieces through one point hiding a
  // touch from each other (the sweep now looks past them), and an arc's end recomputed from its
  // angle, a rounding away from its neighbour's start, which put the two in the wrong order.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0, 1);
  int clean = 0, touched = 0, touchesMissed = 0, dropsSame = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const int n = 5 + static_cast<int>(unit(rng) * 60);
    std::vector<double> angles(n);
    for (double& a : angles) a = unit(rng) * 2 * std::numbers::pi;
    std::sort(angles.begin(), angles.end());
    std::vector<Vec2> v;
    for (int i = 0; i < n; ++i) {
      const double r = 2 + 8 * unit(rng);
      Vec2 p(r * std::cos(angles[i]), r * std::sin(angles[i]));
      if (trial % 5 == 1 && i > 0) p.x() = v.back().x();  // a vertical edge
      if (trial % 5 == 2 && i > 0) p.y() = v.back().y();  // a horizontal one
      v.push_back(p);
    }
    if (trial % 7 == 3 && n > 6) {
      // Pull vertex 3 onto the edge 0-1 (within 5e-7 of it), or across it.
      const Vec2 a = v[0], b = v[1];
      const Vec2 onEdge = a + 0.5 * (b - a);
      const Vec2 normal = Vec2(-(b - a).y(), (b - a).x()).normalized();
      v[3] = onEdge + (trial % 2 ? 5e-7 : -0.01) * normal;
    }
    std::vector<Segment> path;
    for (int i = 0; i < n; ++i) {
      const Vec2 p = v[i], q = v[(i + 1) % n];
      if ((p - q).norm() < 1e-3) continue;
      if (i % 4 == 1) {
        const Vec2 mid = (p + q) / 2, nrm(-(q - p).y(), (q - p).x());
        // The centre two edge lengths to the left (or right) and the arc the short way round: a
        // gentle bulge; every ninth the long way round, which makes most of those polygons meet.
        const bool left = i % 8 == 1, longWay = i % 9 == 4;
        path.push_back(Segment::arc(p, q, mid + (left ? 2.0 : -2.0) * nrm,
                                    left != longWay ? ArcDirection::CounterClockwise : ArcDirection::Clockwise));
      } else {
        path.push_back(Segment::line(p, q));
      }
    }
    SelfIntersectionOptions both, boxes, dropping;
    both.closed = boxes.closed = dropping.closed = true;
    both.maxContacts = boxes.maxContacts = dropping.maxContacts = 100000;
    both.method = SweepMethod::Decision;
    boxes.method = SweepMethod::Boxes;
    dropping.method = SweepMethod::Dropping;
    const auto a = findSelfIntersections(path, both);
    const auto b = findSelfIntersections(path, boxes);
    // The dropping sweeps list only contacts the box sweep lists, and every one of them but a
    // touch within the tolerance that the sweeps never bring next to each other (docs/geometry.md:
    // a nearly vertical line passing within 1e-6 of an arc's end, twice in these trials).
    const auto d = findSelfIntersections(path, dropping);
    auto listedIn = [](const Contact& c, const SelfIntersectionResult& r) {
      return std::any_of(r.contacts.begin(), r.contacts.end(), [&](const Contact& e) {
        return e.first == c.first && e.second == c.second && e.point == c.point && e.kind == c.kind;
      });
    };
    for (const Contact& c : d.contacts) EXPECT_TRUE(listedIn(c, b)) << "trial " << trial;
    for (const Contact& c : b.contacts)
      if (!listedIn(c, d)) {
        EXPECT_EQ(c.kind, ContactKind::Touch) << "trial " << trial;
        ++touchesMissed;
      }
    dropsSame += samePairsAndPoints(d, b);
    std::string listed;
    for (const Contact& c : b.contacts) {
      listed += " (" + std::to_string(c.first) + ", " + std::to_string(c.second) + ") kind " +
                std::to_string(static_cast<int>(c.kind)) + " adjacent " + std::to_string(c.adjacent) + " at " +
                std::to_string(c.point.x()) + ", " + std::to_string(c.point.y()) + ";";
      for (std::size_t k : {c.first, c.second})
        listed += " [" + std::string(path[k].isArc() ? "arc" : "line") + " " + std::to_string(path[k].start.x()) + "," +
                  std::to_string(path[k].start.y()) + " -> " + std::to_string(path[k].end.x()) + "," +
                  std::to_string(path[k].end.y()) + "]";
    }
    ASSERT_EQ(a.contacts.size(), b.contacts.size()) << "trial " << trial << " of " << path.size() << ":" << listed;
    (b.contacts.empty() ? clean : touched)++;
  }
  // Both kinds occur, so the comparison means something either way.
  EXPECT_GT(clean, 80);
  EXPECT_GT(touched, 80);
  EXPECT_LE(touchesMissed, 2);
  EXPECT_GE(dropsSame, 2998);
}

TEST(self_intersection_test, arcs_that_start_or_end_on_their_circles_axes_are_decided_as_the_boxes_list) {
  // Walks on an integer grid of half circles over axis-aligned chords (their ends lie exactly on
  // their circle's axes, where the sweep cuts an arc into x-monotone pieces), quarter circles from
  // axis to axis, full circles (whose axes the sweep finds from the start's angle) and lines: the
  // decision sweep finds a contact exactly when the box sweep lists one.
  std::mt19937 rng(58);
  std::uniform_int_distribution<int> dir(0, 3), kind(0, 5), len(1, 3);
  const Vec2 steps[4] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  int clean = 0, touched = 0;
  for (int trial = 0; trial < 400; ++trial) {
    std::vector<Segment> path;
    Vec2 at(0, 0);
    for (int k = 0; k < 3 + trial % 7; ++k) {
      const int d = dir(rng), what = kind(rng);
      const Vec2 next = at + len(rng) * steps[d];
      const ArcDirection way = trial % 2 ? ArcDirection::Clockwise : ArcDirection::CounterClockwise;
      if (what == 0) {
        // A full circle: about a centre on an axis through where it stands, or off the axes.
        const Vec2 off = k % 2 ? Vec2(0.5 * steps[dir(rng)]) : Vec2(0.3 * steps[dir(rng)] + 0.4 * steps[(d + 1) % 4]);
        path.push_back(Segment::arc(at, at, at + off, way));
        continue;
      }
      if (what == 1) {  // a quarter circle about the corner of the step's square
        const Vec2 turn = steps[(d + 1) % 4], end = at + steps[d] + turn;
        path.push_back(Segment::arc(at, end, at + turn, way));
        at = end;
        continue;
      }
      path.push_back(what < 4 ? Segment::arc(at, next, (at + next) / 2, way) : Segment::line(at, next));
      at = next;
    }
    SelfIntersectionOptions decision, boxes;
    decision.maxContacts = boxes.maxContacts = 100000;
    decision.method = SweepMethod::Decision;
    boxes.method = SweepMethod::Boxes;
    const auto a = findSelfIntersections(path, decision);
    const auto b = findSelfIntersections(path, boxes);
    ASSERT_EQ(a.contacts.empty(), b.contacts.empty()) << "trial " << trial;
    (b.contacts.empty() ? clean : touched)++;
  }
  EXPECT_GT(clean, 40);  // both answers occur, so the comparison means something either way
  EXPECT_GT(touched, 40);
}

TEST(self_intersection_test, a_long_vertical_in_many_pieces_is_decided_with_few_tests) {
  // 100,000 collinear vertical pieces (all boxes at one x: the box sweep's budget runs out), closed
  // by two lines and an arc.
  std::vector<Segment> path;
  const int n = 100000;
  for (int i = 0; i < n; ++i) path.push_back(Segment::line({0, i * 0.01}, {0, (i + 1) * 0.01}));
  path.push_back(Segment::line({0, n * 0.01}, {5, n * 0.01}));
  path.push_back(Segment::arc({5, n * 0.01}, {5, 0}, {5, n * 0.005}, ArcDirection::Clockwise));
  path.push_back(Segment::line({5, 0}, {0, 0}));
  SelfIntersectionOptions o;
  o.closed = true;
  const auto r = findSelfIntersections(path, o);
  EXPECT_TRUE(r.contacts.empty());
  EXPECT_LT(r.candidatePairs, 4 * path.size());
}

TEST(self_intersection_test, a_star_of_long_spikes_is_decided_with_few_tests) {
  // 20,000 spikes: every box overlaps most others (the box sweep tests millions of pairs), while
  // the decision sweep tests each piece against its neighbours only.
  const int n = 20000;
  std::vector<Segment> path;
  std::vector<Vec2> v;
  for (int i = 0; i < 2 * n; ++i) {
    const double a = std::numbers::pi * i / n, r = i % 2 ? 1.0 : 100.0;
    v.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  for (std::size_t i = 0; i < v.size(); ++i) path.push_back(Segment::line(v[i], v[(i + 1) % v.size()]));
  SelfIntersectionOptions o;
  o.closed = true;
  o.method = SweepMethod::Decision;
  const auto r = findSelfIntersections(path, o);
  EXPECT_TRUE(r.contacts.empty());
  EXPECT_LT(r.candidatePairs, 4 * path.size());
  // The default gives the box sweep a linear budget, then decides the same way.
  o.method = SweepMethod::Auto;
  const auto a = findSelfIntersections(path, o);
  EXPECT_TRUE(a.contacts.empty());
  EXPECT_LT(a.candidatePairs, 4 * path.size());
}

namespace {

/// A closed star of n long spikes (radii 100 and 1), with the inner vertices 2k + 1 and 2k + 3
/// swapped at each k in `crossAt`: the two spikes between them then cross each other.
std::vector<Segment> starWithCrossings(int n, const std::vector<int>& crossAt) {
  std::vector<Vec2> v;
  for (int i = 0; i < 2 * n; ++i) {
    const double a = std::numbers::pi * i / n, r = i % 2 ? 1.0 : 100.0;
    v.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  for (const int k : crossAt) std::swap(v[2 * k + 1], v[2 * k + 3]);
  std::vector<Segment> path;
  for (std::size_t i = 0; i < v.size(); ++i) path.push_back(Segment::line(v[i], v[(i + 1) % v.size()]));
  return path;
}

/// The path's contacts by the box sweep (the reference) and by `method`, up to maxContacts.
std::pair<SelfIntersectionResult, SelfIntersectionResult> boxesAnd(const std::vector<Segment>& path, SweepMethod method,
                                                                   std::size_t maxContacts) {
  SelfIntersectionOptions o;
  o.closed = true;
  o.maxContacts = maxContacts;
  o.method = SweepMethod::Boxes;
  SelfIntersectionResult boxes = findSelfIntersections(path, o);
  o.method = method;
  return {std::move(boxes), findSelfIntersections(path, o)};
}

}  // namespace

TEST(self_intersection_test, a_star_with_a_few_crossings_lists_them_without_testing_every_box_pair) {
  // 10,000 spikes, crossing at five places far apart: the box sweep tests millions of pairs; the
  // decision sweep finds a contact, then drops the segments that touch and sweeps again.
  const std::vector<Segment> path = starWithCrossings(10000, {5, 2000, 4500, 7500, 9990});
  const auto [boxes, automatic] = boxesAnd(path, SweepMethod::Auto, 1000);
  ASSERT_GE(boxes.contacts.size(), 5u);
  EXPECT_FALSE(boxes.truncated);
  SelfIntersectionOptions o;
  o.closed = true;
  o.maxContacts = 1000;
  o.method = SweepMethod::Decision;
  for (const SelfIntersectionResult& r : {automatic, findSelfIntersections(path, o)}) {
    EXPECT_TRUE(samePairsAndPoints(r, boxes));
    EXPECT_FALSE(r.truncated);
    EXPECT_FALSE(r.loopKnown);  // the closure is then analysed apart
    EXPECT_LT(r.candidatePairs * 20, boxes.candidatePairs);
  }
}

TEST(self_intersection_test, a_chord_across_a_star_is_dropped_once_with_all_its_crossings) {
  // A line from spike 0's tip to the tip a quarter turn on, and back, crosses every spike between
  // twice: the pair first found has it, the longer one, dropped, and one pass lists its crossings.
  std::vector<Segment> path = starWithCrossings(4000, {});
  const Vec2 tip = path[0].start, quarter = path[2000].start;
  path.insert(path.begin() + 2000, Segment::line(quarter, tip));
  path.insert(path.begin() + 2001, Segment::line(tip, quarter));
  const auto [boxes, r] = boxesAnd(path, SweepMethod::Auto, 100000);
  ASSERT_GT(boxes.contacts.size(), 1000u);
  EXPECT_TRUE(samePairsAndPoints(r, boxes));
  EXPECT_FALSE(r.truncated);
}

TEST(self_intersection_test, past_max_contacts_the_dropping_sweep_stops_with_contacts_of_the_full_answer) {
  std::vector<int> at;
  for (int k = 10; k < 10000; k += 200) at.push_back(k);  // 50 crossings
  const std::vector<Segment> path = starWithCrossings(10000, at);
  const auto [full, all] = boxesAnd(path, SweepMethod::Auto, 100000);
  ASSERT_GE(full.contacts.size(), 50u);
  EXPECT_TRUE(samePairsAndPoints(all, full));
  SelfIntersectionOptions o;
  o.closed = true;
  o.maxContacts = 12;
  const auto cut = findSelfIntersections(path, o);
  EXPECT_TRUE(cut.truncated);
  ASSERT_EQ(cut.contacts.size(), 12u);
  for (const Contact& c : cut.contacts)
    EXPECT_TRUE(std::any_of(full.contacts.begin(), full.contacts.end(), [&](const Contact& f) {
      return f.first == c.first && f.second == c.second && f.point == c.point;
    }));
}

namespace {

/// A long line and a zigzag back over it: each of the zigzag's n pieces crosses the line once.
std::vector<Segment> zigzagOverLine(int n) {
  std::vector<Segment> path;
  path.push_back(Segment::line({0, 0}, {n + 1.0, 0}));
  Vec2 at(n + 1.0, 0);
  for (int i = 0; i <= n; ++i) {
    const Vec2 next(n - i + 0.5, i % 2 ? -1.0 : 1.0);
    path.push_back(Segment::line(at, next));
    at = next;
  }
  return path;
}

/// Runs f on `threads` workers (the count restored after).
template <typename F>
auto withThreads(unsigned threads, F&& f) {
  const kerf::test::ScopedThreads scoped(threads);
  return f();
}

bool sameContacts(const SelfIntersectionResult& a, const SelfIntersectionResult& b) {
  if (a.contacts.size() != b.contacts.size() || a.candidatePairs != b.candidatePairs || a.truncated != b.truncated)
    return false;
  for (std::size_t k = 0; k < a.contacts.size(); ++k) {
    const Contact &x = a.contacts[k], &y = b.contacts[k];
    if (x.first != y.first || x.second != y.second || x.kind != y.kind || x.point != y.point) return false;
  }
  return true;
}

}  // namespace

TEST(self_intersection_test, the_box_sweep_tests_its_pairs_in_batches_on_every_core_with_one_answer) {
  // 50,000 crossings: more pairs than one batch of the box sweep's exact tests.
  const int n = 50000;
  const std::vector<Segment> path = zigzagOverLine(n);
  SelfIntersectionOptions o;
  o.method = SweepMethod::Boxes;
  o.maxContacts = 1000000;
  const auto one = withThreads(1, [&] { return findSelfIntersections(path, o); });
  const auto four = withThreads(4, [&] { return findSelfIntersections(path, o); });
  ASSERT_EQ(one.contacts.size(), static_cast<std::size_t>(n));  // every zigzag piece but the first, which starts on it
  EXPECT_FALSE(one.truncated);
  EXPECT_TRUE(sameContacts(one, four));
  for (const Contact& c : one.contacts) EXPECT_EQ(c.first, 0u);

  // Stopped at maxContacts inside the second batch: the same contacts and pairs counted however
  // many threads test them, each one among the full answer's, and fewer pairs than in full.
  o.maxContacts = 40000;
  const auto cut1 = withThreads(1, [&] { return findSelfIntersections(path, o); });
  const auto cut4 = withThreads(4, [&] { return findSelfIntersections(path, o); });
  EXPECT_TRUE(cut1.truncated);
  ASSERT_EQ(cut1.contacts.size(), 40000u);
  EXPECT_TRUE(sameContacts(cut1, cut4));
  // The sweep meets the crossing pieces left to right, each testing the line and then its left
  // neighbour: the m-th contact is found by the (2m - 2)-th pair, past the first batch of 32,768.
  EXPECT_EQ(cut1.candidatePairs, 2u * 40000 - 2);
  std::vector<std::size_t> full;
  for (const Contact& c : one.contacts) full.push_back(c.second);
  for (const Contact& c : cut1.contacts) EXPECT_TRUE(std::binary_search(full.begin(), full.end(), c.second));
}

TEST(closure_test, the_first_loop_is_the_first_return_not_a_later_one) {
  // A path that comes back to an early vertex twice: the first return (k = 30,000, to v = 100) is
  // the loop reported, not the second (k = 60,000, to v = 5), which returns to an earlier vertex.
  std::vector<Segment> path;
  Vec2 at(0, 0);
  auto go = [&](const Vec2& to) {
    path.push_back(Segment::line(at, to));
    at = to;
  };
  for (int k = 0; k < 30000; ++k) go({k + 1.0, (k % 2) * 0.5});
  go(path[100].start);
  for (int k = 0; k < 30000; ++k) go({-k - 1.0, 10 + (k % 2) * 0.5});
  go(path[5].start);
  const ClosureReport r = analyseClosure(path, 1e-6);
  ASSERT_TRUE(r.loopFrom.has_value());
  EXPECT_EQ(*r.loopFrom, 100u);
  EXPECT_EQ(*r.loopTo, 30000u);
}

TEST(closure_test, the_sweep_finds_the_first_loop_the_closure_finds) {
  // Random walks of lines and arcs on a coarse grid (they come back to earlier vertices), ends
  // jittered within or just past the tolerance, some with a full circle or a zero-length move:
  // findLoop gives analyseClosure's answer (and comparing every pair's) whenever it says it knows
  // it. The box sweep knows it unless a segment is zero-length or it stopped at maxContacts; the
  // automatic method may also decide by the other sweep, which does not meet every pair.
  std::mt19937 rng(23);
  const double tol = 1e-3;
  std::uniform_int_distribution<int> step(-1, 1), kind(0, 9);
  std::uniform_real_distribution<double> unit(0, 1);
  int known = 0, loops = 0, unknownZero = 0, unknownCut = 0;
  for (int trial = 0; trial < 120; ++trial) {
    const int n = 20 + trial * 7;
    std::vector<Segment> p;
    Vec2 at(0, 0);
    bool zero = false;
    for (int k = 0; k < n; ++k) {
      Vec2 next = at + Vec2(step(rng) * (1 + trial % 3), step(rng) * (1 + k % 3));
      if (next == at) next.x() += 1;
      // Some ends fall near an earlier start: 0.999 or 1.001 tolerances from it.
      if (k > 2 && unit(rng) < 0.05) {
        std::uniform_int_distribution<int> pick(0, k - 1);
        const double r = tol * (unit(rng) < 0.5 ? 0.999 : 1.001), a = unit(rng) * 2 * kPi;
        next = p[static_cast<std::size_t>(pick(rng))].start + r * Vec2(std::cos(a), std::sin(a));
      }
      const int what = kind(rng);
      if (what == 0 && trial % 4 == 1) {  // a full circle through where it stands
        p.push_back(Segment::arc(at, at, at + Vec2(0.5, 0), ArcDirection::CounterClockwise));
        continue;
      }
      if (what == 1 && trial % 5 == 2) {  // a zero-length move
        p.push_back(Segment::line(at, at));
        zero = true;
        continue;
      }
      if (what < 5 && (next - at).norm() > 0.1) {  // a half circle over the chord
        p.push_back(Segment::arc(at, next, (at + next) / 2,
                                 what % 2 ? ArcDirection::Clockwise : ArcDirection::CounterClockwise));
      } else {
        p.push_back(Segment::line(at, next));
      }
      at = next;
    }
    // A jittered end may also fall within the tolerance of its own start.
    zero = zero || std::any_of(p.begin(), p.end(), [&](const Segment& s) { return s.length() <= tol; });
    SelfIntersectionOptions o;
    o.tolerance = tol;
    o.findLoop = true;
    o.maxContacts = trial % 6 == 5 ? 3 : 1000000;
    o.method = trial % 2 ? SweepMethod::Boxes : SweepMethod::Auto;
    const SelfIntersectionResult r = findSelfIntersections(p, o);
    const auto [from, to] = firstLoopOfEveryPair(p, tol);
    const ClosureReport c = analyseClosure(p, tol);
    ASSERT_EQ(c.loopFrom, from) << "trial " << trial;
    if (!r.loopKnown) {
      EXPECT_TRUE(zero || r.truncated || o.method == SweepMethod::Auto) << "trial " << trial;
      unknownZero += zero;
      unknownCut += !zero && r.truncated;
      continue;
    }
    ++known;
    EXPECT_FALSE(zero || r.truncated) << "trial " << trial;
    EXPECT_EQ(r.loopFrom, from) << "trial " << trial;
    EXPECT_EQ(r.loopTo, to) << "trial " << trial;
    loops += from.has_value();
  }
  EXPECT_GT(known, 60);
  EXPECT_GT(loops, 40);
  EXPECT_GT(unknownZero, 5);
  EXPECT_GT(unknownCut, 5);
  // Without findLoop nothing is said.
  const std::vector<Segment> square = polyline({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}});
  EXPECT_FALSE(findSelfIntersections(square).loopKnown);
  SelfIntersectionOptions o;
  o.findLoop = true;
  const SelfIntersectionResult r = findSelfIntersections(square, o);
  ASSERT_TRUE(r.loopKnown);
  EXPECT_EQ(r.loopFrom, std::optional<std::size_t>(0));
  EXPECT_EQ(r.loopTo, std::optional<std::size_t>(3));
}
