// Self-intersection of paths of lines and arcs, exact (intersection.h): the primitive
// intersections (line-line, line-arc, arc-arc), the classification of a pair within a path, the
// decision sweep (Shamos-Hoey over x-monotone pieces) and the report sweep over boxes.
// Sections: 1. primitive intersections  2. classification  3. decision sweep  4. report sweep
#include "kerf/geometry/intersection.h"

#include "angles.h"
#include "kerf/geometry/float_steps.h"
#include "kerf/geometry/parallel.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <memory>
#include <memory_resource>
#include <mutex>
#include <numeric>
#include <optional>
#include <set>
#include <stdexcept>
#include <type_traits>
#include <utility>

namespace kerf::geometry {
namespace {

// ---- 1. primitive intersections -------------------------------------------------------------

bool near(const Vec2& p, const Vec2& q, double tol) { return (p - q).norm() <= tol; }

void addPoint(SegmentIntersection& r, const Vec2& p, double tol) {
  for (int i = 0; i < r.count; ++i)
    if ((r.points[i] - p).norm() <= tol) return;
  if (r.count < 2) r.points[r.count++] = p;
}

SegmentIntersection lineLine(const Segment& a, const Segment& b, double tol) {
  SegmentIntersection r;
  const Vec2 p = a.start, q = b.start;
  const Vec2 ra = a.end - a.start, sb = b.end - b.start;
  const double la = ra.norm(), lb = sb.norm();
  const double denom = cross(ra, sb);
  const Vec2 qp = q - p;
  if (std::abs(denom) <= 1e-12 * la * lb) {
    // Parallel: only collinear ones can meet.
    if (std::abs(cross(qp, ra)) / la > tol) return r;
    const double t0 = qp.dot(ra) / (la * la);
    const double t1 = (b.end - p).dot(ra) / (la * la);
    const double lo = std::max(0.0, std::min(t0, t1));
    const double hi = std::min(1.0, std::max(t0, t1));
    if ((hi - lo) * la > tol) {
      r.overlap = true;
      addPoint(r, p + lo * ra, tol);
      addPoint(r, p + hi * ra, tol);
    } else if (hi - lo >= -tol / la) {
      addPoint(r, p + std::clamp((lo + hi) / 2, 0.0, 1.0) * ra, tol);
    }
    return r;
  }
  const double t = cross(qp, sb) / denom;
  const double u = cross(qp, ra) / denom;
  if (t < -tol / la || t > 1 + tol / la || u < -tol / lb || u > 1 + tol / lb) return r;
  addPoint(r, p + std::clamp(t, 0.0, 1.0) * ra, tol);
  return r;
}

SegmentIntersection lineArc(const Segment& line, const Segment& arc, double tol) {
  SegmentIntersection r;
  const Vec2 d = line.end - line.start;
  const double len2 = d.squaredNorm();
  const double len = std::sqrt(len2);
  const Vec2 f = line.start - arc.centre;
  const double t0 = -f.dot(d) / len2;  // foot of the perpendicular from the centre
  const double dist = (f + t0 * d).norm(), radius = arc.radius();
  if (dist > radius + tol) return r;
  double ts[2];
  int n = 0;
  if (std::abs(dist - radius) <= tol) {
    ts[n++] = t0;  // tangent
  } else {
    const double h = std::sqrt(std::max(0.0, radius * radius - dist * dist)) / len;
    ts[n++] = t0 - h;
    ts[n++] = t0 + h;
  }
  for (int i = 0; i < n; ++i) {
    if (ts[i] < -tol / len || ts[i] > 1 + tol / len) continue;
    const Vec2 pt = line.start + std::clamp(ts[i], 0.0, 1.0) * d;
    // Within tol of one of the arc's ends is on the arc, as onArc says (but for its own rounding at
    // exactly tol), without the angle: neighbours meet at such a point, every pair of them.
    if (near(pt, arc.start, tol) || near(pt, arc.end, tol) || detail::onArc(arc, pt, tol)) addPoint(r, pt, tol);
  }
  return r;
}

/// A counter-clockwise angular interval [from, from + span].
struct AngleInterval {
  double from;
  double span;
};

AngleInterval ccwInterval(const Segment& arc) {
  const double a0 = arc.startAngle();
  if (arc.sweep >= 0) return {detail::wrapPositive(a0), arc.sweep};
  return {detail::wrapPositive(a0 + arc.sweep), -arc.sweep};
}

SegmentIntersection arcArc(const Segment& a, const Segment& b, double tol) {
  SegmentIntersection r;
  const Vec2 dc = b.centre - a.centre;
  const double d = dc.norm(), ra = a.radius(), rb = b.radius();
  if (d <= tol && std::abs(ra - rb) <= tol) {
    // Same circle: shared stretches of the two angular intervals.
    const AngleInterval ia = ccwInterval(a), ib = ccwInterval(b);
    const double offset = detail::wrapPositive(ib.from - ia.from);
    double best = 0.0, bestFrom = 0.0, bestTo = 0.0;
    for (double o : {offset, offset - kTwoPi}) {
      const double lo = std::max(0.0, o), hi = std::min(ia.span, o + ib.span);
      if (hi - lo > best) {
        best = hi - lo;
        bestFrom = lo;
        bestTo = hi;
      }
    }
    if (best * ra > tol) {
      r.overlap = true;
      addPoint(r, a.centre + ra * direction(ia.from + bestFrom), tol);
      addPoint(r, a.centre + ra * direction(ia.from + bestTo), tol);
      return r;
    }
    // No shared stretch: they can still touch at end points.
    for (const Vec2& p : {b.start, b.end})
      if (detail::onArc(a, p, tol)) addPoint(r, p, tol);
    for (const Vec2& p : {a.start, a.end})
      if (detail::onArc(b, p, tol)) addPoint(r, p, tol);
    return r;
  }
  if (d > ra + rb + tol || d < std::abs(ra - rb) - tol || d == 0.0) return r;
  const double along = (ra * ra - rb * rb + d * d) / (2 * d);
  const double h2 = ra * ra - along * along;
  const Vec2 u = dc / d;
  const Vec2 base = a.centre + along * u;
  const Vec2 perp(-u.y(), u.x());
  const double h = h2 > 0 ? std::sqrt(h2) : 0.0;
  const Vec2 candidates[2] = {base + h * perp, base - h * perp};
  const int n = h <= tol ? 1 : 2;
  for (int i = 0; i < n; ++i)
    if (detail::onArc(a, candidates[i], tol) && detail::onArc(b, candidates[i], tol)) addPoint(r, candidates[i], tol);
  return r;
}

}  // namespace

SegmentIntersection intersect(const Segment& a, const Segment& b, double tol) {
  if (!a.isArc() && !b.isArc()) return lineLine(a, b, tol);
  if (!a.isArc()) return lineArc(a, b, tol);
  if (!b.isArc()) return lineArc(b, a, tol);
  return arcArc(a, b, tol);
}

namespace {

// ---- 2. classification ----------------------------------------------------------------------

bool atEnd(const Segment& s, const Vec2& p, double tol) { return near(s.start, p, tol) || near(s.end, p, tol); }

/// Do a and b run the same way along their shared stretch?
bool sameDirection(const Segment& a, const Segment& b, const Vec2& at) {
  auto tangentNear = [](const Segment& s, const Vec2& p) {
    if (!s.isArc()) return s.tangentAt(0.0);
    const Vec2 radial = (p - s.centre).normalized();
    return s.sweep >= 0 ? Vec2(-radial.y(), radial.x()) : Vec2(radial.y(), -radial.x());
  };
  return tangentNear(a, at).dot(tangentNear(b, at)) > 0;
}

/// A line and an arc that follow each other end to end at v (the line's other end lineEnd): true
/// when lineArc, within tol, finds them meeting at v alone, which classifyPair passes over as the
/// shared vertex, shown without it. Along the line from v, v + s (lineEnd - v), the carrier meets
/// the circle where W2 s^2 + 2 p s - e = 0 (g = v - centre, p = g.w, W2 = |w|^2, e = r^2 - |g|^2:
/// about 0, as v lies on the circle but for the arc's closing tolerance, which can be far more
/// than tol). With p > 0 the line leaves the circle's side of v: the far root, and the foot of the
/// perpendicular that lineArc takes for a tangent, lie behind v (s < 0), where lineArc skips them
/// or clamps them onto v itself. The near root lies behind v too when v is outside the circle
/// (e <= 0), else ahead of it by at most |e| |w| / p, which must stay within tol. Room for lineArc's
/// rounding (`slack`): a few units of rounding of the coordinates' size, magnified by up to
/// sqrt(r / tol) where the carrier is near tangent (the square root of r^2 - dist^2 > 2 r tol),
/// times 16, and a sixteenth of tol more. Neighbours like these are nearly all the pairs the box
/// sweep tests: a few products instead of lineArc.
bool meetOnlyAtVertex(const Segment& arc, const Vec2& v, const Vec2& lineEnd, double tol) {
  const Vec2 g = v - arc.centre, w = lineEnd - v;
  const double r = arc.radius();
  const double size = std::abs(v.x()) + std::abs(v.y()) + std::abs(arc.centre.x()) + std::abs(arc.centre.y()) +
                      std::abs(w.x()) + std::abs(w.y()) + r;
  if (!(tol > 0) || !(r > 0)) return false;
  const double slack = tol / 16 + 16 * std::numeric_limits<double>::epsilon() * size * (2 + std::sqrt(r / tol));
  if (!(slack < tol / 2)) return false;  // also a NaN
  const double p = g.dot(w), w2 = w.squaredNorm(), e = r * r - g.squaredNorm();
  if (!(p > 0) || !(w2 > 0)) return false;
  const double inner = tol - slack;
  return e <= 0 || e * e * w2 < inner * inner * p * p;
}

/// Appends the contacts of the pair (i, j), i < j.
void classifyPair(SegmentView path, std::size_t i, std::size_t j, bool adjacentForward, bool adjacentWrap, double tol,
                  std::vector<Contact>& out) {
  const Segment& a = path[i];
  const Segment& b = path[j];
  if (adjacentForward && !adjacentWrap && !a.isArc() && !b.isArc() && a.end == b.start) {
    // Two lines from one vertex at an angle (above 0.06 degrees: the carriers' crossing, computed,
    // lies within 1e-13 of a length of the vertex) meet there and nowhere else: a shared vertex,
    // no contact. Most pairs the sweep tests are such neighbours.
    const Vec2 ra = a.end - a.start, sb = b.end - b.start;
    if (std::abs(cross(ra, sb)) > 1e-3 * ra.norm() * sb.norm()) return;
  }
  if (adjacentForward && !adjacentWrap && a.isArc() != b.isArc() && a.end == b.start &&
      (a.isArc() ? meetOnlyAtVertex(a, a.end, b.end, tol) : meetOnlyAtVertex(b, a.end, a.start, tol)))
    return;
  const SegmentIntersection x = intersect(a, b, tol);
  if (x.count == 0) return;
  const bool adjacent = adjacentForward || adjacentWrap;
  Contact c;
  c.first = i;
  c.second = j;
  c.adjacent = adjacent;
  if (x.overlap) {
    c.kind = ContactKind::Overlap;
    // The middle of the shared stretch's ends; a stretch that is a whole circle has one end (the
    // second point was read uninitialised here: a stack's leftovers, a different "near" point
    // from run to run; found by the fuzz target's two readings disagreeing).
    c.point = x.count == 2 ? Vec2((x.points[0] + x.points[1]) / 2) : x.points[0];
    c.opposite = !sameDirection(a, b, c.point);
    out.push_back(c);
    return;
  }
  for (int k = 0; k < x.count; ++k) {
    const Vec2& p = x.points[k];
    if (adjacentForward && near(p, a.end, tol) && near(p, b.start, tol)) continue;  // shared vertex
    if (adjacentWrap && near(p, b.end, tol) && near(p, a.start, tol)) continue;
    const bool endA = atEnd(a, p, tol), endB = atEnd(b, p, tol);
    // End meets end: a vertex visited twice (lead-in and lead-out), or two neighbours that
    // close a loop between them (two half circles). Neither cuts through anything.
    if (endA && endB) continue;
    c.kind = (endA || endB) ? ContactKind::Touch : ContactKind::Crossing;
    c.point = p;
    out.push_back(c);
  }
}

}  // namespace

// ---- 3. decision sweep ------------------------------------------------------------------------
//
// Shamos and Hoey's sweep (1976): a vertical line swept left to right over x-monotone pieces (a
// line, or an arc split where its x turns), the pieces it crosses kept ordered by y; a piece is
// tested only against the pieces next to it when it enters, and the two that become neighbours
// when one leaves. If no tested pair touches, no pair does: the leftmost contact would have made
// its two pieces neighbours before the sweep reached it. O(n log n) whatever the shape — a star of
// long spikes, whose boxes all overlap, included. A vertical line crosses the sweep at one x: it
// is tested against the pieces in its y range there, and against the points that arrive at that
// x inside it.

namespace {

struct Piece {
  std::uint32_t seg = 0;
  std::uint32_t index = 0;  // its place in the sweep's list of pieces
  Vec2 left, right;         // by (x, y)
  double slope = 0.0;       // a line's dy/dx (not vertical)
  bool arc = false;
  bool upper = false;  // arc: the half above the centre
  [[nodiscard]] bool vertical() const { return !arc && left.x() == right.x(); }
};

double yAt(const Piece& p, const Segment& s, double x) {
  if (x <= p.left.x()) return p.left.y();
  if (x >= p.right.x()) return p.right.y();
  if (!p.arc) return p.left.y() + (x - p.left.x()) * p.slope;
  const double dx = x - s.centre.x(), r = s.radius();
  const double h = std::sqrt(std::max(0.0, r * r - dx * dx));
  return s.centre.y() + (p.upper ? h : -h);
}

/// dy/dx just right of x (the order of pieces that leave one point).
double slopeAt(const Piece& p, const Segment& s, double x) {
  if (!p.arc) return p.slope;
  const double dx = x - s.centre.x(), r = s.radius();
  const double h = std::sqrt(std::max(0.0, r * r - dx * dx));
  // Where x turns, the slope is infinite: upwards from the circle's left point on the upper half,
  // downwards on the lower; the other way round at its right point.
  if (h <= 1e-300) return (p.upper == (dx < 0)) ? 1e300 : -1e300;
  return p.upper ? -dx / h : dx / h;
}

/// The x-monotone pieces of a segment, in order (a line is one; an arc is split where its x
/// turns, into at most four), each passed to f. The same segment gives the same pieces bit for bit,
/// so the sweep makes a piece again when it enters rather than keeping them all.
template <typename F>
void forEachPiece(const Segment& s, std::uint32_t index, F&& f) {
  auto lexLess = [](const Vec2& a, const Vec2& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); };
  auto add = [&](const Vec2& a, const Vec2& b, bool arc, bool upper) {
    Piece p;
    p.seg = index;
    p.left = lexLess(b, a) ? b : a;
    p.right = lexLess(b, a) ? a : b;
    p.arc = arc;
    p.upper = upper;
    if (!arc && p.right.x() != p.left.x()) p.slope = (p.right.y() - p.left.y()) / (p.right.x() - p.left.x());
    f(p);
  };
  if (!s.isArc()) {
    add(s.start, s.end, false, false);
    return;
  }
  // Split where x turns: at the circle's rightmost and leftmost points (the axis directions 0 and
  // pi), taken exactly, in the order a counter-clockwise walk from the arc's first end in that
  // sense (the start of a counter-clockwise arc, the end of a clockwise one) meets them. Which axes
  // the walk passes comes from the ends' quadrants (detail::axesPassed), or from the angle of the
  // first end where those disagree with the sweep; no axis on which the walk starts or stops.
  const bool ccw = s.sweep >= 0;
  const Vec2 &from = ccw ? s.start : s.end, &to = ccw ? s.end : s.start;
  const Vec2 a = from - s.centre, e = to - s.centre;
  const double w = std::abs(s.sweep);
  int quadrant = detail::quadrantOf(a);  // where the walk is
  int axes = w < kTwoPi ? detail::axesPassed(quadrant, e, w) : -1;
  if (axes >= 0) {
    if (axes > 0 && e.y() == 0 && (quadrant + axes) % 2 == 0) --axes;  // `to` lies on the last x axis
  } else {
    const double angle = detail::wrapPositive(angleOf(a));
    quadrant = std::min(3, static_cast<int>(angle / (kPi / 2)));
    axes = 0;
    while (axes < 5 && (quadrant + axes + 1) * (kPi / 2) - angle < w) ++axes;
  }
  const double r = s.radius();
  Vec2 last = from;
  bool upper = quadrant < 2;  // the half the walk is in: it changes at each x axis
  int cuts = 0;
  for (int k = 1; k <= axes && cuts < 3; ++k) {  // at most 4 pieces: 2 bits
    const int axis = (quadrant + k) % 4;
    if (axis % 2 != 0) continue;
    const Vec2 cut(s.centre.x() + (axis == 0 ? r : -r), s.centre.y());
    add(last, cut, true, upper);
    last = cut;
    upper = !upper;
    ++cuts;
  }
  add(last, to, true, upper);
}

/// Piece `sub` of a segment (forEachPiece's order).
Piece pieceOf(const Segment& s, std::uint32_t index, unsigned sub) {
  Piece out;
  unsigned k = 0;
  forEachPiece(s, index, [&](const Piece& p) {
    if (k++ == sub) out = p;
  });
  return out;
}

/// A piece where the sweep stands: its y there and, to break a tie, its slope just right of it,
/// with its index for the last tie.
struct Place {
  double y, slope;
  std::uint32_t piece;
};

/// The order of the pieces along the sweep line (y there, then slope just right of it, then
/// index), which also places a Place among them. The tree keeps copies of the pieces, so a
/// comparison reads the node it is at and nothing else (a line's y needs only its own numbers; an
/// arc's also its segment); the slopes are worked out only on a tie.
template <typename Y, typename Slope>
struct OrderAtSweep {
  Y& y;
  Slope& slope;
  using is_transparent = void;
  bool operator()(const Piece& a, const Piece& b) const {
    if (a.index == b.index) return false;
    const double ya = y(a), yb = y(b);
    if (ya != yb) return ya < yb;
    const double ma = slope(a), mb = slope(b);
    return ma != mb ? ma < mb : a.index < b.index;
  }
  bool operator()(const Place& a, const Piece& b) const {
    if (a.piece == b.index) return false;
    const double yb = y(b);
    if (a.y != yb) return a.y < yb;
    const double mb = slope(b);
    return a.slope != mb ? a.slope < mb : a.piece < b.index;
  }
  bool operator()(const Piece& a, const Place& b) const {
    if (a.index == b.piece) return false;
    const double ya = y(a);
    if (ya != b.y) return ya < b.y;
    const double ma = slope(a);
    return ma != b.slope ? ma < b.slope : a.index < b.piece;
  }
};

/// Drops nothing: the decision sweep stops at the first pair that touches.
struct StopAtContact {
  std::optional<std::uint32_t> operator()(std::uint32_t, std::uint32_t) const { return std::nullopt; }
  [[nodiscard]] bool full() const { return true; }
};

/// The decision sweep's events: every live segment's x-monotone pieces (forEachPiece), their ends in
/// the sweep's order: by x, then y, then the first entry (two events at one point are two paths
/// through it, each entry names a piece's end once: the order is total, so any sort gives the
/// same). Made once for a search and read by each of its sweeps — the decision sweep and every
/// dropping sweep after it (which pass the pieces of segments dropped since by).
///
/// The events are distributed into buckets by x — slices of [least x, greatest x], taken through a
/// monotone map, so a bucket's events all precede the next bucket's — and each bucket is sorted
/// alone, the first time a sweep reads into it (from): a sweep that stops at an early contact, as
/// on a path that crosses itself near its left end, sorts only the buckets it reached. A path's
/// events spread over its extent: the buckets hold four on average and the whole is about linear,
/// where a comparison sort of n events costs n log n comparisons (most of the decision sweep's
/// work on a tangled walk). Events that pile into one bucket (a path of one x) are sorted there as
/// the whole was.
class SweepEvents {
 public:
  static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
  // An event: a point where one or two pieces enter or leave the sweep. Neighbouring pieces of a
  // path share their joint, so one event serves both and a closed path of n pieces sorts about n
  // events, not 2n. An entry is piece << 3 | sub-piece of its segment << 1 | enters.
  struct Event {
    double x, y;  // plain doubles: 24 bytes, not the 32 an aligned Vec2 would make it
    std::uint32_t entry[2];
  };
  /// Piece -> its segment, then the probe's none; null when every segment is live and a line (then
  /// piece k is segment k: 4 bytes a piece saved). Room for every piece there can be, each entry
  /// written as its piece is made (room never written takes no memory).
  std::unique_ptr<std::uint32_t[]> pieceSeg;
  bool identity = true;
  std::uint32_t probeIndex = 0;  ///< the index after the last piece: the probe's
  [[nodiscard]] std::uint32_t segOf(std::uint32_t piece) const { return identity ? piece : pieceSeg[piece]; }

