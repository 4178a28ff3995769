// Numbers as NC text: the one formatter of every writer, report and message (fixed decimals, as a
// controller reads them); the parser (program.h) is its inverse.
#pragma once

#include "kerf/geometry/vec.h"

#include <string>

namespace kerf::converter {

/// Fixed-decimal text of v, rounded to nearest, never "-0.000"; whole for any finite v (up to 1e308)
/// and decimals up to 60, "inf" or "nan" for those.
std::string formatFixed(double v, int decimals);

/// "(x, y)" with formatFixed's digits, for messages.
std::string formatPoint(const geometry::Vec2& p, int decimals = 3);

}  // namespace kerf::converter
