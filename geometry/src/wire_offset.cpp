// The wire offset: exact element offsets, arc joins at convex corners, interference removed over
// the whole path (offset.h; docs/geometry.md, "The wire offset").
// Sections: 1. element offsets and their joins  2. winding and nesting  3. offset and join
//           4. interference removed  5. what the wire cannot reach  6. the entry point
#include "kerf/geometry/chain.h"
#include "kerf/geometry/intersection.h"
#include "kerf/geometry/offset.h"

#include "angles.h"
#include "box_tree.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <unordered_map>

namespace kerf::geometry {
namespace {

// ---- 1. element offsets and their joins ---------------------------------------------------------

Vec2 leftOf(const Vec2& v) { return {-v.y(), v.x()}; }

double wrapSigned(double a) {
  while (a > kPi) a -= kTwoPi;
  while (a <= -kPi) a += kTwoPi;
  return a;
}

/// The exact offset curve of s at d (left positive). An arc the offset turns inside out becomes
/// the arc on the far side of its centre; one that shrinks to its centre becomes that point.
Segment exactOffset(const Segment& s, double d, double tol) {
  if (!s.isArc()) {
    const Vec2 dir = s.end - s.start;
    const Vec2 shift = leftOf(dir / dir.norm()) * d;
    return Segment::line(s.start + shift, s.end + shift);
  }
  // Left of a counter-clockwise arc is towards the centre. Each end moves along its own radius, so
  // an arc whose end sits off its circle (within the tolerance it was accepted with) keeps meeting
  // its neighbour's offset where the contour meets it.
  const double toward = s.sweep >= 0 ? -d : d;
  const double r = s.radius() + toward;
  if (std::abs(r) <= tol) return Segment::line(s.centre, s.centre);
  Segment o = s;
  const double radius = std::abs(r);
  const double a0 = r < 0 ? s.startAngle() + kPi : s.startAngle();
  o.start = o.centre + radius * direction(a0);
  const Vec2 ue = s.end - s.centre;
  const double re = ue.norm();
  o.end = o.centre + radius * direction(a0 + o.sweep);
  if (re > 0) o.end = s.centre + ue * ((re + toward) / re);
  return o;
}

/// An arc of the circle about c from p to q, turning by sweep.
Segment joinArc(const Vec2& c, const Vec2& p, const Vec2& q, double sweep) {
  Segment a;
  a.kind = SegmentKind::Arc;
  a.centre = c;
  a.sweep = sweep;
  a.start = p;
  a.end = q;
  return a;
}

struct Raw {
  Segment seg;
  std::size_t element = 0;
  bool corner = false;
};

struct Sub {
  Segment seg;
  std::size_t raw = 0;
  double t0 = 0, t1 = 1;
};

}  // namespace

Segment subSegment(const Segment& s, double t0, double t1) {
  if (!s.isArc()) return Segment::line(t0 <= 0 ? s.start : s.pointAt(t0), t1 >= 1 ? s.end : s.pointAt(t1));
  Segment a = s;
  const double a0 = s.startAngle() + s.sweep * t0, r = s.radius();
  a.sweep = s.sweep * (t1 - t0);
  a.start = t0 <= 0 ? s.start : s.centre + r * direction(a0);
  a.end = t1 >= 1 ? s.end : s.centre + r * direction(a0 + a.sweep);
  return a;
}

namespace {

// ---- 2. winding and nesting ---------------------------------------------------------------------

/// What one segment adds to the winding number of p: its crossings of the ray from p towards +x.
/// Only a segment whose box meets that ray adds anything.
int windingOf(const Segment& s, const Vec2& p) {
  int w = 0;
  {
    if (!s.isArc()) {
      // Half-open in y so that a vertex on the ray counts once.
      const Vec2& a = s.start;
      const Vec2& b = s.end;
      if (a.y() <= p.y() && b.y() > p.y()) {
        if (cross(b - a, p - a) > 0) ++w;
      } else if (a.y() > p.y() && b.y() <= p.y()) {
        if (cross(b - a, p - a) < 0) --w;
      }
      return w;
    }
    const double dy = p.y() - s.centre.y(), r = s.radius();
    if (std::abs(dy) >= r) return w;
    const double h = std::sqrt(r * r - dy * dy), a0 = s.startAngle();
    for (const double x : {s.centre.x() - h, s.centre.x() + h}) {
      if (x <= p.x()) continue;
      const Vec2 q(x, p.y());
      const double phi = angleOf(q - s.centre);
      const double along = detail::angleAlong(a0, s.sweep, phi);
      if (along > std::abs(s.sweep)) continue;
      // Going up or down there: the tangent's y is cos(phi) for a counter-clockwise arc.
      const double up = std::cos(phi) * (s.sweep > 0 ? 1.0 : -1.0);
      // Half-open like the lines: an arc end exactly on the ray counts where the arc leaves upward.
      const bool full = std::abs(s.sweep) >= kTwoPi - 1e-12;  // its start is its end: counted once
      if (!full && (along == 0.0 || along == std::abs(s.sweep))) {
        const bool atStart = along == 0.0;
        if ((up > 0) != atStart) continue;
      }
      w += up > 0 ? 1 : up < 0 ? -1 : 0;
    }
  }
  return w;
}

/// The ray from p towards +x as a box: a segment whose box it misses adds nothing to p's winding.
Box rayFrom(const Vec2& p) {
  Box ray;
  ray.min = p;
  ray.max = Vec2(std::numeric_limits<double>::infinity(), p.y());
  return ray;
}

}  // namespace

int windingNumber(std::span<const Segment> path, const Vec2& p) {
  int w = 0;
  for (const Segment& s : path) w += windingOf(s, p);
  return w;
}

std::vector<int> loopsAround(std::span<const std::span<const Segment>> loops, std::span<const Vec2> probes,
                             std::span<const std::size_t> self) {
  std::vector<Box> boxes(loops.size());
  for (std::size_t l = 0; l < loops.size(); ++l)
    for (const Segment& s : loops[l]) boxes[l].add(s.bounds());
  const detail::BoxTree tree(std::move(boxes));
  std::vector<int> count(probes.size(), 0);
  for (std::size_t i = 0; i < probes.size(); ++i) {
    // A loop whose box the ray from the probe misses (within 1e-6 mm, so that rounding cannot
    // leave one out) has no segment that crosses the ray: its winding number is 0.
    tree.visitOverlapping(rayFrom(probes[i]), 1e-6, [&](std::size_t l) {
      if (l != self[i] && windingNumber(loops[l], probes[i]) != 0) ++count[i];
    });
  }
  return count;
}

namespace {

// ---- 3. offset and join -------------------------------------------------------------------------

/// wireOffset in its stages (docs/geometry.md, "The wire offset"): each element offset exactly and
/// the corners joined (offsetAndJoin), the raw path split where it meets itself (split), the pieces
/// at least |d| from the contour kept (keep), linked head to tail into paths (link), and the runs
/// of elements the wire cannot reach (findLost). A stage that runs past the budgets sets refused.
class WireOffsetBuilder {
 public:
  WireOffsetBuilder(std::span<const Segment> contour, double d, const WireOffsetOptions& options)
      : contour_(contour), d_(d), options_(options), tol_(options.tolerance), dist_(std::abs(d)) {}