  /// Where makeSweepEvents puts the events, in any order, before order() buckets them.
  std::vector<Event>& unordered() { return events_; }
  /// Distributes the events into their buckets (the sweeps' reads sort each).
  [[gnu::noinline]] void order();
  [[nodiscard]] std::size_t size() const { return events_.size(); }
  /// The events from g on: event g and every event at its point in the sweep's order (the bucket
  /// that holds them sorted: a bucket is a range of x, so one point's events share one). Those
  /// after them may not be in order yet, but none of them lies at that point.
  const Event* from(std::size_t g) {
    if (g >= sortedEnd_) sortThrough(g);
    return events_.data();
  }

 private:
  struct Less {
    bool operator()(const Event& a, const Event& b) const {
      return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.entry[0] < b.entry[0];
    }
  };
  /// Sorts the buckets up to the one that holds event i. Out of line: the sweep's loop only
  /// compares with sortedEnd_.
  [[gnu::noinline]] void sortThrough(std::size_t i) {
    while (sortedEnd_ <= i && next_ < bucketEnd_.size()) {
      const std::size_t stop = bucketEnd_[next_++];
      if (stop - sortedEnd_ > 1) std::sort(events_.begin() + sortedEnd_, events_.begin() + stop, Less{});
      sortedEnd_ = stop;
    }
  }

