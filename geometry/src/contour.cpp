#include "kerf/geometry/contour.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace kerf::geometry {

namespace {

/// Open-addressing table of grid cells -> vertex index (a cell may hold several vertices: each
/// is its own entry). Far faster than a node-based multimap for a million vertices. A slot keeps
/// its key and value together, so a probe costs one cache line, not three.
class CellTable {
 public:
  explicit CellTable(std::size_t expected) {
    std::size_t cap = 16;
    while (cap < expected * 2) cap <<= 1;
    slots_.assign(cap, Slot{0, 0, kEmpty});
    mask_ = cap - 1;
  }
  void insert(std::int64_t gx, std::int64_t gy, std::size_t value) {
    for (std::size_t slot = hash(gx, gy) & mask_;; slot = (slot + 1) & mask_) {
      if (slots_[slot].value == kEmpty) {
        slots_[slot] = Slot{gx, gy, value};
        return;
      }
    }
  }
  template <typename F>
  void forEach(std::int64_t gx, std::int64_t gy, F&& f) const {
    for (std::size_t slot = hash(gx, gy) & mask_; slots_[slot].value != kEmpty; slot = (slot + 1) & mask_)
      if (slots_[slot].x == gx && slots_[slot].y == gy) f(slots_[slot].value);
  }

 private:
  static constexpr std::size_t kEmpty = ~std::size_t{0};
  struct Slot {
    std::int64_t x, y;
    std::size_t value;
  };
  static std::size_t hash(std::int64_t gx, std::int64_t gy) {
    std::uint64_t h = static_cast<std::uint64_t>(gx) * 0x9E3779B97F4A7C15ULL;
    h ^= static_cast<std::uint64_t>(gy) + 0x7F4A7C159E3779B9ULL + (h << 6) + (h >> 2);
    h ^= h >> 29;
    return static_cast<std::size_t>(h);
  }
  std::vector<Slot> slots_;
  std::size_t mask_ = 0;
};

}  // namespace

ClosureReport analyseClosure(SegmentView path, double tol) {
  ClosureReport report;
  if (path.empty()) return report;
  report.gap = (path.back().end - path.front().start).norm();
  report.endsAtStart = report.gap <= tol;
  // Vertices on a grid of cell size 2.5 tol. The disc of radius tol around an end reaches at
  // most 0.4 cell each way, so it stays inside the 2 x 2 block of its own cell and the neighbours
  // on the side of the cell's middle it lies on (with 0.1 cell to spare for rounding): four
  // probes per end instead of nine.
  const double cell = 2.5 * std::max(tol, 1e-12);
  auto cellOf = [&](const Vec2& p) {
    return std::pair<std::int64_t, std::int64_t>{static_cast<std::int64_t>(std::floor(p.x() / cell)),
                                                 static_cast<std::int64_t>(std::floor(p.y() / cell))};
  };
  CellTable starts(path.size());
  for (std::size_t k = 0; k < path.size(); ++k) {
    const auto [sx, sy] = cellOf(path[k].start);
    starts.insert(sx, sy, k);
    const Vec2& e = path[k].end;
    const double fx = e.x() / cell, fy = e.y() / cell;
    const auto gx = static_cast<std::int64_t>(std::floor(fx)), gy = static_cast<std::int64_t>(std::floor(fy));
    const std::int64_t sideX = fx - static_cast<double>(gx) < 0.5 ? -1 : 1;
    const std::int64_t sideY = fy - static_cast<double>(gy) < 0.5 ? -1 : 1;
    for (const std::int64_t dx : {std::int64_t{0}, sideX})
      for (const std::int64_t dy : {std::int64_t{0}, sideY})
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
