#include "kerf/geometry/contour.h"

#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace kerf::geometry {

ClosureReport analyseClosure(std::span<const Segment> path, double tol) {
  ClosureReport report;
  if (path.empty()) return report;
  report.gap = (path.back().end - path.front().start).norm();
  report.endsAtStart = report.gap <= tol;
  // Hash vertices on a grid of cell tol; look in the 3x3 neighbourhood so points within tol
  // across a cell border are found.
  const double cell = std::max(tol, 1e-12);
  auto key = [&](std::int64_t gx, std::int64_t gy) {
    return static_cast<std::uint64_t>(gx) * 0x9E3779B97F4A7C15ULL ^ static_cast<std::uint64_t>(gy);
  };
  std::unordered_multimap<std::uint64_t, std::size_t> seen;  // vertex k = start of segment k
  seen.reserve(path.size() * 2);
  auto cellOf = [&](const Vec2& p) {
    return std::pair<std::int64_t, std::int64_t>{static_cast<std::int64_t>(std::floor(p.x() / cell)),
                                                 static_cast<std::int64_t>(std::floor(p.y() / cell))};
  };
  for (std::size_t k = 0; k < path.size(); ++k) {
    const auto [sx, sy] = cellOf(path[k].start);
    seen.emplace(key(sx, sy), k);
    const Vec2& e = path[k].end;
    const auto [gx, gy] = cellOf(e);
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        auto range = seen.equal_range(key(gx + dx, gy + dy));
        for (auto it = range.first; it != range.second; ++it) {
          const std::size_t v = it->second;
          if ((path[v].start - e).norm() <= tol) {
            // v == k: the segment closes on its own start — a full circle does; a zero-length
            // move does not count as a loop.
            if (v == k && path[k].length() <= tol) continue;
            if (!report.loopFrom || v < *report.loopFrom) {
              report.loopFrom = v;
              report.loopTo = k;
            }
          }
        }
      }
    if (report.loopFrom) return report;
  }
  return report;
}

double pathLength(std::span<const Segment> path) {
  double total = 0.0;
  for (const Segment& s : path) total += s.length();
  return total;
}

Box pathBounds(std::span<const Segment> path) {
  Box b;
  for (const Segment& s : path) b.add(s.bounds());
  return b;
}

}  // namespace kerf::geometry
