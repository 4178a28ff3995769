#include "kerf/geometry/parallel.h"

#include <algorithm>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace kerf::geometry {

unsigned workerCount() {
  if (const char* env = std::getenv("KERF_THREADS")) {
    char* end = nullptr;
    const long v = std::strtol(env, &end, 10);
    if (end != env && *end == '\0' && v >= 1) return static_cast<unsigned>(std::min(v, 256L));
  }
  return std::clamp(std::thread::hardware_concurrency(), 1u, 16u);
}

void parallelFor(std::size_t n, std::size_t minChunk, const std::function<void(std::size_t, std::size_t)>& body) {
  const std::size_t chunk = std::max<std::size_t>(minChunk, 1);
  const std::size_t workers = std::min<std::size_t>(workerCount(), n / chunk);
  if (workers <= 1) {
    if (n > 0) body(0, n);
    return;
  }
  // Contiguous, nearly equal ranges: one per worker, the calling thread taking the first.
  std::exception_ptr failure;
  std::mutex failureMutex;
  auto run = [&](std::size_t w) {
    const std::size_t begin = n * w / workers, end = n * (w + 1) / workers;
    try {
      body(begin, end);
    } catch (...) {
      const std::lock_guard<std::mutex> lock(failureMutex);
      if (!failure) failure = std::current_exception();
    }
  };
  std::vector<std::thread> threads;
  threads.reserve(workers - 1);
  try {
    for (std::size_t w = 1; w < workers; ++w) threads.emplace_back(run, w);
  } catch (...) {  // no thread to be had: what was not started runs here
    for (std::size_t w = threads.size() + 1; w < workers; ++w) run(w);
  }
  run(0);
  for (std::thread& t : threads) t.join();
  if (failure) std::rethrow_exception(failure);
}

void parallelInvoke(const std::function<void()>& first, const std::function<void()>& second) {
  const std::function<void()>* tasks[] = {&first, &second};
  parallelFor(2, 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) (*tasks[k])();
  });
}

}  // namespace kerf::geometry
