// The polar X/C writer for mill-turn lathes (docs/polar.md).
#pragma once

#include "kerf/converter/formats/writer.h"
#include "kerf/converter/nc/program.h"

#include <cstdint>
#include <optional>

namespace kerf::converter {

/// How X is written in polar X/C output.
enum class PolarX : std::uint8_t { Diameter, Radius };

struct PolarWriteOptions {
  std::optional<int> decimals;  ///< digits after the point (default 3; 5 for an inch program)
  PolarX polarX = PolarX::Diameter;
  double tolerance = 0.001;  ///< mm: how far the machine's X/C path may leave the programmed one
  /// Set for an ISO source (how its text splits into blocks): the output keeps each block's words
  /// that it does not convert, in place. Unset: the moves alone.
  std::optional<ParseOptions> sourceBlocks;
};

/// X diameter or radius, C in degrees unwrapped, each element subdivided so the machine's spiral
/// stays within the tolerance.
std::optional<EmitOutput> writePolar(const Toolpath& toolpath, const SourceFile* source,
                                     const PolarWriteOptions& options, Diagnostics& diags);

}  // namespace kerf::converter
