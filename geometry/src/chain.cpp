#include "kerf/geometry/chain.h"

#include "kerf/geometry/offset.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace kerf::geometry {

namespace {

/// Ends into nodes: a grid of cells the tolerance wide; an end joins the first node within the
/// tolerance in its own or a neighbouring cell.
class NodeIndex {
 public:
  explicit NodeIndex(double tol) : tol_(tol), cell_(std::max(tol, 1e-9)) {}

  std::size_t nodeOf(const Vec2& p) {
    const std::int64_t cx = key(p.x()), cy = key(p.y());
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const auto it = grid_.find(pack(cx + dx, cy + dy));
        if (it == grid_.end()) continue;
        for (std::size_t n : it->second)
          if ((points_[n] - p).norm() <= tol_) return n;
      }
    points_.push_back(p);
    grid_[pack(cx, cy)].push_back(points_.size() - 1);
    return points_.size() - 1;
  }
  [[nodiscard]] std::size_t size() const { return points_.size(); }

 private:
  std::int64_t key(double v) const { return static_cast<std::int64_t>(std::floor(v / cell_)); }
  static std::uint64_t pack(std::int64_t x, std::int64_t y) {
    return (static_cast<std::uint64_t>(x) * 0x9E3779B97F4A7C15ull) ^ static_cast<std::uint64_t>(y);
  }
  double tol_, cell_;
  std::vector<Vec2> points_;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> grid_;
};

}  // namespace

std::vector<Chain> chainSegments(std::span<const Segment> segments, const ChainOptions& options) {
  const std::size_t n = segments.size();
  NodeIndex index(options.tolerance);
  std::vector<std::size_t> from(n), to(n);
  std::vector<bool> usable(n, true);
  std::vector<std::vector<std::size_t>> at;  // node -> elements touching it
  for (std::size_t i = 0; i < n; ++i) {
    const Segment& s = segments[i];
    if (!s.isArc() && (s.end - s.start).norm() <= 1e-12) {
      usable[i] = false;
      continue;
    }
    from[i] = index.nodeOf(s.start);
    to[i] = index.nodeOf(s.end);
    at.resize(index.size());
    at[from[i]].push_back(i);
    if (to[i] != from[i]) at[to[i]].push_back(i);
  }
  std::vector<bool> used(n, false);

  auto walk = [&](std::size_t first, bool firstReversed) {
    Chain c;
    std::size_t e = first;
    bool rev = firstReversed;
    const std::size_t startNode = rev ? to[e] : from[e];
    while (true) {
      used[e] = true;
      c.elements.push_back(e);
      c.reversed.push_back(rev);
      Segment s = rev ? segments[e].reversed() : segments[e];
      if (!c.path.empty()) {
        const Vec2 join = c.path.back().end;
        if (s.isArc()) {
          const ArcDirection d = s.direction();
          const bool full = (s.end - s.start).norm() <= 1e-12 * std::max(1.0, s.radius());
          s = Segment::arc(join, full ? join : s.end, s.centre, d);
        } else {
          s.start = join;
        }
      }
      c.path.push_back(s);
      const std::size_t node = rev ? from[e] : to[e];
      if (node == startNode && from[e] != to[e]) {
        c.closed = true;
        break;
      }
      if (from[e] == to[e]) {  // a full circle
        c.closed = c.elements.size() == 1;
        break;
      }
      // The unused element at this node that turns least from the way we arrive.
      const Vec2 arrive = s.tangentAt(1.0);
      std::size_t best = n;
      bool bestRev = false;
      double bestTurn = 1e300;
      std::size_t candidates = 0;
      for (std::size_t f : at[node]) {
        if (used[f] || from[f] == to[f]) continue;
        ++candidates;
        const bool r = to[f] == node;
        const Vec2 leave = (r ? segments[f].reversed() : segments[f]).tangentAt(0.0);
        const double turn = std::abs(std::atan2(cross(arrive, leave), arrive.dot(leave)));
        if (turn < bestTurn) {
          bestTurn = turn;
          best = f;
          bestRev = r;
        }
      }
      if (candidates > 1) c.branched = true;
      if (best == n) break;
      e = best;
      rev = bestRev;
    }
    if (!c.closed) c.gap = (c.path.back().end - c.path.front().start).norm();
    if (c.closed && c.path.size() > 1) c.path.back().end = c.path.front().start;
    return c;
  };

  std::vector<Chain> chains;
  // Open chains first, from an end where only one element meets.
  for (std::size_t i = 0; i < n; ++i) {
    if (!usable[i] || used[i]) continue;
    for (const bool atEnd : {false, true}) {
      if (used[i]) break;
      const std::size_t node = atEnd ? to[i] : from[i];
      if (from[i] != to[i] && at[node].size() == 1) chains.push_back(walk(i, atEnd));
    }
  }
  // Then what is left: loops (and what branching left over).
  for (std::size_t i = 0; i < n; ++i)
    if (usable[i] && !used[i]) chains.push_back(walk(i, false));
  std::stable_sort(chains.begin(), chains.end(), [](const Chain& a, const Chain& b) {
    return *std::min_element(a.elements.begin(), a.elements.end()) <
           *std::min_element(b.elements.begin(), b.elements.end());
  });
  return chains;
}

namespace {

/// Adds twice a segment's share of the signed area to `twice`. A line: the triangle it makes with
/// the origin. An arc: the triangles (origin, start, centre) and (origin, centre, end) and the
/// sector, r^2 sweep — the same as the chord's triangle and the circular segment beyond it,
/// r^2 (sweep - sin sweep), without the sine (the cross product of the radii is r^2 sin sweep).
void addTwiceArea(double& twice, const Segment& s) {
  if (!s.isArc()) {
    twice += cross(s.start, s.end);
    return;
  }
  twice += cross(s.centre, s.end - s.start) + (s.start - s.centre).squaredNorm() * s.sweep;
}

}  // namespace

double areaTerm(const Segment& s) {
  double twice = 0.0;
  addTwiceArea(twice, s);
  return 0.5 * twice;
}

double signedArea(std::span<const Segment> path) {
  double twice = 0.0;
  for (const Segment& s : path) addTwiceArea(twice, s);
  return 0.5 * twice;
}

std::vector<int> nestingDepths(std::span<const Chain> chains) {
  std::vector<int> depth(chains.size(), 0);
  std::vector<std::span<const Segment>> loops;
  std::vector<Vec2> probes;
  std::vector<std::size_t> self, of;  // of: the chain each closed loop is
  for (std::size_t c = 0; c < chains.size(); ++c) {
    if (!chains[c].closed) continue;
    self.push_back(loops.size());
    of.push_back(c);
    loops.emplace_back(chains[c].path);
    probes.push_back(chains[c].path.front().pointAt(0.5));
  }
  const std::vector<int> around = loopsAround(loops, probes, self);
  for (std::size_t k = 0; k < of.size(); ++k) depth[of[k]] = around[k];
  return depth;
}

}  // namespace kerf::geometry
