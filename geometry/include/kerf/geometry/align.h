// Placing one set of plane lines and arcs onto another by a rigid motion — a turn and a shift, with
// or without a mirror first: a drawing onto the edge a program cuts (issue 43, docs/drawing.md).
//
// The search starts from the principal axes of both sets (their second moments along their length):
// for each of the four turns that lay one set's axes on the other's, with and without the mirror,
// it refines by iterative closest points (Besl and McKay, "A method for registration of 3-D shapes",
// 1992): points along `from` are paired with their nearest points on `to`, and the turn and shift
// that best fit the pairs in least squares (closed form in the plane) are taken, until they stop
// moving. The best fit of the candidates is returned. It is a search, not a certificate: the caller
// measures the placed set against the other (geometry/deviation.h) before it believes the fit.
#pragma once

#include "kerf/geometry/segment.h"

#include <limits>

namespace kerf::geometry {

/// p -> turn(angle) * (mirror ? (-x, y) : (x, y)) + shift.
struct Placement {
  bool mirror = false;
  double angle = 0.0;  ///< radians, counter-clockwise
  Vec2 shift = Vec2::Zero();

  [[nodiscard]] Vec2 apply(const Vec2& p) const;
  /// The segment placed: an arc keeps its radius, and a mirror turns its direction round.
  [[nodiscard]] Segment apply(const Segment& s) const;
};

struct Alignment {
  Placement placement;
  double rms = std::numeric_limits<double>::infinity();  ///< mm: of the paired points' distances
};

struct AlignOptions {
  bool allowMirror = true;
  std::size_t samples = 2000;   ///< points along `from` (its elements' ends besides)
  std::size_t iterations = 40;  ///< the most refinements of one candidate
};

/// The placement of `from` that lays it best onto `to` (see the file comment). Either set empty:
/// the identity, with an infinite rms.
Alignment align(SegmentView from, SegmentView to, const AlignOptions& options = {});

}  // namespace kerf::geometry
