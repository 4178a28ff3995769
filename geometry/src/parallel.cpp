#include "kerf/geometry/parallel.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace kerf::geometry {
namespace {

std::atomic<unsigned> workers{1};
/// True in a thread while it runs a parallelFor's body: a call from inside runs serially, so the
/// threads never multiply.
thread_local bool insideParallelFor = false;

}  // namespace

unsigned workerCount() { return workers.load(std::memory_order_relaxed); }

void setWorkerCount(unsigned count) { workers.store(std::clamp(count, 1u, 64u), std::memory_order_relaxed); }

void parallelFor(std::size_t n, std::size_t minChunk, const std::function<void(std::size_t, std::size_t)>& body) {
  minChunk = std::max<std::size_t>(minChunk, 1);
  const std::size_t threads = std::min<std::size_t>(workerCount(), n / minChunk);
  if (threads <= 1 || n < 2 * minChunk || insideParallelFor) {
    if (n > 0) body(0, n);
    return;
  }
  // A few pieces a thread, taken in turn: a thread whose core is busy elsewhere takes fewer.
  const std::size_t pieces = std::min(n / minChunk, threads * 4);
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failureLock;
  auto work = [&] {
    insideParallelFor = true;
    for (std::size_t p; (p = next.fetch_add(1, std::memory_order_relaxed)) < pieces;) {
      try {
        body(n * p / pieces, n * (p + 1) / pieces);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(failureLock);
        if (!failure) failure = std::current_exception();
        next.store(pieces, std::memory_order_relaxed);  // no piece starts after a failure
      }
    }
    insideParallelFor = false;
  };
  std::vector<std::thread> helpers;
  helpers.reserve(threads - 1);
  for (std::size_t t = 1; t < threads; ++t) helpers.emplace_back(work);
  work();
  for (std::thread& t : helpers) t.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace kerf::geometry
