#include "kerf/geometry/tessellation.h"
#include "kerf/geometry/arc.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace kerf::geometry;

namespace {

Segment sectorArc() {  // the seed's test part: 90 degrees of radius 40 mm
  return Segment::arc({40, 0}, {0, 40}, {0, 0}, ArcDirection::CounterClockwise);
}

// The seed's experiment: k = 0.1, 0.5, 1 mm on the R40 quarter circle. Closed form: the step
// angle is gamma = 2 asin(k / 2R); there are floor(sweep / gamma) full chords and one shorter
// chord for the rest; the largest deviation is the sagitta of a full chord, R (1 - cos(gamma/2)),
// which equals R - sqrt(R^2 - k^2/4).
TEST(tessellation_test, seed_sector_experiment_matches_closed_form) {
  const double r = 40.0, sweep = kPi / 2;
  struct Case {
    double k;
    std::size_t points;  // after the start, by hand: ceil(sweep / gamma)
  };
  // gamma(0.1) = 0.00250000065 rad -> 628.3 chords; gamma(0.5) -> 125.66; gamma(1) -> 62.83
  for (const Case c : {Case{0.1, 629}, Case{0.5, 126}, Case{1.0, 63}}) {
    SCOPED_TRACE(c.k);
    const double gamma = 2 * std::asin(c.k / (2 * r));
    const std::size_t expected = static_cast<std::size_t>(std::ceil(sweep / gamma));
    EXPECT_EQ(expected, c.points);
    std::vector<Vec2> pts;
    const ArcSampleStats st = sample(sectorArc(), Sampling::step(c.k), &pts);
    EXPECT_EQ(st.points, c.points);
    EXPECT_EQ(pts.size(), c.points);
    EXPECT_NEAR(st.maxDeviation, r - std::sqrt(r * r - c.k * c.k / 4), 1e-9);
    // Every full chord is exactly k long; the last one is shorter.
    Vec2 prev(40, 0);
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
      EXPECT_NEAR((pts[i] - prev).norm(), c.k, 1e-9);
      prev = pts[i];
    }
    EXPECT_LE((pts.back() - prev).norm(), c.k + 1e-12);
    EXPECT_EQ(pts.back(), Vec2(0, 40));
  }
}

TEST(tessellation_test, seed_algorithm_gives_the_same_points) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> coord(-20, 20), ks(0.05, 3);
  for (int i = 0; i < 300; ++i) {
    const Vec2 c(coord(rng), coord(rng));
    const double r = 1 + std::abs(coord(rng));
    const double a0 = coord(rng), a1 = coord(rng);
    const ArcDirection dir = i % 2 ? ArcDirection::Clockwise : ArcDirection::CounterClockwise;
    const Segment s = Segment::arc(c + r * direction(a0), c + r * direction(a1), c, dir);
    const double k = ks(rng);
    std::vector<Vec2> ours;
    sample(s, Sampling::step(k), &ours);
    const std::vector<Vec2> seed = seedArcPoints(s, k);
    ASSERT_EQ(ours.size(), seed.size()) << "arc " << i;
    for (std::size_t j = 0; j < ours.size(); ++j) EXPECT_NEAR((ours[j] - seed[j]).norm(), 0, 1e-9);
  }
}

TEST(tessellation_test, tolerance_mode_keeps_every_chord_within_tolerance) {
  for (double tol : {0.001, 0.01, 0.1}) {
    for (double r : {0.5, 5.0, 80.0}) {
      const Segment s = Segment::arc({r, 0}, {r, 0}, {0, 0}, ArcDirection::Clockwise);  // full circle
      std::vector<Vec2> pts;
      const ArcSampleStats st = sample(s, Sampling::tolerance(tol), &pts);
      EXPECT_LE(st.maxDeviation, tol + 1e-12);
      // One chord fewer would exceed the tolerance (the fewest chords).
      const double span = 2 * kPi / static_cast<double>(st.points - 1 == 0 ? 1 : st.points - 1);
      if (st.points > 2) {
        EXPECT_GT(r * (1 - std::cos(span / 2)), tol);
      }
      // Chord midpoints lie within tol of the circle, and points on it.
      Vec2 prev(r, 0);
      for (const Vec2& p : pts) {
        EXPECT_NEAR(p.norm(), r, 1e-9);
        EXPECT_LE(r - ((p + prev) / 2).norm(), tol + 1e-12);
        prev = p;
      }
    }
  }
}

