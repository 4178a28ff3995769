#include "kerf/geometry/contour.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace kerf::geometry {

namespace {

/// Open-addressing table of grid cells -> vertex index (a cell may hold several vertices: each
/// is its own entry). Far faster than a node-based multimap for a million vertices.
class CellTable {
 public:
  explicit CellTable(std::size_t expected) {
    std::size_t cap = 16;
    while (cap < expected * 2) cap <<= 1;
    keysX_.assign(cap, 0);
    keysY_.assign(cap, 0);
    values_.assign(cap, kEmpty);
    mask_ = cap - 1;
  }
  void insert(std::int64_t gx, std::int64_t gy, std::size_t value) {
    for (std::size_t slot = hash(gx, gy) & mask_;; slot = (slot + 1) & mask_) {
      if (values_[slot] == kEmpty) {
        keysX_[slot] = gx;
        keysY_[slot] = gy;
        values_[slot] = value;
        return;
      }
    }
  }
  template <typename F>
  void forEach(std::int64_t gx, std::int64_t gy, F&& f) const {
    for (std::size_t slot = hash(gx, gy) & mask_; values_[slot] != kEmpty; slot = (slot + 1) & mask_)
      if (keysX_[slot] == gx && keysY_[slot] == gy) f(values_[slot]);
  }

 private:
  static constexpr std::size_t kEmpty = ~std::size_t{0};
  static std::size_t hash(std::int64_t gx, std::int64_t gy) {
    std::uint64_t h = static_cast<std::uint64_t>(gx) * 0x9E3779B97F4A7C15ULL;
    h ^= static_cast<std::uint64_t>(gy) + 0x7F4A7C159E3779B9ULL + (h << 6) + (h >> 2);
    h ^= h >> 29;
    return static_cast<std::size_t>(h);
  }
  std::vector<std::int64_t> keysX_, keysY_;
  std::vector<std::size_t> values_;
  std::size_t mask_ = 0;
};

}  // namespace

ClosureReport analyseClosure(std::span<const Segment> path, double tol) {
  ClosureReport report;
  if (path.empty()) return report;
  report.gap = (path.back().end - path.front().start).norm();
  report.endsAtStart = report.gap <= tol;
  // Vertices on a grid of cell size tol; an end is compared with the starts in its own and the
  // eight neighbouring cells, so points within tol across a cell border are found.
  const double cell = std::max(tol, 1e-12);
  auto cellOf = [&](const Vec2& p) {
    return std::pair<std::int64_t, std::int64_t>{static_cast<std::int64_t>(std::floor(p.x() / cell)),
                                                 static_cast<std::int64_t>(std::floor(p.y() / cell))};
  };
  CellTable starts(path.size());
  for (std::size_t k = 0; k < path.size(); ++k) {
    const auto [sx, sy] = cellOf(path[k].start);
    starts.insert(sx, sy, k);
    const Vec2& e = path[k].end;
    const auto [gx, gy] = cellOf(e);
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        starts.forEach(gx + dx, gy + dy, [&](std::size_t v) {
          if ((path[v].start - e).norm() > tol) return;
          // v == k: the segment closes on its own start — a full circle does; a zero-length
          // move does not count as a loop.
          if (v == k && path[k].length() <= tol) return;
          if (!report.loopFrom || v < *report.loopFrom) {
            report.loopFrom = v;
            report.loopTo = k;
          }
        });
    if (report.loopFrom) return report;
  }
  return report;
}

}  // namespace kerf::geometry
