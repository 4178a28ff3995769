// Doubles rounded to floats outwards with room to spare: the boxes the self-intersection sweeps
// keep (floats) are made with these.
#pragma once

#include <cmath>
#include <limits>

namespace kerf::geometry {

/// A float below v by more than one float step: at most the float next below the greatest float
/// not above v (what std::nextafter(floor-to-float(v), -infinity) gives), for any v that is not
/// NaN. v moved down by 2^-21 of itself and by the least normal float, then rounded to the nearest
/// float: two float steps below v are at most 2^-22 |v| (a float's step is at most 2^-23 of it) or
/// 2^-148 (steps below the normal floats), the rounding moves it at most half a step back, and
/// the sum's own rounding in doubles is 2^-29 of a float step. Past the floats' range it is the
/// float next below the largest one (-infinity below them all). A few float steps wider than the
/// tightest such float, and six instructions where the tightest takes twenty: a box is made of four.
inline float floatWellBelow(double v) {
  constexpr double kLowestTop = 0x1.fffffcp127;  // the float next below the largest float
  const double w = v - (std::abs(v) * 0x1p-21 + 0x1p-126);
  return static_cast<float>(w < kLowestTop ? w : kLowestTop);  // +infinity made a NaN: the top
}

/// A float above v by more than one float step (floatWellBelow mirrored).
inline float floatWellAbove(double v) { return -floatWellBelow(-v); }

}  // namespace kerf::geometry