  WireOffsetResult run() {
    // Elements with a length: a zero-length move has no direction to offset from.
    for (std::size_t i = 0; i < contour_.size(); ++i)
      if (contour_[i].length() > tol_) kept_.push_back(i);
    if (kept_.empty() || dist_ <= tol_) {
      if (!kept_.empty()) {  // no offset: the contour itself
        std::vector<WirePiece> path;
        for (std::size_t i : kept_) path.push_back({contour_[i], i, false});
        result_.paths.push_back(std::move(path));
      }
      return result_;
    }
    if (kept_.size() * 3 > options_.maxPieces) {
      result_.refused = true;
      return result_;
    }
    n_ = kept_.size();
    offsetAndJoin();
    maxTests_ = options_.maxTests ? options_.maxTests : 8 * raw_.size() + 20'000'000;
    if (!split() || !keep()) return result_;
    link();
    findLost();
    return result_;
  }

 private:
  void offsetAndJoin();
  bool split();
  bool keep();
  void link();
  void findLost();
  /// One exact test, counted against the budget: past it the offset is refused, after bounded work.
  bool overBudget() {
    if (++result_.tests <= maxTests_) return false;
    result_.refused = result_.tooMuchWork = true;
    return true;
  }

  std::span<const Segment> contour_;
  const double d_;
  const WireOffsetOptions& options_;
  const double tol_, dist_;
  std::size_t maxTests_ = 0;
  WireOffsetResult result_;
  std::vector<std::size_t> kept_;                           // the elements with a length
  std::size_t n_ = 0;                                       // kept_.size()
  std::vector<Raw> raw_;                                    // offsets and joins, in order
  std::size_t m_ = 0;                                       // raw_.size()
  std::vector<std::vector<std::pair<double, Vec2>>> cuts_;  // per raw piece: where the path meets it
  std::vector<Sub> subs_;                                   // the pieces kept
  std::vector<bool> alive_;                                 // per element: some of its offset was kept
};

void WireOffsetBuilder::offsetAndJoin() {
  std::vector<Segment> off(n_);
  for (std::size_t k = 0; k < n_; ++k) off[k] = exactOffset(contour_[kept_[k]], d_, tol_);
  raw_.reserve(3 * n_);
  std::vector<std::optional<Segment>> joins(n_);  // joins[k]: between k and k + 1
  const std::size_t joints = options_.closed ? n_ : n_ - 1;
  for (std::size_t k = 0; k < joints; ++k) {
    const std::size_t next = (k + 1) % n_;
    Segment& a = off[k];
    Segment& b = off[next];
    const Vec2 p = a.end, q = b.start;
    if ((p - q).norm() <= tol_) {
      b.start = p;  // exactly shared, for the linking below (an arc's circle follows its start)
      continue;
    }
    const Vec2 v = contour_[kept_[k]].end;
    double sweep = wrapSigned(angleOf(q - v) - angleOf(p - v));
    const double convexSign = d_ > 0 ? -1.0 : 1.0;  // a left offset rolls clockwise round a corner
    if (std::abs(std::abs(sweep) - kPi) < 1e-9) sweep = convexSign * kPi;  // a reversal: the round cap
    if (sweep * convexSign > 0) {
      joins[k] = joinArc(v, p, q, sweep);
      continue;
    }
    // Concave: trim both at their intersection nearest the corner, when they meet.
    const SegmentIntersection x = intersect(a, b, tol_);
    std::optional<Vec2> best;
    for (int c = 0; c < x.count; ++c)
      if (!best || (x.points[c] - v).norm() < (*best - v).norm()) best = x.points[c];
    if (best && a.length() > tol_ && b.length() > tol_) {
      const double ta = a.parameterOf(*best), tb = b.parameterOf(*best);
      if (ta > 0.0 && tb < 1.0) {
        a = subSegment(a, 0.0, ta);
        b = subSegment(b, tb, 1.0);
        a.end = *best;
        b.start = *best;
        continue;
      }
    }
    joins[k] = joinArc(v, p, q, sweep);  // the short reversed arc: removed as interference below
  }
  for (std::size_t k = 0; k < n_; ++k) {
    if (off[k].length() > tol_ * 0.01) raw_.push_back({off[k], kept_[k], false});
    if (joins[k]) raw_.push_back({*joins[k], kept_[k], true});
  }
  result_.rawPieces = raw_.size();
}

// ---- 4. interference removed --------------------------------------------------------------------

bool WireOffsetBuilder::split() {
  // 3: split where the raw_ path meets itself.
  std::vector<Box> boxes(raw_.size());
  for (std::size_t i = 0; i < raw_.size(); ++i) boxes[i] = raw_[i].seg.bounds();
  const detail::BoxTree pieces(boxes);
  cuts_.assign(raw_.size(), {});
  m_ = raw_.size();
  std::size_t splitCount = 0;
  for (std::size_t i = 0; i < m_ && !result_.refused; ++i) {
    pieces.visitOverlapping(boxes[i], tol_, [&](std::size_t j) {
      if (j <= i || result_.refused || overBudget()) return;
      const SegmentIntersection x = intersect(raw_[i].seg, raw_[j].seg, tol_);
      const bool neighbours = j == i + 1 || (options_.closed && i == 0 && j == m_ - 1);
      for (int c = 0; c < x.count; ++c) {
        const Vec2 pt = x.points[c];
        if (neighbours) {
          const Vec2 shared = j == i + 1 ? raw_[i].seg.end : raw_[i].seg.start;
          if ((pt - shared).norm() <= 10 * tol_) continue;
        }
        cuts_[i].push_back({raw_[i].seg.parameterOf(pt), pt});
        cuts_[j].push_back({raw_[j].seg.parameterOf(pt), pt});
        if (++splitCount > options_.maxPieces) result_.refused = true;
      }
    });
  }
  if (result_.refused) return false;
  result_.splitPoints = splitCount;
  return true;
}

bool WireOffsetBuilder::keep() {
  // Keep the pieces whose middle is at least |d_| from the contour_.
  std::vector<Box> elementBoxes(contour_.size());
  for (std::size_t i = 0; i < contour_.size(); ++i) elementBoxes[i] = contour_[i].bounds();
  const detail::BoxTree elements(elementBoxes);
  // A closed contour_: the side of the offset is also a winding number (a piece of an offset that
  // has passed through a thin part of the contour_ to its far side is |d_| away, but on the wrong side).
  const double area = options_.closed ? signedArea(contour_) : 0.0;
  const int sideWinding = d_ > 0 ? (area > 0 ? 1 : 0) : (area > 0 ? 0 : -1);
  auto valid = [&](const Vec2& p) {
    if (options_.closed) {
      // windingNumber(contour_, p), from the elements whose boxes meet the ray from p (within the
      // tolerance, so that rounding cannot leave one out): the same sum, not a pass over the whole
      // contour_ for every piece (80,000 vertices: 26.9 s of kerf cam, 89% of it here).
      int w = 0;
      elements.visitOverlapping(rayFrom(p), tol_, [&](std::size_t e) { w += windingOf(contour_[e], p); });
      if (w != sideWinding) return false;
    }
    bool ok = true;
    Box b;
    b.add(p);
    elements.visitOverlapping(b, dist_, [&](std::size_t e) {
      if (ok && !result_.refused && !overBudget() && contour_[e].length() > tol_ &&
          contour_[e].distanceTo(p) < dist_ - tol_)
        ok = false;
    });
    return ok;
  };
  alive_.assign(contour_.size(), false);
  for (std::size_t i = 0; i < m_; ++i) {
    auto& c = cuts_[i];
    std::sort(c.begin(), c.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    const double len = raw_[i].seg.length();
    std::vector<std::pair<double, Vec2>> at{{0.0, raw_[i].seg.start}};
    for (const auto& [t, pt] : c) {
      if (t * len <= tol_ || (1.0 - t) * len <= tol_) continue;
      if ((pt - at.back().second).norm() <= tol_) continue;
      at.push_back({t, pt});
    }
    at.push_back({1.0, raw_[i].seg.end});
    for (std::size_t s = 0; s + 1 < at.size(); ++s) {
      Segment piece = subSegment(raw_[i].seg, at[s].first, at[s + 1].first);
      piece.start = at[s].second;
      piece.end = at[s + 1].second;
      if (piece.length() <= tol_ * 0.01) continue;
      if (!valid(piece.pointAt(0.5))) continue;
      subs_.push_back({piece, i, at[s].first, at[s + 1].first});
      if (!raw_[i].corner) alive_[raw_[i].element] = true;
    }
    if (result_.refused) return false;
  }

  return true;
}

void WireOffsetBuilder::link() {
  // Link the kept_ pieces head to tail (they run in the raw_ path's order except across a split).
  const double link = 100 * tol_;  // ends this close are one point (offset ends of arcs off their circle)
  auto key = [&](const Vec2& p) {
    const auto gx = static_cast<std::int64_t>(std::floor(p.x() / (4 * link)));
    const auto gy = static_cast<std::int64_t>(std::floor(p.y() / (4 * link)));
    return std::pair{gx, gy};
  };
  struct PairHash {
    std::size_t operator()(const std::pair<std::int64_t, std::int64_t>& k) const {
      return std::hash<std::int64_t>()(k.first * 73856093 ^ k.second * 19349663);
    }
  };
  std::unordered_map<std::pair<std::int64_t, std::int64_t>, std::vector<std::size_t>, PairHash> starts;
  for (std::size_t s = 0; s < subs_.size(); ++s) starts[key(subs_[s].seg.start)].push_back(s);
  std::vector<bool> used(subs_.size(), false);
  auto following = [&](std::size_t s) -> std::optional<std::size_t> {
    const Vec2 e = subs_[s].seg.end;
    if (s + 1 < subs_.size() && !used[s + 1] && (subs_[s + 1].seg.start - e).norm() <= link) return s + 1;
    const auto [gx, gy] = key(e);
    std::optional<std::size_t> best;
    std::size_t bestAhead = 0;
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const auto it = starts.find({gx + dx, gy + dy});
        if (it == starts.end()) continue;
        for (std::size_t c : it->second) {
          if (used[c] || (subs_[c].seg.start - e).norm() > link) continue;
          const std::size_t ahead = (c + subs_.size() - s) % subs_.size();  // nearest along the raw_ path
          if (!best || ahead < bestAhead) best = c, bestAhead = ahead;
        }
      }
    return best;
  };
  // The same raw_ piece continuing across a split point that removed nothing becomes one element.
  auto append = [&](std::vector<WirePiece>& path, const Sub& sub, std::size_t& lastRaw, double& lastT0,
                    double& lastT1) {
    if (!path.empty() && lastRaw == sub.raw && lastT1 == sub.t0) {
      Segment merged = subSegment(raw_[sub.raw].seg, lastT0, sub.t1);
      merged.start = path.back().segment.start;
      merged.end = sub.seg.end;
      path.back().segment = merged;
    } else {
      path.push_back({sub.seg, raw_[sub.raw].element, raw_[sub.raw].corner});
      lastT0 = sub.t0;
    }
    lastRaw = sub.raw;
    lastT1 = sub.t1;
  };
  for (std::size_t first = 0; first < subs_.size(); ++first) {
    if (used[first]) continue;
    std::vector<WirePiece> path;
    std::size_t lastRaw = std::numeric_limits<std::size_t>::max();
    double lastT0 = 0, lastT1 = -1;
    std::size_t cur = first;
    used[cur] = true;
    append(path, subs_[cur], lastRaw, lastT0, lastT1);
    for (;;) {
      const std::optional<std::size_t> next = following(cur);
      // Close the loop where it came round, unless a piece starts nearer the end than the loop's
      // own start does (a corner arc shorter than the link tolerance would otherwise be left
      // over as a loop of its own).
      if (options_.closed && path.size() > 1) {
        const double home = (subs_[cur].seg.end - subs_[first].seg.start).norm();
        if (home <= link && (!next || home <= (subs_[*next].seg.start - subs_[cur].seg.end).norm())) break;
      }
      if (!next) break;
      cur = *next;
      used[cur] = true;
      append(path, subs_[cur], lastRaw, lastT0, lastT1);
    }
    result_.paths.push_back(std::move(path));
  }
}

// ---- 5. what the wire cannot reach --------------------------------------------------------------

void WireOffsetBuilder::findLost() {
  std::vector<std::size_t> dead;
  for (std::size_t k = 0; k < n_; ++k)
    if (!alive_[kept_[k]]) dead.push_back(k);
  if (dead.empty()) return;
  std::vector<Segment> cut;
  for (const auto& path : result_.paths)
    for (const WirePiece& p : path) cut.push_back(p.segment);
  std::vector<Box> cutBoxes(cut.size());
  for (std::size_t i = 0; i < cut.size(); ++i) cutBoxes[i] = cut[i].bounds();
  const detail::BoxTree cutTree(std::move(cutBoxes));
  // The least distance from p to what the wire cuts_: the pieces whose boxes come within r of p,
  // r doubled until one of them lies within r (then no piece farther out can be nearer). The same
  // minimum as over every piece, without a pass over all of them for each point of a lost element.
  auto nearestCut = [&](const Vec2& p) {
    double nearest = std::numeric_limits<double>::infinity();
    if (cut.empty()) return nearest;
    Box at;
    at.add(p);
    for (double r = std::max(dist_, 1e-3);; r *= 2) {
      cutTree.visitOverlapping(at, r, [&](std::size_t c) { nearest = std::min(nearest, cut[c].distanceTo(p)); });
      if (nearest <= r || !std::isfinite(r)) return nearest;
    }
  };
  auto farthest = [&](std::size_t element, Vec2& where) {
    double worst = -1;
    for (int s = 0; s <= 8; ++s) {
      const Vec2 p = contour_[element].pointAt(s / 8.0);
      const double nearest = nearestCut(p);
      if (nearest > worst) worst = nearest, where = p;
    }
    return worst;
  };
  std::size_t r = 0;
  // On a closed contour_ a run may wrap from the last element to the first: start after a live one.
  std::size_t begin = 0;
  if (options_.closed && dead.size() < n_) {
    while (begin < dead.size() && dead[begin] == begin) ++begin;
    if (begin == dead.size()) begin = 0;
  }
  std::vector<std::size_t> order(dead.begin() + static_cast<std::ptrdiff_t>(begin), dead.end());
  order.insert(order.end(), dead.begin(), dead.begin() + static_cast<std::ptrdiff_t>(begin));
  while (r < order.size()) {
    std::size_t e = r + 1;
    while (e < order.size() && order[e] == (order[e - 1] + 1) % n_) ++e;
    LostRun run;
    run.first = kept_[order[r]];
    run.count = e - r;
    run.uncut = -1;
    for (std::size_t q = r; q < e; ++q) {
      Vec2 where = Vec2::Zero();
      const double far = farthest(kept_[order[q]], where);
      if (far - dist_ > run.uncut) run.uncut = far - dist_, run.where = where;
    }
    if (!std::isfinite(run.uncut)) run.uncut = 0;
    const Segment& s0 = contour_[run.first];
    run.fillet = run.count == 1 && s0.isArc() && s0.radius() < dist_ && (d_ > 0) == (s0.sweep > 0);
    result_.lost.push_back(run);
    r = e;
  }
}

}  // namespace

// ---- 6. the entry point -------------------------------------------------------------------------

WireOffsetResult wireOffset(std::span<const Segment> contour, double d, const WireOffsetOptions& options) {
  return WireOffsetBuilder(contour, d, options).run();
}

}  // namespace kerf::geometry