  std::vector<Event> events_;
  std::vector<std::uint32_t> bucketEnd_;  // where each bucket's events end
  std::size_t next_ = 0;                  // the first bucket not sorted yet
  std::size_t sortedEnd_ = 0;             // the events before this one are in the sweep's order
};

void SweepEvents::order() {
  const std::size_t n = events_.size();
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Event& e : events_) {
    lo = std::min(lo, e.x);
    hi = std::max(hi, e.x);
  }
  const std::size_t buckets = std::bit_ceil(std::max<std::size_t>(n / 4, 1));
  const double scale = static_cast<double>(buckets) / (hi - lo);
  if (n < 16 || !(hi > lo) || !std::isfinite(scale)) {  // a few, or one x: the comparison sort
    geometry::parallelSort(events_.begin(), events_.end(), Less{});
    sortedEnd_ = n;
    return;
  }
  // (x - lo) * scale rounds monotonically, and so does the truncation: a larger x never takes an
  // earlier bucket. The last bucket also takes x = hi (and what rounding puts past it).
  const auto last = static_cast<std::uint32_t>(buckets - 1);
  const auto bucketOf = [&](const Event& e) {
    const double t = (e.x - lo) * scale;
    return t < static_cast<double>(last) ? static_cast<std::uint32_t>(t) : last;
  };
  // end[b] counts bucket b's events, then (summed) is where the bucket ends; the events placed
  // from the last back, it is where the bucket starts.
  std::vector<std::uint32_t>& end = bucketEnd_;
  end.assign(buckets, 0);
  for (const Event& e : events_) ++end[bucketOf(e)];
  std::uint32_t at = 0;
  for (std::uint32_t& b : end) at = b += at;
  std::vector<Event> placed(n);
  for (auto e = events_.rbegin(); e != events_.rend(); ++e) placed[--end[bucketOf(*e)]] = *e;
  // Where each bucket ends: where the next starts, and the last at n.
  std::rotate(end.begin(), end.begin() + 1, end.end());
  end.back() = static_cast<std::uint32_t>(n);
  events_.swap(placed);
}

