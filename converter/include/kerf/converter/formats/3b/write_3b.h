// The 3B and 4B writers (docs/3b.md).
#pragma once

#include "kerf/converter/formats/writer.h"

#include <optional>
#include <string>

namespace kerf::converter {

struct ThreeBWriteOptions {
  bool compact = false;                    ///< `B9900B0B9900GXL1` instead of `B9900 B0 B9900 GX L1`
  std::string end = "DD";                  ///< the last line ("" for none)
  std::optional<std::uint32_t> startLine;  ///< begin at the cut move of this source line
};

/// 3B: records from rounded absolute positions, so the program ends exactly where the source ends;
/// an arc whose rounded ends do not share a circle gets the nearest µm centre that fits.
std::optional<EmitOutput> writeThreeB(const Toolpath& toolpath, const SourceFile* source,
                                      const ThreeBWriteOptions& options, Diagnostics& diags);
/// 4B: `±B x B y B J B R G D|DD Z`, a layout marked [unsure].
std::optional<EmitOutput> writeFourB(const Toolpath& toolpath, const SourceFile* source,
                                     const ThreeBWriteOptions& options, Diagnostics& diags);

}  // namespace kerf::converter
