#include "kerf/geometry/contour.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

namespace kerf::geometry {

namespace {

/// Open-addressing table of grid cells -> the vertices in them. A slot is 6 bytes in two arrays: a
/// 16-bit tag of its cell's hash (0: the slot is empty), scanned alone, and the first vertex of its
/// chain, read only where the tag matches; each vertex names the next of its chain (4 bytes a
/// vertex). A vertex joins the chain of the first slot with its tag on its cell's probe sequence,
/// so the vertices of one cell share one slot: a program of 40,000 moves inside one cell (a fuzz
/// input, tests/fuzz/corpus/closure-one-cell.nc) made a run of 40,000 slots with a vertex each,
/// and inserting took 0.8 s, growing as the square of the moves. Two cells may share a tag, and
/// then a chain: a match is a candidate only; the caller measures the distance anyway. There are
/// 2 slots a vertex (any count, not a power of two: the slot is the hash scaled to the table), so
/// the table is 16 bytes a vertex, 3.2 MB at 200,000; at 1.5 (13 bytes) the linear probes scanned
/// half as many tags again (docs/performance.md). Slots of 24 bytes (both cell coordinates and the
/// vertex) at twice the vertices took 12.6 MB.
class CellTable {
 public:
  /// vertices_ and next_ are left unwritten: a slot's vertex is read only where its tag says it
  /// holds one, and a vertex's next only once it is in the table.
  explicit CellTable(std::size_t expected)
      : size_(std::max<std::size_t>(16, 2 * expected)),
        tags_(size_, kEmpty),
        vertices_(new std::uint32_t[size_]),
        next_(new std::uint32_t[std::max<std::size_t>(1, expected)]) {}
  /// A cell as the table finds it: its hash, made once for an insertion and a probe of one cell.
  struct Cell {
    std::uint64_t hash;
  };
  static Cell cell(std::int64_t gx, std::int64_t gy) { return {hash(gx, gy)}; }
  /// value < expected, each once.
  void insert(Cell c, std::uint32_t value) {
    const std::uint16_t t = tag(c.hash);
    for (std::size_t slot = slotOf(c.hash);; slot = next(slot)) {
      if (tags_[slot] == kEmpty) {
        tags_[slot] = t;
        vertices_[slot] = value;
        next_[value] = kEnd;
        return;
      }
      if (tags_[slot] == t) {  // its cell's chain (or one with the same tag): at its head
        next_[value] = vertices_[slot];
        vertices_[slot] = value;
        return;
      }
    }
  }
  /// f(vertex) for every vertex that may lie in the cell (and a few of other cells).
  template <typename F>
  void forEach(Cell c, F&& f) const {
    const std::uint16_t t = tag(c.hash);
    for (std::size_t slot = slotOf(c.hash); tags_[slot] != kEmpty; slot = next(slot))
      if (tags_[slot] == t)
        for (std::uint32_t v = vertices_[slot]; v != kEnd; v = next_[v]) f(std::size_t{v});
  }

