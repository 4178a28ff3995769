// Work over independent indices on the machine's cores: the per-move measures of a long program.
#pragma once

#include <algorithm>
#include <cstddef>
#include <functional>
#include <iterator>

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

/// parallelFor in pieces of at least minChunk indices, up to four a worker, each taken by the
/// first worker free: for work split finely enough, a worker whose core is shared (a piece of
/// runBesideWhenIdle's, another program on a shared machine) takes fewer pieces, and the call no
/// longer waits for the slower of fixed halves. Pieces run in no fixed order and on no fixed thread, so
/// body must write only what belongs to its own indices (as for parallelFor).
void parallelForBalanced(std::size_t n, std::size_t minChunk,
                         const std::function<void(std::size_t, std::size_t)>& body);

/// While one lives, parallelFor keeps its threads between calls instead of making and ending
/// them for each (a check makes a score of calls); they are made at the first call that needs
/// them, so a short program makes none. The commands open one around a program's
/// pipeline; the threads end with it, long before the process does (LeakSanitizer's tracer
/// crashed on threads kept to the end of a process). Scopes nest: the outermost keeps the threads.
class ParallelScope {
 public:
  ParallelScope();
  ~ParallelScope();
  ParallelScope(const ParallelScope&) = delete;
  ParallelScope& operator=(const ParallelScope&) = delete;

 private:
  bool owner_ = false;
};

/// Runs first and second at once, second on another thread, when there are two workers or more;
/// otherwise first, then second. The two must not write what the other reads. An exception from
/// either is rethrown here once both have finished (one of them, when both throw).
void parallelInvoke(const std::function<void()>& first, const std::function<void()>& second);

/// Runs main in the calling thread while the scope's kept threads (ParallelScope) take
/// piece(0) .. piece(pieces - 1) whenever no parallelFor needs them, one piece at a time, each to
/// its end; when main returns, the calling thread takes the pieces still left, and the call
/// returns once every piece has run. Work that must be done by the end of a stage, beside a stage
/// that needs every core for some of its time and one for the rest: the summary beside the
/// checks, whose passes over the moves want both cores and whose box sweep leaves one idle. A
/// parallelFor of main's waits for a helper at most the piece it is in. (A thread of its own beside
/// them took a core from those passes at ordinary priority; at the lowest (SCHED_IDLE) a helper
/// woken for main's parallelFor waited for the scheduler's next tick, up to 4 ms, behind it.)
/// piece must be safe to run for different pieces at once, on different threads; a parallelFor
/// inside it runs serially. Outside a scope, with one worker or one piece, main then the pieces,
/// here. An exception from main is rethrown here once the pieces running have ended (no more
/// start); from a piece, the first one, once every piece has run or stopped (no more start after it).
void runBesideWhenIdle(const std::function<void()>& main, std::size_t pieces,
                       const std::function<void(std::size_t)>& piece);

/// Sorts [first, last) by less: one chunk per worker sorted at once, then merged pairwise (in
/// place; std::inplace_merge takes a buffer when it can). Below minSize elements, or with one
/// worker, std::sort alone. Not stable, as std::sort is not: equal elements may come in any order.
template <typename It, typename Less>
void parallelSort(It first, It last, Less less, std::size_t minSize = 1 << 16) {
  const auto n = static_cast<std::size_t>(std::distance(first, last));
  const std::size_t chunks = std::min<std::size_t>(workerCount(), n / std::max<std::size_t>(minSize / 2, 1));
  if (chunks <= 1) {
    std::sort(first, last, less);
    return;
  }
  auto bound = [&](std::size_t c) { return first + static_cast<std::ptrdiff_t>(n * c / chunks); };
  parallelFor(chunks, 1, [&](std::size_t b, std::size_t e) {
    for (std::size_t c = b; c < e; ++c) std::sort(bound(c), bound(c + 1), less);
  });
  for (std::size_t width = 1; width < chunks; width *= 2)
    for (std::size_t c = 0; c + width < chunks; c += 2 * width)
      std::inplace_merge(bound(c), bound(c + width), bound(std::min(c + 2 * width, chunks)), less);
}

}  // namespace kerf::geometry