template <typename IsLive>
SweepEvents makeSweepEvents(SegmentView path, std::size_t live, IsLive& isLive) {
  using Event = SweepEvents::Event;
  SweepEvents out;
  std::size_t arcs = 0;
  for (std::size_t i = 0; i < path.size(); ++i) arcs += path[i].isArc() && isLive(i);
  out.identity = live == path.size() && arcs == 0;
  // Room for every piece and event there can be (an arc has four pieces at most, a piece two
  // ends), so that they are never copied while they grow: room never written takes no memory.
  const std::size_t most = live + 3 * arcs;
  if (!out.identity) out.pieceSeg.reset(new std::uint32_t[most + 1]);
  std::vector<Event>& events = out.unordered();
  events.reserve(2 * most);
  std::size_t pieces = 0;
  std::size_t previous[2] = {SIZE_MAX, SIZE_MAX};  // the events of the previous piece's ends
  for (std::uint32_t i = 0; i < path.size(); ++i) {
    if (!isLive(i)) continue;
    unsigned sub = 0;
    forEachPiece(path[i], i, [&](const Piece& piece) {
      const std::size_t k = pieces++;
      if (k >= (std::size_t{1} << 29)) throw std::length_error("findSelfIntersections: more than 2^29 pieces");
      if (!out.identity) out.pieceSeg[k] = i;
      std::size_t mine[2];
      for (int end = 0; end < 2; ++end) {
        const Vec2& at = end == 0 ? piece.left : piece.right;
        const std::uint32_t entry = static_cast<std::uint32_t>(k) << 3 | sub << 1 | (end == 0 ? 1u : 0u);
        mine[end] = SIZE_MAX;
        for (const std::size_t e : previous)
          if (e != SIZE_MAX && events[e].entry[1] == SweepEvents::kNone && events[e].x == at.x() &&
              events[e].y == at.y()) {
            events[e].entry[1] = entry;
            mine[end] = e;
            break;
          }
        if (mine[end] == SIZE_MAX) {
          events.push_back({at.x(), at.y(), {entry, SweepEvents::kNone}});
          mine[end] = events.size() - 1;
        }
      }
      previous[0] = mine[0];
      previous[1] = mine[1];
      ++sub;
    });
  }
  out.order();
  out.probeIndex = static_cast<std::uint32_t>(pieces);
  if (!out.identity) out.pieceSeg[pieces] = std::numeric_limits<std::uint32_t>::max();
  return out;
}

/// The decision sweep, in its stages: the events (SweepEvents), then each event's pieces entering
/// (enter) and leaving (leave) the order along the sweep line, each new pair of neighbours tested.
///
/// run() is true when no pair of the live segments (isLive) touches (`touches` decides a pair
/// exactly); tested counts the pairs it asked about. With kDrop, a pair that touches does not end
/// the sweep: drop(a, b) is told (it lists the contacts of one of the two segments with every
/// other, and makes it not live) and names the segment it dropped; that segment's pieces leave the
/// order at the end of the event (leaveDropped), as if they ended there, and the sweep goes on. It
/// stops when drop.full() (enough contacts listed). The order may then be wrong past a contact the
/// sweep did not see: a sweep that dropped something proves nothing, and findSelfIntersections
/// sweeps again until one drops nothing.
///
/// The pieces are not kept: each is made again from its segment when it enters, and the sweep
/// holds only those it crosses. Per piece, what stays is its segment (4 bytes, none for a path of
/// lines), its place in the order (8) and its share of an event (24): at most 36 bytes.
template <bool kDrop, typename IsLive, typename Touches, typename Drop>
class DecisionSweep {
 public:
  DecisionSweep(SegmentView path, SweepEvents& events, IsLive& isLive, Touches& touches, double near,
                std::size_t& tested, Drop& drop)
      : path_(path), shared_(events), isLive_(isLive), touches_(touches), near_(near), tested_(tested), drop_(drop) {}

  bool run() {
    probe_.seg = std::numeric_limits<std::uint32_t>::max();
    probe_.index = shared_.probeIndex;
    where_.assign(std::size_t{shared_.probeIndex} + 1, order_.end());
    const std::size_t n = shared_.size();
    for (std::size_t g = 0; g < n;) {
      const SweepEvents::Event* events = shared_.from(g);
      const Vec2 at(events[g].x, events[g].y);
      std::size_t h = g + 1;
      while (h < n && events[h].x == at.x() && events[h].y == at.y()) ++h;
      sweepX_ = at.x();
      if (sweepX_ != verticalsX_) {
        verticals_.clear();
        verticalsX_ = sweepX_;
      }
      // At one point the pieces enter before any leaves, so that everything meeting there is in
      // the order at once.
      for (std::size_t e = g; e < h; ++e)
        for (const std::uint32_t entry : events[e].entry)
          if (entry != kNone && (entry & 1u) && !enter(entry >> 3, (entry >> 1) & 3u, at)) return false;
      for (std::size_t e = g; e < h; ++e)
        for (const std::uint32_t entry : events[e].entry)
          if (entry != kNone && !(entry & 1u) && !leave(entry >> 3, at)) return false;
      if constexpr (kDrop)
        if (!leaveDropped()) return false;
      g = h;
    }
    return true;
  }

 private:
  static constexpr std::uint32_t kNone = SweepEvents::kNone;

  [[nodiscard]] std::uint32_t segOf(std::uint32_t piece) const { return shared_.segOf(piece); }
  // The probe is a line: its segment unused.
  double yNow(const Piece& p) const {
    return p.vertical() ? p.left.y() : yAt(p, p.arc ? path_[p.seg] : path_[0], sweepX_);
  }
  double slopeNow(const Piece& p) const {
    return p.vertical() ? 1e300 : slopeAt(p, p.arc ? path_[p.seg] : path_[0], sweepX_);
  }

  /// Whether the pieces a and b touch (with kDrop: whether the sweep must stop).
  bool test(std::uint32_t a, std::uint32_t b) {
    if (segOf(a) == segOf(b)) return false;  // two pieces of one arc meet where it turns
    if constexpr (kDrop) {
      if (stop_) return true;
      if (!isLive_(segOf(a)) || !isLive_(segOf(b))) return false;  // dropped during this event
    }
    ++tested_;
    if (!touches_(segOf(a), segOf(b))) return false;
    if constexpr (kDrop) {
      const std::optional<std::uint32_t> gone = drop_(segOf(a), segOf(b));
      if (drop_.full()) {
        stop_ = true;
        return true;
      }
      if (gone) leaving_.push_back(*gone == segOf(a) ? a : b);
      return false;
    } else {
      return true;
    }
  }