TEST(tessellation_test, mean_relative_error_closed_form_matches_numeric_average) {
  for (double span : {0.001, 0.05, 0.5, 1.0, kPi / 2, kPi}) {
    // Average of 1 - cos(span/2)/cos(phi) over phi in [-span/2, span/2], by the midpoint rule.
    const int n = 200000;
    double sum = 0;
    for (int i = 0; i < n; ++i) {
      const double phi = -span / 2 + (i + 0.5) * span / n;
      sum += 1 - std::cos(span / 2) / std::cos(phi);
    }
    EXPECT_NEAR(chordMeanRelativeError(span), sum / n, 1e-9) << span;
  }
}

TEST(tessellation_test, mean_relative_error_is_continuous_and_positive_for_tiny_chords) {
  // Either side of the switch to the series, and far below it, where the closed form cancelled.
  EXPECT_NEAR(chordMeanRelativeError(1e-2 * (1 - 1e-12)), chordMeanRelativeError(1e-2), 1e-12);
  for (double span : {1e-11, 1e-8, 1e-5, 1e-3}) {
    EXPECT_GT(chordMeanRelativeError(span), 0.0) << span;
    EXPECT_NEAR(chordMeanRelativeError(span) / (span * span / 12), 1.0, 1e-6) << span;
  }
}

TEST(tessellation_test, mean_relative_error_series_and_closed_form_agree_with_forty_digits) {
  // 1 - cos(s/2) (2/s) ln tan(pi/4 + s/4), by mpmath at 40 digits (mp.dps = 40), to 20: below
  // 0.25 rad the summary takes the series, from there the closed form. The series is exact to a
  // few units of the last place; the closed form loses digits to cancellation as the span shrinks.
  const struct {
    double span, value, relative;
  } cases[] = {{0.001, 8.3333333333333382937e-8, 1e-15},     {0.01, 8.3333333333829367835e-6, 1e-15},
               {0.1, 0.00083333338296408405839, 1e-15},      {0.2, 0.0033333365150104774283, 1e-15},
               {0.2499999, 0.0052083413190174814303, 1e-15}, {0.25, 0.0052083454857125143723, 1e-13},
               {0.3, 0.0075000363426345947138, 1e-13}};
  for (const auto& c : cases) EXPECT_NEAR(chordMeanRelativeError(c.span), c.value, c.value * c.relative) << c.span;
}

TEST(tessellation_test, sagitta_of_short_chords_agrees_with_forty_digits) {
  // A half-circle arc of radius 2 cut into chords of 0.2 mm in step mode: its last chord is
  // shorter than a step, so both the full chords' sagitta (from the sine of the half angle) and
  // the last one's (a series below 0.25 rad) are taken. The full chord's angle is
  // 2 asin(0.05); 2 (1 - cos(asin 0.05)) by mpmath at 40 digits is 0.002501564456182108422.
  const Segment arc = Segment::arc({2, 0}, {-2, 0}, {0, 0}, ArcDirection::CounterClockwise);
  const ArcSampleStats st = sample(arc, Sampling{SamplingMode::Step, 0.2}, nullptr);
  EXPECT_NEAR(st.maxDeviation, 0.002501564456182108422, 2e-18);
  // A chord of 0.1 rad on a circle of radius 1 (tolerance mode gives equal chords): sagitta
  // 1 - cos(0.05) = 0.0012497396050337534371 (mpmath, 40 digits).
  const Segment tenth = Segment::arc({1, 0}, {std::cos(0.1), std::sin(0.1)}, {0, 0}, ArcDirection::CounterClockwise);
  const ArcSampleStats one = sample(tenth, Sampling{SamplingMode::Tolerance, 0.01}, nullptr);
  EXPECT_EQ(one.points, 1u);
  EXPECT_NEAR(one.maxDeviation, 0.0012497396050337534371, 2e-18);
}

TEST(tessellation_test, lines_add_only_their_end_point) {
  const std::vector<Segment> path = {Segment::line({0, 0}, {10, 0}), Segment::line({10, 0}, {10, 10})};
  std::vector<Vec2> pts;
  const PathSampleStats st = samplePath(path, Sampling::step(0.1), &pts);
  EXPECT_EQ(st.points, 3u);
  EXPECT_EQ(st.arcs, 0u);
  ASSERT_EQ(pts.size(), 3u);
}

