// Biarcs (geometry/biarc.h) against seed 003 (CAWEP), Table 1: the sine y = 10 sin(x/10), x in
// [0, 20], and the involute x = 10(cos t + t sin t), y = 10(sin t - t cos t), t in [0, 2], fitted
// within +-0.005 mm. CAWEP needs 16 and 14 nodes with span errors of 1.2-4.3 um. The error here is
// measured independently of the fitter: 20,000 samples of the true curve per span.
#include "kerf/geometry/biarc.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace kerf::geometry;

namespace {

/// The largest distance from the curve on [a, b] to the segments, 20,000 samples.
double measured(const ParametricCurve& c, double a, double b, const std::vector<Segment>& segs) {
  double worst = 0.0;
  for (int k = 0; k <= 20000; ++k) {
    const Vec2 p = c.point(a + (b - a) * k / 20000.0);
    double best = 1e300;
    for (const Segment& s : segs) best = std::min(best, s.distanceTo(p));
    worst = std::max(worst, best);
  }
  return worst;
}

void expectSmoothChain(const BiarcFit& fit, const ParametricCurve& c) {
  ASSERT_FALSE(fit.segments.empty());
  EXPECT_LE((fit.segments.front().start - c.point(c.t0)).norm(), 1e-12);
  EXPECT_LE((fit.segments.back().end - c.point(c.t1)).norm(), 1e-9);
  for (std::size_t i = 1; i < fit.segments.size(); ++i) {
    const Segment &a = fit.segments[i - 1], &b = fit.segments[i];
    EXPECT_LE((a.end - b.start).norm(), 1e-9) << i;
    // Tangent-continuous: the direction leaving equals the direction arriving.
    EXPECT_LE((a.tangentAt(1.0).normalized() - b.tangentAt(0.0).normalized()).norm(), 1e-6) << i;
  }
}

void report(const char* name, const BiarcFit& fit, const ParametricCurve& c, std::size_t cawepNodes) {
  std::printf("%s: %zu spans (CAWEP %zu), errors in um:", name, fit.spans.size(), cawepNodes);
  for (const BiarcSpan& s : fit.spans) {
    std::vector<Segment> segs(fit.segments.begin() + static_cast<std::ptrdiff_t>(s.first),
                              fit.segments.begin() + static_cast<std::ptrdiff_t>(s.first + s.count));
    std::printf(" %.1f", 1000 * measured(c, s.t0, s.t1, segs));
  }
  std::printf("\n");
}

ParametricCurve sine() {
  ParametricCurve c;
  c.point = [](double x) { return Vec2(x, 10 * std::sin(x / 10)); };
  c.derivative = [](double x) { return Vec2(1, std::cos(x / 10)); };
  c.t0 = 0;
  c.t1 = 20;
  return c;
}

ParametricCurve involute() {
  ParametricCurve c;
  c.point = [](double t) { return Vec2(10 * (std::cos(t) + t * std::sin(t)), 10 * (std::sin(t) - t * std::cos(t))); };
  c.derivative = [](double t) { return Vec2(10 * t * std::cos(t), 10 * t * std::sin(t)); };
  c.t0 = 0;
  c.t1 = 2;
  return c;
}

TEST(biarc_test, a_single_biarc_joins_its_ends_with_the_given_tangents) {
  const std::vector<Segment> b = biarc({0, 0}, {1, 0}, {10, 5}, {0, 1});
  ASSERT_FALSE(b.empty());
  EXPECT_LE((b.front().start - Vec2(0, 0)).norm(), 1e-12);
  EXPECT_LE((b.back().end - Vec2(10, 5)).norm(), 1e-9);
  EXPECT_LE((b.front().tangentAt(0).normalized() - Vec2(1, 0)).norm(), 1e-9);
  EXPECT_LE((b.back().tangentAt(1).normalized() - Vec2(0, 1)).norm(), 1e-9);
  EXPECT_TRUE(biarc({0, 0}, {-1, 0}, {10, 0}, {-1, 0}).empty());  // both tangents against the chord
}

TEST(biarc_test, a_circle_is_fitted_by_its_own_arcs) {
  ParametricCurve c;
  c.point = [](double t) { return Vec2(7 * std::cos(t), 7 * std::sin(t)); };
  c.t0 = 0;
  c.t1 = 3;
  const BiarcFit fit = fitBiarcs(c, {});
  EXPECT_EQ(fit.spans.size(), 1u);
  for (const Segment& s : fit.segments) EXPECT_NEAR(s.radius(), 7.0, 1e-6);
}

TEST(seed003_table1_test, sine_within_5um_in_no_more_spans_than_cawep) {
  const ParametricCurve c = sine();
  BiarcOptions o;
  o.tolerance = 0.005;
  const BiarcFit fit = fitBiarcs(c, o);
  ASSERT_TRUE(fit.ok);
  EXPECT_LE(fit.spans.size(), 16u);
  expectSmoothChain(fit, c);
  EXPECT_LE(measured(c, c.t0, c.t1, fit.segments), 0.005);
  report("sine", fit, c, 16);
}

TEST(seed003_table1_test, involute_within_5um_in_no_more_spans_than_cawep) {
  const ParametricCurve c = involute();
  BiarcOptions o;
  o.tolerance = 0.005;
  const BiarcFit fit = fitBiarcs(c, o);
  ASSERT_TRUE(fit.ok);
  EXPECT_LE(fit.spans.size(), 14u);
  expectSmoothChain(fit, c);
  EXPECT_LE(measured(c, c.t0, c.t1, fit.segments), 0.005);
  report("involute", fit, c, 14);
}

TEST(seed003_table1_test, spans_have_approximately_equal_error) {
  for (const ParametricCurve& c : {sine(), involute()}) {
    BiarcOptions o;
    o.tolerance = 0.005;
    const BiarcFit fit = fitBiarcs(c, o);
    ASSERT_GE(fit.spans.size(), 2u);
    double lo = 1e300, hi = 0;
    for (const BiarcSpan& s : fit.spans) {
      lo = std::min(lo, s.error);
      hi = std::max(hi, s.error);
    }
    EXPECT_LE(hi, 0.005);
    EXPECT_GE(lo, 0.5 * hi) << "the last span takes its share";
  }
}

TEST(fit_point_list_test, points_on_a_circle_give_arcs_near_the_circle) {
  std::vector<Vec2> pts;
  for (int i = 0; i <= 24; ++i) pts.emplace_back(20 * std::cos(i * 0.1), 20 * std::sin(i * 0.1));
  BiarcOptions o;
  o.tolerance = 0.001;
  const BiarcFit fit = fitPointList(pts, o);
  ASSERT_TRUE(fit.ok);
  for (const Vec2& p : pts) {
    double best = 1e300;
    for (const Segment& s : fit.segments) best = std::min(best, s.distanceTo(p));
    EXPECT_LE(best, 0.001 + 1e-9);  // the spline passes through its points; the arcs within 1 um of it
  }
  for (const Segment& s : fit.segments)
    for (double t : {0.25, 0.5, 0.75}) EXPECT_NEAR(s.pointAt(t).norm(), 20.0, 0.01);
}

TEST(biarc_test, the_walk_evaluates_the_curve_a_bounded_number_of_times_per_span) {
  // A rippled circle of 30 lobes needs hundreds of spans at 1 um: each step of the walk costs a
  // few trials from the span before, and equalise a few walks, not a bisection to the last bit of
  // the parameter per step and 24 walks (that took seconds for a 250-point DXF spline).
  long evaluations = 0;
  ParametricCurve c;
  c.point = [&evaluations](double t) {
    ++evaluations;
    const double r = 40 * (1 + 0.1 * std::sin(30 * t));
    return Vec2(r * std::cos(t), r * std::sin(t));
  };
  c.t0 = 0;
  c.t1 = 2 * M_PI;
  BiarcOptions o;
  o.tolerance = 0.001;
  const BiarcFit fit = fitBiarcs(c, o);
  ASSERT_TRUE(fit.ok);
  ASSERT_GE(fit.spans.size(), 100u);
  const double perSpan = static_cast<double>(evaluations) / static_cast<double>(fit.spans.size());
  std::printf("%zu spans, %ld evaluations, %.0f per span\n", fit.spans.size(), evaluations, perSpan);
  EXPECT_LE(perSpan, 4000.0);
  EXPECT_LE(fit.maxError, 0.001);
}

}  // namespace
