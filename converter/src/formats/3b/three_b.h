// 3B geometry shared by the reader (read_3b.cpp) and the writer (write_3b.cpp): quadrant codes and
// the count J of an arc over every quadrant piece it crosses (docs/3b.md, FORMATS §4).
#pragma once

#include "kerf/geometry/vec.h"

#include <cstdint>

namespace kerf::converter::three_b {

/// The count axis: GX counts travel along x, GY along y.
enum class Axis : std::uint8_t { X, Y };

/// Signs of (x, y) in quadrant q = 1..4: (+,+), (-,+), (-,-), (+,-).
geometry::Vec2 quadrantSigns(int quadrant);

/// A line's Z (L1..L4) from its end point relative to its start (not both zero): on the axes +X L1,
/// +Y L2, -X L3, -Y L4; off them by quadrant.
int lineQuadrant(double dx, double dy);
/// A line's count axis: the larger component; at 45 degrees GY in quadrants 1 and 3, GX in 2 and 4.
Axis lineAxis(double dx, double dy);

/// An arc's Z quadrant from its start point relative to the centre. Counter-clockwise, a start on
/// an axis takes the quadrant it moves into (+X NR1, +Y NR2, -X NR3, -Y NR4); clockwise by
/// symmetry (+X SR4, +Y SR1, -X SR2, -Y SR3).
int arcQuadrant(double sx, double sy, bool counterClockwise);
/// An arc's count axis from its end point relative to the centre: |xe| > |ye| counts y (GY), else x.
Axis arcAxis(double ex, double ey);

/// The count of an arc: travel along `axis` from the start (angle a0, coordinate value at the
/// start `startValue`) over `sweep` radians (signed, counter-clockwise positive) on a circle of
/// radius r, ending at the coordinate value `endValue`. Between the two, the coordinate runs to ±r
/// at every extreme the arc passes.
double arcCount(double a0, double sweep, double r, Axis axis, double startValue, double endValue);

/// Where an arc's count ends: from the start point relative to the centre, turning in the given
/// direction on the circle through the start, until `count` has been travelled along `axis`.
/// Nothing (false) when the start is the centre, or the count is longer than one full circle (4 r)
/// by more than `slack`.
bool arcEnd(const geometry::Vec2& startRel, bool counterClockwise, Axis axis, double count, double slack,
            geometry::Vec2& endRel, double& sweep);

}  // namespace kerf::converter::three_b
