// What the reader fuzz entry points share: the pipeline run on the bytes as one input format, with
// budgets small enough for a fuzzer, and each output that Kerf can read again read again.
#pragma once

#include "kerf/converter/pipeline.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace kerf::fuzz {

/// The pipeline on `data` read as `format` (the name given to the source as well), with the move
/// and element budgets a fuzzer can afford.
converter::Pipeline readAs(const std::uint8_t* data, std::size_t size, converter::InputFormat format, const char* name);

/// Writes the toolpath as DXF, 3B and ISO and reads each back; a written file that its own reader
/// calls malformed (K0121, K0120) or that does not read at all is a bug: the process traps.
void writeAndReadBack(const converter::Pipeline& p);

}  // namespace kerf::fuzz