  /// A piece leaves at `at`: its neighbours become neighbours. False when they touch. A neighbour
  /// within `near` of the point (another piece through it) may have hidden a piece beyond it that
  /// touches this one there: those are tested too, up to the first piece farther away.
  bool leave(std::uint32_t piece, const Vec2& at) {
    const auto it = where_[piece];
    if (it == order_.end()) return true;  // a vertical piece: never in the order
    if (it != order_.begin()) {
      auto q = std::prev(it);
      while (q != order_.begin() && yNow(*q) >= at.y() - near_) {
        --q;
        if (test(q->index, piece)) return false;
      }
    }
    for (auto q = std::next(it); q != order_.end() && yNow(*q) <= at.y() + near_;) {
      if (++q == order_.end()) break;
      if (test(piece, q->index)) return false;
    }
    if (it != order_.begin() && std::next(it) != order_.end() && test(std::prev(it)->index, std::next(it)->index))
      return false;
    order_.erase(it);
    if constexpr (kDrop) where_[piece] = order_.end();  // it may be dropped, or leave, later again
    return true;
  }

  /// A vertical piece enters: everything the sweep holds within its y range at this x.
  bool enterVertical(const Piece& p, std::uint32_t piece) {
    for (const Piece& v : verticals_)
      if (test(v.index, piece)) return false;
    // The probe at the range's foot finds where it starts.
    probe_.left = Vec2(sweepX_, p.left.y() - 1e-9);
    probe_.right = Vec2(sweepX_ + 1.0, p.left.y() - 1e-9);
    for (auto q = order_.lower_bound(probe_); q != order_.end(); ++q) {
      if (yNow(*q) > p.right.y() + 1e-9) break;
      if (test(q->index, piece)) return false;
    }
    verticals_.push_back(p);
    return true;
  }

  /// A piece enters at `at`: tested against its new neighbours. False when one touches it.
  bool enter(std::uint32_t piece, unsigned sub, const Vec2& at) {
    if constexpr (kDrop)
      if (!isLive_(segOf(piece))) return true;  // dropped before it entered
    Piece p = pieceOf(path_[segOf(piece)], segOf(piece), sub);
    p.index = piece;
    // A point arriving at this x inside a vertical line there. Points arrive by y, so a line that
    // ends below this one is done with (a long vertical drawn in many pieces stays a short list).
    std::erase_if(verticals_, [&](const Piece& v) { return v.right.y() < at.y() - 1e-9; });
    for (const Piece& v : verticals_)
      if (at.y() >= v.left.y() - 1e-9 && at.y() <= v.right.y() + 1e-9 && test(v.index, piece)) return false;
    if (p.vertical()) return enterVertical(p, piece);
    // Found with its own place computed once (heterogeneous lookup), not again at every node.
    const auto it = order_.emplace_hint(order_.lower_bound(Place{yNow(p), slopeNow(p), p.index}), p);
    where_[piece] = it;
    // Its neighbours, and past them every piece still within `near` of the point: pieces that
    // pass through one point (a shared vertex) must not hide from it a piece that touches it
    // within the tolerance (their own contact with that piece may be excused: a joint).
    for (auto q = it; q != order_.begin();) {
      --q;
      if (test(q->index, piece)) return false;
      if (yNow(*q) < at.y() - near_) break;
    }
    for (auto q = std::next(it); q != order_.end(); ++q) {
      if (test(piece, q->index)) return false;
      if (yNow(*q) > at.y() + near_) break;
    }
    return true;
  }

  /// kDrop: the dropped segments' pieces in the order (an arc's pieces are numbered in a row)
  /// leave it here; their neighbours, now next to each other, are tested (and may drop more).
  bool leaveDropped() {
    while (!leaving_.empty()) {
      const std::uint32_t piece = leaving_.back();
      leaving_.pop_back();
      const std::uint32_t seg = segOf(piece);
      std::uint32_t first = piece, last = piece;
      while (first > 0 && segOf(first - 1) == seg) --first;
      while (last + 1 < shared_.probeIndex && segOf(last + 1) == seg) ++last;
      for (std::uint32_t q = first; q <= last; ++q)
        if (where_[q] != order_.end() && !leave(q, Vec2(sweepX_, yNow(*where_[q])))) return false;
    }
    return true;
  }

  struct YNow {
    const DecisionSweep* sweep;
    double operator()(const Piece& p) const { return sweep->yNow(p); }
  };
  struct SlopeNow {
    const DecisionSweep* sweep;
    double operator()(const Piece& p) const { return sweep->slopeNow(p); }
  };
  using Less = OrderAtSweep<const YNow, const SlopeNow>;

  SegmentView path_;
  SweepEvents& shared_;
  IsLive& isLive_;
  Touches& touches_;
  double near_;
  std::size_t& tested_;
  Drop& drop_;
  Piece probe_;  // a flat piece, to find where a vertical line's range starts
  double sweepX_ = 0.0;
  const YNow yNow_{this};
  const SlopeNow slopeNow_{this};
  // The nodes come from one arena: a million inserts and erases without a million allocations.
  std::pmr::unsynchronized_pool_resource arena_;
  std::pmr::set<Piece, Less> order_{Less{yNow_, slopeNow_}, &arena_};
  std::vector<typename std::pmr::set<Piece, Less>::iterator> where_;
  std::vector<Piece> verticals_;  // the vertical pieces at sweepX_
  double verticalsX_ = -std::numeric_limits<double>::infinity();
  std::vector<std::uint32_t> leaving_;  // kDrop: pieces of dropped segments, to leave the order
  bool stop_ = false;                   // kDrop: drop is full
};

/// True when no pair of the live segments touches (DecisionSweep, above).
template <bool kDrop = false, typename IsLive, typename Touches, typename Drop = StopAtContact>
bool sweepFindsNoContact(SegmentView path, SweepEvents& events, IsLive&& isLive, Touches&& touches, double near,
                         std::size_t& tested, Drop&& drop = Drop{}) {
  return DecisionSweep<kDrop, std::remove_reference_t<IsLive>, std::remove_reference_t<Touches>,
                       std::remove_reference_t<Drop>>(path, events, isLive, touches, near, tested, drop)
      .run();
}

}  // namespace

// ---- 4. report sweep --------------------------------------------------------------------------

