// Work over independent indices on the machine's cores: the per-move measures of a long program.
#pragma once

#include <cstddef>
#include <functional>

namespace kerf::geometry {

/// Threads parallelFor uses, the calling one included: the hardware's, at most 16; the
/// environment variable KERF_THREADS (1 and up) overrides it, KERF_THREADS=1 runs serially.
unsigned workerCount();

/// Calls body(begin, end) on contiguous chunks that together cover [0, n) once each, on up to
/// workerCount() threads; below 2 x minChunk indices, or with one worker, in the calling thread
/// alone. Chunks run in no fixed order, so body must write only what belongs to its own indices;
/// then the result does not depend on the threads. An exception from body is rethrown here once
/// every thread has finished.
void parallelFor(std::size_t n, std::size_t minChunk, const std::function<void(std::size_t, std::size_t)>& body);

}  // namespace kerf::geometry
