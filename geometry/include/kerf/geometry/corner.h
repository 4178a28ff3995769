// Corners rounded or chamfered between two elements that meet: Fanuc's optional corner words
// (`,R r` and `,C c` on a G01/G02/G03 block) and a taper's rounded corner on each plane (the
// equal-radius and independent corner models, docs/taper.md).
//
// Exact for lines and arcs: the fillet's centre is where the two elements' offsets by r (towards
// the inside of the turn) meet, its tangent points are that centre's feet on the elements. Lengths
// in mm.
#pragma once

#include "kerf/geometry/segment.h"

#include <cstdint>

namespace kerf::geometry {

enum class CornerStatus : std::uint8_t {
  Ok,
  NotJoined,   ///< the second element does not start where the first ends
  Tangent,     ///< the elements meet tangent: there is no corner to round or chamfer
  Reversal,    ///< the second element turns straight back along the first
  DoesNotFit,  ///< the fillet or chamfer needs more of an element than it has (or no fillet of r touches both)
};

struct Corner {
  CornerStatus status = CornerStatus::NotJoined;
  Segment first;   ///< the first element, ending where the corner begins
  Segment corner;  ///< the fillet (an arc of radius r, turning as the corner turns) or the chamfer (a line)
  Segment second;  ///< the second element, starting where the corner ends
  /// Where the elements met: the corner the fillet or chamfer replaces.
  Vec2 sharp = Vec2::Zero();
};

/// The corner between a (ending at the corner) and b (starting there) rounded with radius r > 0.
/// Each element keeps more than `keep` mm of its length, or the status is DoesNotFit; a and b must
/// meet within `joinTolerance` mm.
Corner roundCorner(const Segment& a, const Segment& b, double r, double joinTolerance = 1e-6, double keep = 1e-6);

/// The corner between a and b cut by a chamfer from the point of a to the point of b each at the
/// straight distance c > 0 from the corner (for lines, c along each). The same statuses.
Corner chamferCorner(const Segment& a, const Segment& b, double c, double joinTolerance = 1e-6, double keep = 1e-6);

}  // namespace kerf::geometry