 private:
  static constexpr std::uint16_t kEmpty = 0;
  static constexpr std::uint32_t kEnd = std::numeric_limits<std::uint32_t>::max();
  static std::uint64_t hash(std::int64_t gx, std::int64_t gy) {
    // Both coordinates through a full 64-bit finaliser (MurmurHash3's fmix64 constants), so that
    // the low bits (the slot) and the high bits (the tag) are each well mixed.
    std::uint64_t h = static_cast<std::uint64_t>(gx) * 0x9E3779B97F4A7C15ULL ^ static_cast<std::uint64_t>(gy);
    h ^= h >> 33;
    h *= 0xFF51AFD7ED558CCDULL;
    h ^= h >> 33;
    h *= 0xC4CEB9FE1A85EC53ULL;
    h ^= h >> 33;
    return h;
  }
  /// The top 16 bits, never 0 (that marks an empty slot).
  static std::uint16_t tag(std::uint64_t h) {
    const auto t = static_cast<std::uint16_t>(h >> 48);
    return t == kEmpty ? std::uint16_t{1} : t;
  }
  /// The low 32 bits of the hash scaled to [0, size) (the tag takes the top 16). Half the size
  /// times 32 bits stays within 64 bits for any table of fewer than 2^33 slots.
  [[nodiscard]] std::size_t slotOf(std::uint64_t h) const {
    return static_cast<std::size_t>(((h & 0xFFFFFFFFULL) * (size_ >> 1)) >> 31);
  }
  [[nodiscard]] std::size_t next(std::size_t slot) const { return slot + 1 == size_ ? 0 : slot + 1; }
  std::size_t size_;
  std::vector<std::uint16_t> tags_;
  std::unique_ptr<std::uint32_t[]> vertices_;
  std::unique_ptr<std::uint32_t[]> next_;
};

/// floor(f) as an integer, inline (std::floor is a call on the baseline x86-64); beyond 2^62
/// cells, the farthest cell (both ends of a comparison land there alike).
std::int64_t cellIndex(double f) {
  constexpr double kFar = 4.6e18;  // below 2^62
  if (!(std::abs(f) < kFar)) return f < 0 ? -(std::int64_t{1} << 62) : std::int64_t{1} << 62;
  const auto i = static_cast<std::int64_t>(f);  // toward zero
  return static_cast<double>(i) > f ? i - 1 : i;
}

}  // namespace

ClosureReport analyseClosure(SegmentView path, double tol) {
  ClosureReport report;
  if (path.empty()) return report;
  report.gap = (path.back().end - path.front().start).norm();
  report.endsAtStart = report.gap <= tol;
  // Vertices on a grid of cell size 32 tol. The disc of radius tol around an end reaches at most
  // 1/32 cell each way, so besides its own cell it meets the neighbour across a side only when it
  // lies within 1/32 cell of that side (probed from 0.05 cell, for rounding): most ends probe one
  // cell, 1.2 on average where the ends fall anywhere, 4 at most. (At 8 tol and 0.15, 1.7 cells:
  // the probes took a quarter more instructions on a tangled walk; a cell still holds few of a
  // program's vertices, which lie a step of the path apart.)
  constexpr double kCellTolerances = 32.0, kNear = 0.05;
  const double cell = kCellTolerances * std::max(tol, 1e-12);
  const double perCell = 1.0 / cell;  // insertion and probes scale alike, so they agree on every cell
  auto cellOf = [&](const Vec2& p) {
    return std::pair<std::int64_t, std::int64_t>{cellIndex(p.x() * perCell), cellIndex(p.y() * perCell)};
  };
  if (path.size() >= std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("analyseClosure: more than 2^32 - 2 segments");
  // The first segment k whose end meets the start of a segment v <= k, and the earliest such v: one
  // pass in which the start of k goes into the table and then the end of k is probed, so the table
  // holds the starts of 0..k alone and the pass stops at the first k that meets one. A path that
  // runs on from each end (the next start is that end) has its start's cell from the probe before.
  CellTable starts(path.size());
  std::size_t loopTo = path.size(), loopFrom = path.size();
  CellTable::Cell endCell{};  // the cell of the end probed last
  for (std::size_t k = 0; k < path.size(); ++k) {
    const Vec2& s = path[k].start;
    if (k == 0 || s != path[k - 1].end) {
      const auto [sx, sy] = cellOf(s);
      starts.insert(CellTable::cell(sx, sy), static_cast<std::uint32_t>(k));
    } else {
      starts.insert(endCell, static_cast<std::uint32_t>(k));
    }
    const Vec2& e = path[k].end;
    const double fx = e.x() * perCell, fy = e.y() * perCell;
    const std::int64_t gx = cellIndex(fx), gy = cellIndex(fy);
    const double rx = fx - static_cast<double>(gx), ry = fy - static_cast<double>(gy);
    const std::int64_t sideX = rx < kNear ? -1 : rx > 1 - kNear ? 1 : 0;
    const std::int64_t sideY = ry < kNear ? -1 : ry > 1 - kNear ? 1 : 0;
    std::size_t best = path.size();
    auto visit = [&](CellTable::Cell c) {
      starts.forEach(c, [&](std::size_t v) {
        if (v >= best || (path[v].start - e).norm() > tol) return;
        // v == k: the segment closes on its own start — a full circle does; a zero-length
        // move does not count as a loop.
        if (v == k && path[k].length() <= tol) return;
        best = v;
      });
    };
    endCell = CellTable::cell(gx, gy);
    visit(endCell);
    if (sideX) visit(CellTable::cell(gx + sideX, gy));
    if (sideY) visit(CellTable::cell(gx, gy + sideY));
    if (sideX && sideY) visit(CellTable::cell(gx + sideX, gy + sideY));
    if (best < path.size()) {
      loopTo = k;
      loopFrom = best;
      break;
    }
  }
  if (loopTo < path.size()) {
    report.loopFrom = loopFrom;
    report.loopTo = loopTo;
  }
  return report;
}

}  // namespace kerf::geometry
