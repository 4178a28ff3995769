#include "kerf/geometry/phase_times.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>

#if defined(__unix__)
#include <sys/resource.h>
#endif

namespace kerf::geometry {
namespace {

struct Recorder {
  std::atomic<bool> on{false};
  std::atomic<std::size_t> count{0};
  std::chrono::steady_clock::time_point start;
  std::array<PhaseMark, kMostPhaseMarks> marks{};
};

Recorder& recorder() {
  static Recorder r;
  return r;
}

long minorFaultsSoFar() {
#if defined(__unix__)
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) == 0) return usage.ru_minflt;
#endif
  return 0;
}

}  // namespace

void enablePhaseTimes() {
  Recorder& r = recorder();
  r.start = std::chrono::steady_clock::now();
  r.on.store(true, std::memory_order_release);
}

void markPhase(const char* what) {
  Recorder& r = recorder();
  if (!r.on.load(std::memory_order_acquire)) return;
  const std::size_t k = r.count.fetch_add(1, std::memory_order_relaxed);
  if (k >= kMostPhaseMarks) return;
  const std::chrono::duration<double, std::milli> since = std::chrono::steady_clock::now() - r.start;
  r.marks[k] = {what, since.count(), minorFaultsSoFar()};
}

std::vector<PhaseMark> phaseMarks() {
  Recorder& r = recorder();
  const std::size_t n = std::min(r.count.load(std::memory_order_acquire), kMostPhaseMarks);
  return {r.marks.begin(), r.marks.begin() + static_cast<std::ptrdiff_t>(n)};
}

}  // namespace kerf::geometry