namespace {

/// Both ends of line b lie on one side of line a's carrier, each farther than tol from it: the
/// two lines cannot meet within tol. (The cross products' rounding, about 1e-16 of |a| |b|, is far
/// below tol |a| for any part a wire machine holds.)
bool strictlyOneSide(const Segment& a, const Segment& b, double tol) {
  const Vec2 d = a.end - a.start;
  const double margin = tol * d.norm();
  const double s0 = cross(d, b.start - a.start), s1 = cross(d, b.end - a.start);
  return (s0 > margin && s1 > margin) || (s0 < -margin && s1 < -margin);
}

constexpr std::uint32_t kDead = std::numeric_limits<std::uint32_t>::max();  // a segment too short to test

/// A segment's box as the box sweep keeps it, in floats (half the memory of a Box), a filter that
/// never drops a pair whose boxes come within tol of each other (it only lets a few more through,
/// which the exact tests settle). The near sides are rounded down by more than a float step
/// (floatWellBelow); the far sides are moved out by the tolerance once, in doubles, and rounded up
/// the same way (reach > d(max) + tol by a float step). So whether two boxes come within tol is four
/// comparisons of floats: every pair with d(a.min) <= d(b.max) + tol on both axes both ways passes,
/// and a box leaves the active list only when reach < the entering box's min, which implies
/// d(max) < d(min) - tol: none leaves that the double test kept. The float step to spare makes two
/// points within the tolerance of each other, as (p - q).norm() <= tol computes it, lie in boxes
/// that meet by this test, whatever the rounding of that norm and of the test's own sums (a float
/// step is 2^29 times the double steps those are made of). The first loop found from the sweep's
/// pairs relies on it.
struct SweepBox {
  float minX, minY, reachX, reachY;
  static SweepBox around(const Box& b, double tol) {
    return {floatWellBelow(b.min.x()), floatWellBelow(b.min.y()), floatWellAbove(b.max.x() + tol),
            floatWellAbove(b.max.y() + tol)};
  }
  [[nodiscard]] bool meets(const SweepBox& b) const {
    return minX <= b.reachX && b.minX <= reachX && minY <= b.reachY && b.minY <= reachY;
  }
};

/// A float's place in the order of floats, as an unsigned integer: negative floats have their
/// bits reversed, positive ones the sign bit set. -0 counts as +0, as the comparison of floats has
/// it; a NaN (no coordinate is one) lands past +infinity.
std::uint32_t orderKey(float f) {
  const auto bits = std::bit_cast<std::uint32_t>(f == 0.0f ? 0.0f : f);
  return (bits & 0x80000000U) != 0 ? ~bits : bits | 0x80000000U;
}

/// A segment's place in the box sweep: the least x of its box (rounded down to a float), then its
/// index. Made in place by the extents pass.
struct XKey {
  float x;
  std::uint32_t seg;
  friend bool operator<(const XKey& a, const XKey& b) { return a.x != b.x ? a.x < b.x : a.seg < b.seg; }
};
using XKeys = std::vector<XKey>;

/// Sorts (x, segment) keys that come in the order of their segments by x, then segment: the
/// order std::sort gives them. A least-significant-digit radix sort of the keys in
/// three passes of 11 bits, each stable, so pairs of one x keep their segments' order: O(n) where
/// std::sort is O(n log n). A pass whose digit is the same in every key is skipped.
void sortByX(XKeys& pairs) {
  constexpr int kBits = 11, kPasses = 3;
  constexpr std::size_t kBuckets = std::size_t{1} << kBits;
  const std::size_t n = pairs.size();
  if (n < 64) {
    std::sort(pairs.begin(), pairs.end());
    return;
  }
  std::vector<std::array<std::uint32_t, kBuckets>> counts(kPasses);
  for (auto& c : counts) c.fill(0);
  for (const XKey& p : pairs) {
    const std::uint32_t key = orderKey(p.x);
    for (int pass = 0; pass < kPasses; ++pass) ++counts[pass][(key >> (pass * kBits)) & (kBuckets - 1)];
  }
  XKeys other(n);
  for (int pass = 0; pass < kPasses; ++pass) {
    auto& c = counts[static_cast<std::size_t>(pass)];
    if (std::find(c.begin(), c.end(), n) != c.end()) continue;  // one digit in every key
    std::uint32_t at = 0;
    for (std::uint32_t& bucket : c) at += std::exchange(bucket, at);
    for (const auto& p : pairs) other[c[(orderKey(p.x) >> (pass * kBits)) & (kBuckets - 1)]++] = p;
    pairs.swap(other);
  }
}

}  // namespace

namespace {

/// The order of a result's contacts: by (first, second).
bool byPair(const Contact& l, const Contact& r) { return l.first != r.first ? l.first < r.first : l.second < r.second; }

/// The contacts of a path that meets itself where the box sweep would test too many pairs (a star
/// of long spikes with a few crossings: 61.6 M pairs at 1e5 spikes). A decision sweep that drops,
/// at each pair that touches, the longer of the two segments — listing its contacts with every
/// segment still live by one pass over their boxes — and goes on; sweeps again from the start
/// until one drops nothing (the remaining segments then meet nowhere, by Shamos and Hoey) or
/// maxContacts is reached. Every contact has a dropped segment, and each was listed when the first
/// of its two was dropped. Each drop lists at least the pair that caused it, so at most maxContacts
/// segments are dropped: O(maxContacts (n log n)) at worst, one sweep and a pass over n boxes a
/// drop; two sweeps when the crossings are found in one.
/// The sweeps read the events the decision sweep read (a dropped segment's pieces are passed by);
/// a drop's pass over the segments reads their boxes (boxOf(i): segment i's SweepBox).
template <typename BoxOf, typename IsLive, typename IsForward, typename IsWrap, typename Touches>
SelfIntersectionResult dropAndSweep(SegmentView path, const SelfIntersectionOptions& options, SweepEvents& events,
                                    BoxOf&& boxOf, IsLive&& isLive, IsForward&& isForward, IsWrap&& isWrap,
                                    Touches&& touches, std::size_t tested) {
  const std::size_t n = path.size();
  SelfIntersectionResult r;
  std::vector<char> dropped(n, 0);
  auto stillLive = [&](std::size_t i) { return isLive(i) && !dropped[i]; };
  struct Dropper {
    SegmentView path;
    const SelfIntersectionOptions& options;
    BoxOf& boxOf;
    std::vector<char>& dropped;
    SelfIntersectionResult& r;
    IsLive& isLive;
    IsForward& isForward;
    IsWrap& isWrap;
    std::size_t dropsNow = 0;
    std::optional<std::uint32_t> operator()(std::uint32_t a, std::uint32_t b) {
      const std::uint32_t s = path[a].length() >= path[b].length() ? a : b;
      dropped[s] = 1;
      ++dropsNow;
      // s against every segment not dropped before it, on every core; the parts' contacts join in
      // the order of the segments.
      const double tol = options.tolerance;
      const SweepBox box = boxOf(s);
      const std::size_t n = path.size();
      std::mutex mutex;
      std::vector<std::pair<std::size_t, std::vector<Contact>>> parts;
      std::size_t pairs = 0;
      geometry::parallelFor(n, 4096, [&](std::size_t lo, std::size_t hi) {
        std::vector<Contact> found;
        std::size_t count = 0;
        for (std::size_t j = lo; j < hi; ++j) {
          // The boxes first: most do not meet s's, and that one test passes them.
          if (!box.meets(boxOf(j)) || j == s || !isLive(j) || dropped[j]) continue;
          const std::size_t i = std::min<std::size_t>(s, j), k = std::max<std::size_t>(s, j);
          ++count;
          classifyPair(path, i, k, isForward(i, k), isWrap(i, k), tol, found);
        }
        const std::lock_guard<std::mutex> lock(mutex);
        parts.emplace_back(lo, std::move(found));
        pairs += count;
      });
      std::sort(parts.begin(), parts.end(), [](const auto& l, const auto& x) { return l.first < x.first; });
      for (auto& part : parts) r.contacts.insert(r.contacts.end(), part.second.begin(), part.second.end());
      r.candidatePairs += pairs;
      return s;
    }
    [[nodiscard]] bool full() const { return r.contacts.size() >= options.maxContacts; }
  } drop{path, options, boxOf, dropped, r, isLive, isForward, isWrap};
  r.candidatePairs = tested;
  for (;;) {
    drop.dropsNow = 0;
    std::size_t swept = 0;
    const bool clean = sweepFindsNoContact<true>(path, events, stillLive, touches, options.tolerance, swept, drop);
    r.candidatePairs += swept;
    if (drop.full() || (clean && drop.dropsNow == 0)) break;
  }
  std::stable_sort(r.contacts.begin(), r.contacts.end(), byPair);
  if (drop.full()) {  // as the box sweep has it: maxContacts reached, more may lie beyond
    r.truncated = true;
    r.contacts.resize(options.maxContacts);
  }
  return r;
}

}  // namespace

namespace {

/// findSelfIntersections in its stages, each a member: measure (one pass over the segments: the
/// extent, the dead ones, the sweep's keys and boxes), the box sweep (every pair whose boxes
/// overlap, within a budget of work), the decision sweep (does any pair touch at all), and the
/// dropping sweeps that list the contacts where the box sweep would take too long. run() chooses.
class SelfIntersectionSearch {
 public:
  SelfIntersectionSearch(SegmentView path, const SelfIntersectionOptions& options)
      : path_(path), options_(options), tol_(options.tolerance), n_(path.size()) {}

  SelfIntersectionResult run();

 private:
  void measure();
  void sortByMinX();
  /// Every pair whose boxes overlap, tested exactly; nothing when the work (entries of the active
  /// list visited) passes a budget that is not 0.
  std::optional<SelfIntersectionResult> boxSweep(std::size_t budget);
  void fillBoxBlock(std::vector<SweepBox>& boxes, std::size_t base) const;
  /// Tests the pending pairs into r; true when maxContacts is reached (r is then final).
  bool flush(std::vector<std::pair<std::uint32_t, std::uint32_t>>& pending, SelfIntersectionResult& r);
  /// Whether a and b touch, for the decision sweep.
  bool touches(std::size_t a, std::size_t b);
  SelfIntersectionResult withLoop(SelfIntersectionResult r);

