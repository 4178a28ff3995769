// Work over independent indices on several cores: the per-move passes of a long program's checks.
//
// The library never asks the system how many threads to use: the program sets the count once
// (setWorkerCount) and every call here reads it. Until then one worker: everything runs in the
// calling thread.
#pragma once

#include <algorithm>
#include <cstddef>
#include <functional>
#include <iterator>

namespace kerf::geometry {

/// Threads parallelFor may use, the calling one included (at least 1).
unsigned workerCount();
/// Sets workerCount(), clamped to [1, 64]. Call it before any parallel work starts (the program
/// does, once).
void setWorkerCount(unsigned workers);

/// Calls body(begin, end) on contiguous pieces that together cover [0, n) once each, on up to
/// workerCount() threads: pieces of at least minChunk indices, a few a worker, each taken by the
/// first thread free. Below 2 x minChunk indices, with one worker, or from inside another
/// parallelFor's body, in the calling thread alone. Pieces run in no fixed order, so body must
/// write only what belongs to its own indices; then the result does not depend on the threads. An
/// exception from body is rethrown here (the first one) once every thread has finished.
void parallelFor(std::size_t n, std::size_t minChunk, const std::function<void(std::size_t, std::size_t)>& body);

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
