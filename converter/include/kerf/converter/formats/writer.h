// What every writer shares: the text it writes and how it says what it wrote, and where a cut path
// starts (--start-block). Each format's writer and its options are in its folder; the table of
// writers is emit.h.
#pragma once

#include "kerf/converter/check/summary.h"
#include "kerf/converter/nc/diagnostics.h"
#include "kerf/converter/toolpath.h"

#include <cstdint>
#include <string>

namespace kerf::converter {

struct EmitOutput {
  std::string text;
  std::string what;    ///< "412 points (bp95d profile)", "14 records"
  std::string detail;  ///< "; step k = 0.100000 mm, max deviation 0.000031 mm"
};

/// Starts a cut path at the cut move of `startLine`: a closed path is rotated to begin there; on an
/// open one the moves before it are left out (warning K0803). False, with an error, when no cut
/// move comes from that line. Every writer's --start-block.
bool startCutPathAt(const Toolpath& toolpath, CutPath& path, std::uint32_t startLine, const SourceFile* source,
                    Diagnostics& diags);

}  // namespace kerf::converter
