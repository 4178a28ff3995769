// --workpiece Z0,Z1: the part a program's wire cuts between the work's faces, where its two planes
// are the machine's (a hot-wire foam cutter's carriages, docs/taper.md "The wire between its
// guides").
#pragma once

#include "kerf/converter/nc/diagnostics.h"
#include "kerf/converter/nc/source.h"
#include "kerf/converter/toolpath.h"

#include <cstddef>

namespace kerf::converter {

/// Replaces a taper toolpath's planes with the work's faces z0 < z1 (mm, in the planes' frame):
/// each move's wire cut at both heights. A section is one line or arc where it is exact (line with
/// line; arcs with the same sweep), else the move is split at common t into lines on both faces
/// within `tolerance` (mm), so that each move stays one position-paired patch. The program's planes
/// become the guides (unless guides are already known). The tables that name moves follow
/// (Toolpath::replaceMoves). False, with an error in diags and the toolpath unchanged, for a
/// program with no upper contour or unknown heights, faces not in order, or more than maxMoves moves.
bool cutBetweenFaces(Toolpath& toolpath, double z0, double z1, double tolerance, std::size_t maxMoves,
                     const SourceFile* source, Diagnostics& diags);

}  // namespace kerf::converter
