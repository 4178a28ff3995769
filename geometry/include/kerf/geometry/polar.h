// Polar coordinates of the face plane of a mill-turn lathe (seed 002, FORMATS §5, docs/polar.md):
// the tool at radius r and table angle C (degrees) is the point r (cos C, sin C). C is unwrapped:
// of the values congruent mod 360 the one nearest the previous C.
#pragma once

#include "kerf/geometry/segment.h"
#include "kerf/geometry/vec.h"

#include <cstddef>
#include <vector>

namespace kerf::geometry {

struct PolarPoint {
  double radius = 0.0;  ///< mm
  double c = 0.0;       ///< degrees, unwrapped
};

/// The angle (degrees) congruent with `degrees` mod 360 nearest `previous`.
double unwrapDegrees(double degrees, double previous);

/// The polar point of p, its C unwrapped against `previousC`.
PolarPoint toPolar(const Vec2& p, double previousC);
/// The face-plane point of a polar one.
Vec2 fromPolar(const PolarPoint& q);

/// The largest distance from the machine's path between two polar points (linear in r and C: a
/// spiral in the face plane) to a segment, sampled at `samples` inner points.
double spiralDeviation(const PolarPoint& a, const PolarPoint& b, const Segment& s, int samples = 16);

struct PolarSubdivision {
  /// A segment that starts at the centre leaves it at the angle of its tangent: the table turns
  /// there first (X 0, C that angle), then X moves. Written before `points` when set.
  bool leadTurn = false;
  PolarPoint lead;
  std::vector<PolarPoint> points;  ///< after the segment's start: the end of each piece
  double maxDeviation = 0.0;       ///< mm, of the spirals from the segment
  bool throughCentre = false;      ///< the segment passes the centre, where C is undefined
  bool overBudget = false;         ///< more pieces than the budget allowed
};

/// Points along s such that the machine's spiral between neighbours stays within `tolerance` of
/// s. Pieces are bisected until they fit, so they are denser near the centre, where C turns
/// fastest; no piece turns C by more than 45 degrees or sweeps more than 90 degrees of an arc. `startC` is the C of
/// s.start; at most `budget` points are made. A segment whose inside comes closer to the centre than `centreGap` passes
/// through it (C undefined); one that starts or ends there does not.
PolarSubdivision subdivideForPolar(const Segment& s, double startC, double tolerance, std::size_t budget,
                                   double centreGap = 1e-6);

struct SpiralPieces {
  std::vector<Segment> pieces;  ///< lines and arcs, in order, from the first point to the last
  double maxDeviation = 0.0;    ///< mm, of the spiral from the pieces (sampled)
  bool overBudget = false;      ///< the spiral turns so far that it needs more than the budget
};

/// The machine's path between two polar points as the mill-turn reader draws it: X and C move
/// linearly together, a spiral r(u) = ra + u (rb - ra), C(u) = ca + u (cb - ca) in the face plane.
/// Each piece is the arc through the spiral's points at its start, middle and end (a line where
/// they are collinear), bisected until the spiral stays within `tolerance` of it (sampled at 9
/// inner points); no piece turns C more than 45 degrees. Constant r gives arcs about the centre,
/// exactly. At least ceil(|cb - ca| / 45) pieces are needed: over `budget` it says so before
/// making any.
SpiralPieces spiralAsArcs(const PolarPoint& a, const PolarPoint& b, double tolerance, std::size_t budget);

}  // namespace kerf::geometry
