// The checks between the passes over one contour (docs/passes.md): every pass on the side of its
// programmed contour that the contour's first pass takes, offsets that shrink from the rough cut
// to the last skim, and what falls when (a punch cut free before its skims, a cut-off without a
// stop before it, where a die's slug falls).
#pragma once

#include "kerf/converter/nc/diagnostics.h"
#include "kerf/converter/structure/passes.h"
#include "kerf/converter/toolpath.h"

namespace kerf::converter {

/// Reports, for each contour of `structure` cut in more than one pass, what its passes do to one
/// another (K0610-K0614), each at the line of the move it concerns.
void checkPasses(const Structure& structure, const Toolpath& toolpath, const SourceFile* src, Diagnostics& diags);

}  // namespace kerf::converter