TEST(tessellation_test, metamorphic_rigid_motion_keeps_counts_and_errors) {
  const Vec2 c(0.5, 3);
  const Segment s = Segment::arc(c + 3.2 * direction(0.3), c + 3.2 * direction(2.4), c, ArcDirection::Clockwise);
  const ArcSampleStats base = sample(s, Sampling::step(0.2), nullptr);
  for (const auto& m : kerf::test::someMotions()) {
    const ArcSampleStats moved = sample(m.apply(s), Sampling::step(0.2), nullptr);
    EXPECT_EQ(moved.points, base.points);
    EXPECT_NEAR(moved.maxDeviation, base.maxDeviation, 1e-12);
    EXPECT_NEAR(moved.meanRelativeError, base.meanRelativeError, 1e-12);
  }
  const ArcSampleStats rev = sample(s.reversed(), Sampling::step(0.2), nullptr);
  EXPECT_EQ(rev.points, base.points);
  EXPECT_NEAR(rev.maxDeviation, base.maxDeviation, 1e-12);
}

TEST(tessellation_test, fit_to_capacity_never_exceeds_and_is_the_finest) {
  std::vector<Segment> path;
  path.push_back(Segment::line({-5, 0}, {0, 0}));
  path.push_back(Segment::line({0, 0}, {40, 0}));
  path.push_back(Segment::arc({40, 0}, {0, 40}, {0, 0}, ArcDirection::CounterClockwise));
  path.push_back(Segment::line({0, 40}, {0, 0}));
  path.push_back(Segment::arc({0, 0}, {0, 0}, {-3, 0}, ArcDirection::Clockwise));
  for (SamplingMode mode : {SamplingMode::Step, SamplingMode::Tolerance}) {
    for (std::size_t cap : {9u, 10u, 17u, 50u, 333u, 5000u}) {
      const CapacityFit fit = fitToCapacity(path, cap, mode);
      ASSERT_TRUE(fit.fits) << cap;
      EXPECT_LE(fit.points, cap);
      EXPECT_EQ(samplePath(path, fit.sampling, nullptr).points, fit.points);
      // The finest that fits: a step 1e-6 finer no longer does (the count may jump past cap).
      const Sampling finer{mode, fit.sampling.value * (1 - 1e-6)};
      EXPECT_GT(samplePath(path, finer, nullptr).points, cap) << cap;
    }
    const CapacityFit impossible = fitToCapacity(path, 5, mode);
    EXPECT_FALSE(impossible.fits);
    EXPECT_GT(impossible.fewestPossible, 5u);
  }
}

}  // namespace

TEST(tessellation_test, samplers_of_consecutive_stretches_append_to_the_whole_paths_counts) {
  // Lines and arcs with a jump now and then (a start that is not the last end counts a point):
  // split anywhere, including at a jump, the appended samplers count what one sampler does.
  std::mt19937 rng(7);
  std::vector<Segment> path;
  Vec2 at(0, 0);
  for (int k = 0; k < 300; ++k) {
    if (k % 37 == 5) at += Vec2(3, 0);  // a jump
    const Vec2 to = at + Vec2(1 + rng() % 5, static_cast<double>(rng() % 7) - 3);
    if (k % 2)
      path.push_back(
          Segment::arc(at, to, (at + to) / 2, k % 4 == 1 ? ArcDirection::Clockwise : ArcDirection::CounterClockwise));
    else
      path.push_back(Segment::line(at, to));
    at = to;
  }
  const Sampling sampling{SamplingMode::Step, 0.3};
  const PathSampleStats whole = samplePath(path, sampling, nullptr);
  for (std::size_t cut : {std::size_t{1}, std::size_t{5}, std::size_t{42}, std::size_t{190}, std::size_t{299}}) {
    PathSampler first(sampling, nullptr), second(sampling, nullptr), joined(sampling, nullptr);
    for (std::size_t k = 0; k < path.size(); ++k) (k < cut ? first : second).add(path[k]);
    joined.append(first);
    joined.append(second);
    joined.append(PathSampler(sampling, nullptr));  // an empty stretch changes nothing
    const PathSampleStats got = joined.stats();
    EXPECT_EQ(got.points, whole.points) << cut;
    EXPECT_EQ(got.arcs, whole.arcs) << cut;
    EXPECT_EQ(got.maxDeviation, whole.maxDeviation) << cut;
    EXPECT_NEAR(got.arcLength, whole.arcLength, 1e-9 * whole.arcLength) << cut;
    EXPECT_NEAR(got.meanRelativeError, whole.meanRelativeError, 1e-12) << cut;
  }
}