  // A segment's rank is its place among the live segments, kDead for the others (zero-length,
  // reported elsewhere); the ranks are kept only when some segment is dead (else rank i is i).
  [[nodiscard]] std::uint32_t rank(std::size_t i) const {
    return ranks_.empty() ? static_cast<std::uint32_t>(i) : ranks_[i];
  }
  [[nodiscard]] bool isLive(std::size_t i) const { return ranks_.empty() || ranks_[i] != kDead; }
  [[nodiscard]] bool alive(std::size_t i) const { return path_[i].length() > tol_; }
  /// Neighbours skip over dead segments: they share a vertex just the same.
  [[nodiscard]] bool isForward(std::size_t i, std::size_t j) const {
    return isLive(i) && rank(j) == rank(i) + 1 && near(path_[i].end, path_[j].start, tol_);
  }
  [[nodiscard]] bool isWrap(std::size_t i, std::size_t j) const {
    return options_.closed && live_ > 2 && rank(i) == 0 && rank(j) == live_ - 1 &&
           near(path_[j].end, path_[i].start, tol_);
  }
  [[nodiscard]] bool boxesFirst() const {
    return options_.method == SweepMethod::Boxes || options_.method == SweepMethod::Auto;
  }
  [[nodiscard]] std::size_t linearBudget() const { return 16 * std::size_t{live_} + 100000; }

