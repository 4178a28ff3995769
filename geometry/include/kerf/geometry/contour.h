// Whole-path measures: closure.
#pragma once

#include "kerf/geometry/segment.h"

#include <cstddef>
#include <optional>
#include <span>

namespace kerf::geometry {

struct ClosureReport {
  bool endsAtStart = false;             ///< last end within tol of first start
  std::optional<std::size_t> loopFrom;  ///< first segment of the first closed loop, if any
  std::optional<std::size_t> loopTo;    ///< the segment whose end closes that loop
  double gap = 0.0;                     ///< distance from last end to first start, mm
};

/// Does the path close a loop? The loop may start after a lead-in and be followed by a
/// lead-out: any segment end that returns to an earlier vertex (within tol) closes one.
ClosureReport analyseClosure(SegmentView path, double tol);

}  // namespace kerf::geometry
