#include "kerf/geometry/deviation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace kerf::geometry {

namespace {

/// About this many chords per grid cell on average.
constexpr double kChordsPerCell = 2.0;
/// The grid never has more cells than this, whatever the spread of the chords.
constexpr double kMostCells = 1 << 20;
/// An element's arc is halved into pieces of at most this sweep first (the tangent triangle needs
/// pieces well under a half turn).
constexpr double kMostPieceSweep = kPi / 4;

double distanceToChord(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double l2 = ab.squaredNorm();
  const double t = l2 > 0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

}  // namespace

DeviationSet::DeviationSet(SegmentView segments, double chordDeviation, std::size_t maxChords)
    : segments_(segments.begin(), segments.end()), chordDeviation_(chordDeviation) {
  for (std::size_t k = 0; k < segments.size(); ++k) {
    const Segment& s = segments[k];
    if (!s.isArc()) {
      chords_.push_back({s.start, s.end, k});
      continue;
    }
    // A chord of sweep a on radius r stands at most r (1 - cos(a / 2)) off its arc.
    const double r = std::max(s.radius(), 1e-12);
    const double most = 2.0 * std::acos(std::clamp(1.0 - chordDeviation / r, -1.0, 1.0));
    const double pieces = std::ceil(std::abs(s.sweep) / std::max(most, 1e-9));
    if (!(pieces <= static_cast<double>(maxChords)) || chords_.size() + static_cast<std::size_t>(pieces) > maxChords) {
      ok_ = false;
      return;
    }
    const auto n = std::max<std::size_t>(1, static_cast<std::size_t>(pieces));
    Vec2 prev = s.start;
    for (std::size_t i = 1; i <= n; ++i) {
      const Vec2 next = i == n ? s.end : s.pointAt(static_cast<double>(i) / static_cast<double>(n));
      chords_.push_back({prev, next, k});
      prev = next;
    }
  }
  if (chords_.empty()) return;
  for (const Chord& c : chords_) {
    box_.add(c.a);
    box_.add(c.b);
  }
  const double w = std::max(box_.max.x() - box_.min.x(), 1e-9), h = std::max(box_.max.y() - box_.min.y(), 1e-9);
  const double cells = std::min(kMostCells, static_cast<double>(chords_.size()) / kChordsPerCell + 1);
  cell_ = std::max(std::sqrt(w * h / cells), std::max(w, h) / 1024.0);
  nx_ = static_cast<std::size_t>(std::ceil(w / cell_)) + 1;
  ny_ = static_cast<std::size_t>(std::ceil(h / cell_)) + 1;
  cells_.resize(nx_ * ny_);
  for (std::size_t k = 0; k < chords_.size(); ++k) {
    const Chord& c = chords_[k];
    const std::size_t x0 = cellOf(std::min(c.a.x(), c.b.x()), box_.min.x(), nx_);
    const std::size_t x1 = cellOf(std::max(c.a.x(), c.b.x()), box_.min.x(), nx_);
    const std::size_t y0 = cellOf(std::min(c.a.y(), c.b.y()), box_.min.y(), ny_);
    const std::size_t y1 = cellOf(std::max(c.a.y(), c.b.y()), box_.min.y(), ny_);
    for (std::size_t y = y0; y <= y1; ++y)
      for (std::size_t x = x0; x <= x1; ++x) cells_[y * nx_ + x].push_back(k);
  }
}

std::size_t DeviationSet::cellOf(double v, double lo, std::size_t n) const {
  const double c = std::floor((v - lo) / cell_);
  return static_cast<std::size_t>(std::clamp(c, 0.0, static_cast<double>(n - 1)));
}

double DeviationSet::distanceTo(const Vec2& p, std::size_t chord) const {
  return distanceToChord(p, chords_[chord].a, chords_[chord].b);
}

DeviationSet::Hit DeviationSet::nearest(const Vec2& p) const {
  Hit best{std::numeric_limits<double>::infinity(), 0};
  if (chords_.empty()) return best;
  // Rings of cells around p's cell (p clamped into the grid): a chord not yet seen lies in ring r
  // or beyond, at least (r - 1) cells away from the clamped point, and p is at least its distance
  // outside the grid away from any of it.
  const long cx = static_cast<long>(cellOf(p.x(), box_.min.x(), nx_));
  const long cy = static_cast<long>(cellOf(p.y(), box_.min.y(), ny_));
  const double outside = std::hypot(std::max({box_.min.x() - p.x(), 0.0, p.x() - box_.max.x()}),
                                    std::max({box_.min.y() - p.y(), 0.0, p.y() - box_.max.y()}));
  auto visit = [&](long x, long y) {
    if (x < 0 || y < 0 || x >= static_cast<long>(nx_) || y >= static_cast<long>(ny_)) return;
    for (const std::size_t k : cells_[static_cast<std::size_t>(y) * nx_ + static_cast<std::size_t>(x)]) {
      const double d = distanceTo(p, k);
      if (d < best.distance || (d == best.distance && k < best.chord)) best = {d, k};
    }
  };
  const long rings = static_cast<long>(std::max(nx_, ny_));
  for (long r = 0; r <= rings; ++r) {
    if (r >= 1 && std::max(outside, static_cast<double>(r - 1) * cell_) > best.distance) break;
    for (long x = cx - r; x <= cx + r; ++x) {
      visit(x, cy - r);
      if (r > 0) visit(x, cy + r);
    }
    for (long y = cy - r + 1; y <= cy + r - 1; ++y) {
      visit(cx - r, y);
      if (r > 0) visit(cx + r, y);
    }
  }
  return best;
}

Farthest farthestFrom(const Segment& s, const DeviationSet& set, double precision) {
  Farthest out;
  if (set.empty()) {
    out.distance = std::numeric_limits<double>::infinity();
    out.at = s.start;
    return out;
  }
  const double length = s.length();
  out.distance = -1.0;
  auto probe = [&](double t) {
    const Vec2 p = s.pointAt(t);
    const DeviationSet::Hit h = set.nearest(p);
    const double exact = set.ownerDistance(p, h.chord);
    if (exact > out.distance) {
      out.distance = exact;
      out.at = p;
      out.nearest = set.chord(h.chord).owner;
    }
    return h.chord;
  };
  // The meeting point of the arc's tangents at parameters t0 and t1 (the piece lies in the triangle
  // of it and the two end points); a line piece has none.
  auto apex = [&](double t0, double t1) -> std::optional<Vec2> {
    if (!s.isArc()) return std::nullopt;
    const double half = 0.5 * (t1 - t0) * std::abs(s.sweep);
    const Vec2 mid = s.pointAt(0.5 * (t0 + t1));
    return s.centre + (mid - s.centre) / std::cos(half);
  };
  struct Piece {
    double t0, t1;
  };
  std::vector<Piece> open;
  const auto first = static_cast<std::size_t>(std::max(1.0, std::ceil(std::abs(s.sweep) / kMostPieceSweep)));
  for (std::size_t i = 0; i < first; ++i)
    open.push_back(
        {static_cast<double>(i) / static_cast<double>(first), static_cast<double>(i + 1) / static_cast<double>(first)});
  for (const Piece& q : open) probe(q.t0);
  probe(1.0);
  const double shortest = precision / std::max(length, precision);  // a piece this short is not halved
  while (!open.empty()) {
    const Piece q = open.back();
    open.pop_back();
    const std::size_t c = probe(0.5 * (q.t0 + q.t1));
    double bound = std::max(set.distanceTo(s.pointAt(q.t0), c), set.distanceTo(s.pointAt(q.t1), c));
    if (const std::optional<Vec2> top = apex(q.t0, q.t1)) bound = std::max(bound, set.distanceTo(*top, c));
    if (bound <= out.distance + precision || q.t1 - q.t0 <= shortest) continue;
    const double tm = 0.5 * (q.t0 + q.t1);
    open.push_back({q.t0, tm});
    open.push_back({tm, q.t1});
  }
  return out;
}

}  // namespace kerf::geometry