  SegmentView path_;
  const SelfIntersectionOptions& options_;
  const double tol_;
  const std::size_t n_;
  std::vector<std::uint32_t> ranks_;
  std::uint32_t live_ = 0;
  double lowX_ = 0.0, highX_ = 0.0, widths_ = 0.0;  // the live boxes' extent in x, their widths' sum
  std::size_t selfLoop_ = SIZE_MAX;                 // the first segment that ends on its own start
  // Sorting (min x, index) pairs directly is much faster than sorting indices through boxes; only
  // the box sweep needs them.
  XKeys byMinX_;
  bool sorted_ = false;
  // Every live segment's box, in the segments' order, made once by measure (an arc's box takes
  // its axis extremes: most of the work of a box) and read by the box sweep and the dropping
  // sweeps — up to a million segments (16 MiB); past that the memory would grow with the path, so
  // each box is made again where it is needed (boxOf).
  std::vector<SweepBox> boxes_;
  [[nodiscard]] SweepBox boxOf(std::size_t i) const {
    return boxes_.empty() ? SweepBox::around(path_[i].bounds(), tol_) : boxes_[i];
  }
  // The first loop (findLoop): the least (k, v), v < k, whose end of k lies within tol of the start
  // of v, as k << 32 | v, among the pairs the box sweep tested.
  std::uint64_t loop_ = UINT64_MAX;
  std::vector<Contact> scratch_;
};

void SelfIntersectionSearch::measure() {
  if (boxesFirst()) byMinX_.resize(n_);
  constexpr std::size_t kKeptBoxesMost = std::size_t{1} << 20;
  if (n_ <= kKeptBoxesMost) boxes_.resize(n_);
  const bool keepBoxes = !boxes_.empty();
  // On every core, in stretches of a fixed length whose sums are added in order: the figures do
  // not depend on the number of threads.
  constexpr std::size_t kStretch = 4096;
  const std::size_t stretches = (n_ + kStretch - 1) / kStretch;
  struct Extent {
    double lowX = std::numeric_limits<double>::infinity(), highX = -std::numeric_limits<double>::infinity();
    double widths = 0.0;
    std::size_t selfLoop = SIZE_MAX;
    std::size_t dead = 0;
  };
  std::vector<Extent> extents(stretches);
  geometry::parallelFor(stretches, 2, [&](std::size_t sb, std::size_t se) {
    for (std::size_t st = sb; st < se; ++st) {
      Extent e;
      for (std::size_t i = st * kStretch; i < std::min(n_, (st + 1) * kStretch); ++i) {
        if (!alive(i)) {
          ++e.dead;
          if (boxesFirst()) byMinX_[i] = {0.0f, kDead};
          continue;
        }
        const Box b = path_[i].bounds();
        e.lowX = std::min(e.lowX, b.min.x());
        e.highX = std::max(e.highX, b.max.x());
        e.widths += b.max.x() - b.min.x() + 2 * tol_;
        const SweepBox box = SweepBox::around(b, tol_);
        if (keepBoxes) boxes_[i] = box;
        if (boxesFirst()) byMinX_[i] = {box.minX, static_cast<std::uint32_t>(i)};
        if (options_.findLoop && e.selfLoop == SIZE_MAX && near(path_[i].end, path_[i].start, tol_)) e.selfLoop = i;
      }
      extents[st] = e;
    }
  });
  lowX_ = std::numeric_limits<double>::infinity();
  highX_ = -lowX_;
  std::size_t dead = 0;
  for (const Extent& e : extents) {
    lowX_ = std::min(lowX_, e.lowX);
    highX_ = std::max(highX_, e.highX);
    widths_ += e.widths;
    selfLoop_ = std::min(selfLoop_, e.selfLoop);
    dead += e.dead;
  }
  live_ = static_cast<std::uint32_t>(n_ - dead);
  if (dead == 0) return;
  ranks_.assign(n_, kDead);
  std::uint32_t r = 0;
  for (std::size_t i = 0; i < n_; ++i)
    if (alive(i)) ranks_[i] = r++;
  if (boxesFirst())
    byMinX_.erase(std::remove_if(byMinX_.begin(), byMinX_.end(), [](const XKey& k) { return k.seg == kDead; }),
                  byMinX_.end());
}

void SelfIntersectionSearch::sortByMinX() {
  if (byMinX_.empty()) {  // not made yet, or given back for the decision sweep
    byMinX_.reserve(live_);
    for (std::size_t i = 0; i < n_; ++i)
      if (isLive(i)) byMinX_.push_back({boxOf(i).minX, static_cast<std::uint32_t>(i)});
  }
  if (!sorted_) sortByX(byMinX_);  // byMinX_ comes in the order of the segments
  sorted_ = true;
}

SelfIntersectionResult SelfIntersectionSearch::withLoop(SelfIntersectionResult r) {
  if (!options_.findLoop || r.truncated || live_ < n_) return r;
  r.loopKnown = true;
  if (selfLoop_ != SIZE_MAX) loop_ = std::min(loop_, std::uint64_t{selfLoop_} << 32 | selfLoop_);
  if (loop_ != UINT64_MAX) {
    r.loopTo = static_cast<std::size_t>(loop_ >> 32);
    r.loopFrom = static_cast<std::size_t>(loop_ & 0xFFFFFFFFU);
  }
  return r;
}

// The sweep itself only finds the pairs; their exact tests, most of its time, run on every core in
// batches. A batch's contacts join the result in the order of its pairs, so the result, its
// truncation at maxContacts and the pairs counted up to there are the same as testing each pair
// as it is found.
bool SelfIntersectionSearch::flush(std::vector<std::pair<std::uint32_t, std::uint32_t>>& pending,
                                   SelfIntersectionResult& r) {
  if (pending.empty()) return false;
  std::mutex mutex;
  std::vector<std::pair<std::size_t, std::vector<Contact>>> parts;  // (first pair, its contacts)
  geometry::parallelFor(pending.size(), 2048, [&](std::size_t b, std::size_t e) {
    std::vector<Contact> found;
    std::uint64_t first = UINT64_MAX;
    for (std::size_t k = b; k < e; ++k) {
      const auto [i, j] = pending[k];
      classifyPair(path_, i, j, isForward(i, j), isWrap(i, j), tol_, found);
      if (options_.findLoop && near(path_[j].end, path_[i].start, tol_))
        first = std::min(first, std::uint64_t{j} << 32 | i);
    }
    const std::lock_guard<std::mutex> lock(mutex);
    parts.emplace_back(b, std::move(found));
    loop_ = std::min(loop_, first);
  });
  std::sort(parts.begin(), parts.end(), [](const auto& l, const auto& x) { return l.first < x.first; });
  const std::size_t before = r.contacts.size();
  for (auto& part : parts) r.contacts.insert(r.contacts.end(), part.second.begin(), part.second.end());
  if (r.contacts.size() < options_.maxContacts) {
    r.candidatePairs += pending.size();
    pending.clear();
    return false;
  }
  // The pairs up to the one whose contact was the last kept: a pair's contacts are consecutive
  // and name it. (With maxContacts 0 the first pair tested ends the sweep.)
  std::size_t pair = 0;
  for (std::size_t c = before; c < options_.maxContacts; ++c)
    while (pending[pair].first != r.contacts[c].first || pending[pair].second != r.contacts[c].second) ++pair;
  r.candidatePairs += pair + 1;
  r.truncated = true;
  r.contacts.resize(options_.maxContacts);
  std::sort(r.contacts.begin(), r.contacts.end(), byPair);
  return true;
}

// The boxes in the sweep's order from `base`, gathered a block at a time on every core before the
// sweep reads them in turn (rather than fetching them one by one out of order).
void SelfIntersectionSearch::fillBoxBlock(std::vector<SweepBox>& boxes, std::size_t base) const {
  const std::size_t count = std::min(boxes.size(), byMinX_.size() - base);
  geometry::parallelFor(count, 4096, [&](std::size_t b, std::size_t e) {
    constexpr std::size_t kAhead = 8;
    if (!boxes_.empty()) {
      for (std::size_t q = b; q < e; ++q) {
        if (q + kAhead < e) __builtin_prefetch(&boxes_[byMinX_[base + q + kAhead].seg]);
        boxes[q] = boxes_[byMinX_[base + q].seg];
      }
      return;
    }
    for (std::size_t q = b; q < e; ++q) {
      if (q + kAhead < e) __builtin_prefetch(&path_[byMinX_[base + q + kAhead].seg]);
      boxes[q] = boxOf(byMinX_[base + q].seg);
    }
  });
}

std::optional<SelfIntersectionResult> SelfIntersectionSearch::boxSweep(std::size_t budget) {
  constexpr std::size_t kBatch = std::size_t{1} << 15;     // pairs tested at a time: 8 bytes each
  constexpr std::size_t kBoxBlock = std::size_t{1} << 16;  // boxes made at a time: 1 MB
  SelfIntersectionResult r;
  std::size_t work = 0;
  struct Active {
    SweepBox box;
    std::uint32_t idx;
  };
  std::vector<Active> active;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pending;  // (i, j), i < j, in the sweep's order
  pending.reserve(std::min<std::size_t>(kBatch, live_));
  loop_ = UINT64_MAX;
  std::vector<SweepBox> boxes(std::min(byMinX_.size(), kBoxBlock));
  for (std::size_t k = 0; k < byMinX_.size(); ++k) {
    if (k % kBoxBlock == 0) fillBoxBlock(boxes, k);
    const std::uint32_t idx = byMinX_[k].seg;
    const SweepBox box = boxes[k % kBoxBlock];
    work += active.size();
    if (budget && work > budget) {
      // Pairs found before the budget ran out may already reach maxContacts: then the sweep did
      // finish, as it would have testing them one by one.
      if (flush(pending, r)) return r;
      return std::nullopt;
    }
    std::size_t w = 0;
    for (std::size_t a = 0; a < active.size(); ++a) {
      if (active[a].box.reachX < box.minX) continue;  // leaves the sweep
      const float minY = active[a].box.minY, reachY = active[a].box.reachY;
      const std::uint32_t other = active[a].idx;
      if (w != a) active[w] = active[a];  // the entries that stay, closed up
      ++w;
      // The boxes meet in x: the entry's starts no later (the order) and reaches this one's start.
      if (!(minY <= box.reachY && box.minY <= reachY)) continue;
      pending.emplace_back(std::min(idx, other), std::max(idx, other));
      if (pending.size() == kBatch && flush(pending, r)) return r;
    }
    active.resize(w);
    active.push_back({box, idx});
  }
  if (flush(pending, r)) return r;
  std::sort(r.contacts.begin(), r.contacts.end(), byPair);
  return r;
}

bool SelfIntersectionSearch::touches(std::size_t a, std::size_t b) {
  const std::size_t i = std::min(a, b), j = std::max(a, b);
  // Most neighbours along the sweep line are two lines far apart: one lies wholly on one side of
  // the other's line, farther than the tolerance. Two cross products say so; the full test is
  // left for the rest.
  if (!path_[i].isArc() && !path_[j].isArc() &&
      (strictlyOneSide(path_[i], path_[j], tol_) || strictlyOneSide(path_[j], path_[i], tol_)))
    return false;
  scratch_.clear();
  classifyPair(path_, i, j, isForward(i, j), isWrap(i, j), tol_, scratch_);
  return !scratch_.empty();
}

SelfIntersectionResult SelfIntersectionSearch::run() {
  if (n_ >= kDead) throw std::length_error("findSelfIntersections: more than 2^32 - 2 segments");
  measure();
  if (options_.method == SweepMethod::Boxes) {
    sortByMinX();
    return withLoop(*boxSweep(0));
  }
  // On the shapes wire programs have, few boxes overlap and the box sweep is the fastest answer:
  // tried first with work linear in the path. Where boxes pile up (long spikes of a star), the
  // decision sweep shows in O(n log n) that the path does not meet itself — what a program that can
  // be cut needs; only a path that does meet itself is then listed. The box sweep's work is about
  // the number of boxes times the boxes a vertical line meets on average (their widths over the
  // extent): past the budget already on average, it is not tried.
  if (options_.method == SweepMethod::Auto) {
    const double meets = widths_ / std::max(highX_ - lowX_, 1e-300);
    if (meets * static_cast<double>(live_) <= static_cast<double>(linearBudget())) {
      sortByMinX();
      if (std::optional<SelfIntersectionResult> quick = boxSweep(linearBudget())) return withLoop(std::move(*quick));
    }
  }
  // The decision sweep does not need the boxes' order: its memory goes back first (8 bytes a
  // segment: 80 MB at 1e7), and a box sweep after it sorts again.
  XKeys().swap(byMinX_);
  sorted_ = false;
  auto isLiveSegment = [this](std::size_t i) { return isLive(i); };
  auto touchesPair = [this](std::size_t a, std::size_t b) { return touches(a, b); };
  std::size_t tested = 0;
  SweepEvents events = makeSweepEvents(path_, live_, isLiveSegment);
  if (sweepFindsNoContact(path_, events, isLiveSegment, touchesPair, tol_, tested)) {
    SelfIntersectionResult clean;
    clean.candidatePairs = tested;
    return clean;
  }
  // The path meets itself. Its contacts are listed by the box sweep while its work stays linear
  // (the decision method tries it here; the automatic one already ran out of it, or knew it would).
  if (options_.method == SweepMethod::Decision) {
    sortByMinX();
    if (std::optional<SelfIntersectionResult> quick = boxSweep(linearBudget())) return withLoop(std::move(*quick));
  }
  auto forward = [this](std::size_t i, std::size_t j) { return isForward(i, j); };
  auto wrap = [this](std::size_t i, std::size_t j) { return isWrap(i, j); };
  auto box = [this](std::size_t i) { return boxOf(i); };
  return dropAndSweep(path_, options_, events, box, isLiveSegment, forward, wrap, touchesPair, tested);
}

}  // namespace

SelfIntersectionResult findSelfIntersections(SegmentView path, const SelfIntersectionOptions& options) {
  return SelfIntersectionSearch(path, options).run();
}

}  // namespace kerf::geometry
