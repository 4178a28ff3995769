// How the report and the construction write a figure in a sentence: a length in mm and an angle in
// degrees, each to three decimals (one place, so that kerf explain and the pictures' labels agree).
#pragma once

#include "kerf/converter/nc/number_format.h"
#include "kerf/geometry/vec.h"

#include <string>

namespace kerf::converter::figures {

/// A length, mm, three decimals ("12.500").
inline std::string mm(double v) { return formatFixed(v, 3); }
/// An angle given in radians, written in degrees to three decimals.
inline std::string deg(double radians) { return formatFixed(radians * 180.0 / geometry::kPi, 3); }

}  // namespace kerf::converter::figures
