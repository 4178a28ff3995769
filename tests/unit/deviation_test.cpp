// The farthest distance from a segment to a set of segments (geometry/deviation.h), against cases
// worked by hand and against brute force.
#include "kerf/geometry/deviation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace kerf::geometry;

namespace {

const double kQuarter = std::acos(-1.0) / 4;

TEST(deviation_test, a_set_is_no_distance_from_its_own_elements) {
  const std::vector<Segment> set{Segment::line({0, 0}, {10, 0}),
                                 Segment::arc({10, 0}, {0, 10}, {0, 0}, ArcDirection::CounterClockwise),
                                 Segment::arc({0, 10}, {-3, 7}, {0, 7}, ArcDirection::CounterClockwise)};
  const DeviationSet near(set);
  for (const Segment& s : set) EXPECT_LE(farthestFrom(s, near).distance, near.chordDeviation() + 1e-4);
}

TEST(deviation_test, parallel_lines_are_their_spacing_apart) {
  const std::vector<Segment> set{Segment::line({0, 1}, {10, 1})};
  const Farthest f = farthestFrom(Segment::line({0, 0}, {10, 0}), DeviationSet(set));
  EXPECT_NEAR(f.distance, 1.0, 1e-12);
}

TEST(deviation_test, an_arc_is_its_sagitta_from_its_chord) {
  // A semicircle of radius 10 over its diameter: the farthest point is the top, 10 mm up; a
  // quarter circle over its chord: the sagitta r (1 - cos 45 degrees).
  const std::vector<Segment> chord{Segment::line({-10, 0}, {10, 0})};
  const Farthest half =
      farthestFrom(Segment::arc({10, 0}, {-10, 0}, {0, 0}, ArcDirection::CounterClockwise), DeviationSet(chord));
  EXPECT_NEAR(half.distance, 10.0, 1e-4);
  EXPECT_NEAR((half.at - Vec2(0, 10)).norm(), 0.0, 0.1);
  const std::vector<Segment> quarterChord{Segment::line({10, 0}, {0, 10})};
  const Farthest quarter =
      farthestFrom(Segment::arc({10, 0}, {0, 10}, {0, 0}, ArcDirection::CounterClockwise), DeviationSet(quarterChord));
  EXPECT_NEAR(quarter.distance, 10.0 * (1.0 - std::cos(kQuarter)), 1e-4);
  // The other way: the chord against the arc, whose farthest point is the chord's ends' neighbour.
  const std::vector<Segment> arc{Segment::arc({10, 0}, {0, 10}, {0, 0}, ArcDirection::CounterClockwise)};
  const Farthest back = farthestFrom(quarterChord[0], DeviationSet(arc));
  EXPECT_NEAR(back.distance, 10.0 * (1.0 - std::cos(kQuarter)), 1e-4);
}

TEST(deviation_test, a_gap_in_the_set_is_found_between_probes) {
  // The ends of the element lie on the set; its middle is 1 mm from the nearest end of a gap.
  const std::vector<Segment> set{Segment::line({0, 0}, {4, 0}), Segment::line({6, 0}, {10, 0})};
  const Farthest f = farthestFrom(Segment::line({0, 0}, {10, 0}), DeviationSet(set));
  EXPECT_NEAR(f.distance, 1.0, 1e-4);
  EXPECT_NEAR(f.at.x(), 5.0, 1e-3);
}

TEST(deviation_test, a_radius_typed_wrong_is_its_difference_at_the_middle) {
  // R10 drawn, R10.2 cut between the same end points: the arcs part most at their middles.
  const Vec2 a(10, 0), b(0, 10);
  const Segment drawn = Segment::arc(a, b, {0, 0}, ArcDirection::CounterClockwise);
  // The centre of the R10.2 arc through a and b, on the line y = x, nearer the arc's inside.
  const double c = 0.5 * (10 - std::sqrt(2 * 10.2 * 10.2 - 100));
  const Segment cut = Segment::arc(a, b, {c, c}, ArcDirection::CounterClockwise);
  const double want = std::abs(((cut.pointAt(0.5) - Vec2(0, 0)).norm()) - 10.0);
  EXPECT_NEAR(farthestFrom(drawn, DeviationSet(std::vector<Segment>{cut})).distance, want, 2e-4);
  EXPECT_NEAR(farthestFrom(cut, DeviationSet(std::vector<Segment>{drawn})).distance, want, 2e-4);
}

TEST(deviation_test, the_grid_finds_the_nearest_chord_as_brute_force_does) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-50, 50);
  std::vector<Segment> set;
  for (int i = 0; i < 300; ++i) {
    const Vec2 a(u(rng), u(rng));
    set.push_back(i % 3 == 0 ? Segment::arc(a + Vec2(2, 0), a + Vec2(0, 2), a, ArcDirection::CounterClockwise)
                             : Segment::line(a, a + Vec2(u(rng), u(rng)) * 0.05));
  }
  const DeviationSet near(set);
  for (int k = 0; k < 2000; ++k) {
    const Vec2 p(u(rng) * 1.5, u(rng) * 1.5);  // some outside the grid
    double best = 1e300;
    for (const Segment& s : set) best = std::min(best, s.distanceTo(p));
    EXPECT_NEAR(near.nearest(p).distance, best, near.chordDeviation() + 1e-12) << p.transpose();
  }
}

}  // namespace
