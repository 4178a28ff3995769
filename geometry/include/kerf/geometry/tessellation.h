// Tessellation of segments into points, and the error it makes.
//
// Two ways to sample an arc (lines contribute only their end point, as in the seed paper):
//  - Step: the seed's fixed interpolation step k — consecutive points are k mm apart (chord
//    length), stepping from the start; the last chord is whatever remains, so it is <= k.
//  - Tolerance: the fewest equal chords whose sagitta (max distance between chord and arc) is
//    <= the tolerance.
//
// Error measures (docs/geometry.md defines them with formulas):
//  - maxDeviation: the largest sagitta of any chord, mm.
//  - meanRelativeError: the radial gap between chord and arc, divided by the radius, averaged
//    over the swept angle (closed form per chord; arc-length weighted over a path). This is our
//    precise reading of the quantity the seed plots in its Fig. 16.
#pragma once

#include "kerf/geometry/segment.h"

#include <cstddef>
#include <span>
#include <vector>

namespace kerf::geometry {

enum class SamplingMode : std::uint8_t { Step, Tolerance };

struct Sampling {
  SamplingMode mode = SamplingMode::Step;
  double value = 0.1;  ///< step k (mm) or tolerance (mm); > 0

  static Sampling step(double k) { return {SamplingMode::Step, k}; }
  static Sampling tolerance(double t) { return {SamplingMode::Tolerance, t}; }
};

struct ArcSampleStats {
  std::size_t points = 0;          ///< points after the start; the last one is the arc's end
  double maxDeviation = 0.0;       ///< mm
  double meanRelativeError = 0.0;  ///< dimensionless, averaged over the swept angle
};

/// Number of points sample() would emit for this arc (after its start). Lines give 1.
std::size_t sampleCount(const Segment& seg, const Sampling& sampling);

/// Samples one segment. Appends the points after the start to out (if not null); the last
/// point appended is seg.end exactly as programmed.
ArcSampleStats sample(const Segment& seg, const Sampling& sampling, std::vector<Vec2>* out);

/// Mean relative radial error of one chord that spans the angle `span` (radians, 0 < span <= pi)
/// of a circle: 1 - cos(span/2) * (2/span) * ln(tan(pi/4 + span/4)).
double chordMeanRelativeError(double span);

struct PathSampleStats {
  std::size_t points = 0;  ///< including the path's first start point
  std::size_t arcs = 0;
  double maxDeviation = 0.0;
  double meanRelativeError = 0.0;  ///< arc-length weighted over the arcs; 0 with no arcs
  double arcLength = 0.0;
};

/// Samples a path: its first start point, then every segment's points. Where a segment does not
/// start at the previous end (a jump), its start is emitted as well.
PathSampleStats samplePath(SegmentView path, const Sampling& sampling, std::vector<Vec2>* out);

/// samplePath a segment at a time, for a path not stored as one view (the cut moves among a
/// toolpath's rapids): the same figures, added in the same order.
class PathSampler {
 public:
  PathSampler(const Sampling& sampling, std::vector<Vec2>* out) : sampling_(sampling), out_(out) {}
  /// Samples the next segment; returns its length (Segment::length, bit for bit), which the
  /// sampler works out anyway for an arc.
  double add(const Segment& seg);
  /// Takes in the counts of a sampler (without points) that sampled the segments that follow
  /// these: the same counts as adding those segments here, but for the order of the sums. Its
  /// first start point is not counted again where it is this one's last end.
  void append(const PathSampler& later);
  [[nodiscard]] PathSampleStats stats() const;

 private:
  Sampling sampling_;
  std::vector<Vec2>* out_;
  PathSampleStats stats_;
  Vec2 first_{0, 0};
  Vec2 last_{0, 0};
  double weighted_ = 0.0;
};

/// Result of fitting the sampling to a controller's point capacity.
struct CapacityFit {
  bool fits = false;
  Sampling sampling;               ///< the finest sampling found whose output fits
  std::size_t points = 0;          ///< points at that sampling
  std::size_t fewestPossible = 0;  ///< points with every arc at its coarsest (half circles)
};

/// Finds the smallest step (or tolerance, by mode) whose output has at most maxPoints points.
/// The result is exact to 1e-9 relative: a step 1e-9 smaller would exceed the capacity.
CapacityFit fitToCapacity(std::span<const Segment> path, std::size_t maxPoints, SamplingMode mode);

/// The seed's angles for an arc sampled at step k, in its own convention: angles measured
/// clockwise from +X (formula (4): X = Xs + R cos(delta), Y = Ys - R sin(delta)).
struct SeedArcAngles {
  double alpha = 0.0;  ///< centre -> start
  double beta = 0.0;   ///< centre -> end (unwrapped so that delta runs from alpha to beta)
  double gamma = 0.0;  ///< angle step the chord k gives: 2 asin(k / 2R)
};
SeedArcAngles seedAngles(const Segment& arc, double k);

/// The seed's algorithm, as printed: delta starts at alpha and grows by gamma for G2 (falls for
/// G3) until it passes beta; each point by formula (4); the end point closes the arc. Used to
/// cross-check sample() and to show the working in `kerf explain`.
std::vector<Vec2> seedArcPoints(const Segment& arc, double k);

}  // namespace kerf::geometry
