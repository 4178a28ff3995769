// Biarcs: a smooth plane curve as tangent-continuous pairs of circular arcs (seed 003, CAWEP §2,
// docs/geometry.md).
//
// A span of the curve from P0 (unit tangent T0) to P1 (unit tangent T1) is replaced by two arcs
// that meet at a joint J with a common tangent: the first leaves P0 along T0, the second arrives at
// P1 along T1. Of the one-parameter family of such pairs Kerf takes the equal-distance one (the
// control points P0 + d T0 and P1 - d T1 at one distance d from their ends), which exists whenever
// the tangents do not both point against the chord. Consecutive biarcs share the curve's tangent at
// their node, so the fitted path is tangent-continuous everywhere: a controller cuts it without a
// corner.
//
// Nodes: CAWEP's "approximately equal error". From each node the next is the farthest parameter
// whose biarc stays within the tolerance, to within 1/64 of the span (found by bisection on the
// parameter, starting from twice the span before; the error is measured by sampling the true curve
// densely and taking each sample's distance to the two arcs). That gives (nearly) the fewest spans
// n the greedy walk allows; the walk is then repeated with a smaller target error, bisected to
// 1/16 of the tolerance while it still needs n spans and the last span's error is close to the
// others' — so the errors of all spans come out nearly equal and below the tolerance. Both
// precisions bound the work: a spline through 1,000 points is fitted in a bounded number of trials.
#pragma once

#include "kerf/geometry/segment.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace kerf::geometry {

/// A parametric plane curve on [t0, t1]: its point, and its derivative (nothing: central
/// differences of the point).
struct ParametricCurve {
  std::function<Vec2(double)> point;
  std::function<Vec2(double)> derivative;  ///< may be empty
  double t0 = 0.0;
  double t1 = 1.0;
};

/// The biarc from p0 (unit tangent u0) to p1 (unit tangent u1): one or two segments (an arc
/// whose chord leaves along the tangent degenerates to a line). Empty when no equal-distance
/// biarc exists (a tangent pointing back along the chord).
std::vector<Segment> biarc(const Vec2& p0, const Vec2& u0, const Vec2& p1, const Vec2& u1);

struct BiarcSpan {
  double t0 = 0.0, t1 = 0.0;  ///< the curve's parameters at the span's nodes
  double error = 0.0;         ///< mm: the largest sampled distance from the curve to the span's arcs
  std::size_t first = 0;      ///< index of its first segment in BiarcFit::segments
  std::size_t count = 0;      ///< its segments (2, or 1 where an arc is a line)
};

struct BiarcFit {
  std::vector<Segment> segments;
  std::vector<BiarcSpan> spans;
  double maxError = 0.0;  ///< mm, over every span
  bool ok = true;         ///< false: a span could not be fitted within the tolerance (a cusp, a corner)
  bool overBudget = false;
  /// fitPointList: the spline through the points swings out far beyond them (its control points
  /// lie more than ten times the points' extent outside their box): refused, nothing fitted.
  bool swings = false;
};

struct BiarcOptions {
  double tolerance = 0.001;  ///< mm, the largest distance of the arcs from the curve
  int samples = 64;          ///< samples of the curve per span when measuring the error
  bool equalise = true;      ///< CAWEP's approximately equal error (off, or past 1,000 spans: the greedy walk alone)
  std::size_t maxSpans = 100000;  ///< refuse past this many spans
  double minSpan = 1e-9;          ///< smallest parameter step: below it the curve has a corner
};

/// Fits the curve with biarcs within options.tolerance (see the file comment).
BiarcFit fitBiarcs(const ParametricCurve& curve, const BiarcOptions& options = {});

/// The most points fitPointList takes. Eigen's interpolation solves a dense system (O(n^3) time,
/// O(n^2) memory) and the biarc fit of the result grows with it (docs/performance.md), so the
/// readers refuse longer lists at their line.
constexpr std::size_t kMostFitPoints = 1000;

/// A smooth curve through points (an interpolating cubic B-spline, chord-length parameters:
/// Eigen's unsupported SplineFitting), fitted with biarcs: CAWEP's point lists. At least two
/// distinct points and at most kMostFitPoints (ok is false otherwise).
BiarcFit fitPointList(const std::vector<Vec2>& points, const BiarcOptions& options = {});

}  // namespace kerf::geometry
