// The normalised ISO writer (docs/formats.md, "Writing ISO").
#pragma once

#include "kerf/converter/formats/writer.h"
#include "kerf/converter/interpret/machine.h"

#include <optional>

namespace kerf::converter {

struct IsoWriteOptions {
  const MachineProfile* target = nullptr;  ///< the controller's conventions (null: generic)
  std::optional<int> decimals;             ///< digits after the point (default: the target's, 3)
  bool offsetsApplied = false;             ///< G41/G42 marks are the controller's job (kerf cam), not a loss
  bool flattenSlivers = false;             ///< arcs bulging less than half the resolution as lines (kerf cam)
};

/// Absolute, mm, one move per block, I J incremental, in the target's conventions.
std::optional<EmitOutput> writeIso(const Toolpath& toolpath, const SourceFile* source, const IsoWriteOptions& options,
                                   Diagnostics& diags);

}  // namespace kerf::converter
