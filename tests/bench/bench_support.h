// Clock and memory readings shared by the benchmark harnesses.
#pragma once

#include <sys/resource.h>

#include <chrono>

namespace kerf::bench {

using Clock = std::chrono::steady_clock;

inline double seconds(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

/// Peak resident set size of this process so far, KiB.
inline long peakRssKiB() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss;
}

}  // namespace kerf::bench
