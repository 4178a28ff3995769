#include "kerf/geometry/align.h"

#include "kerf/geometry/deviation.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace kerf::geometry {

namespace {

/// Points spread evenly along the set's length (so each unit of length weighs the same), with
/// the elements' ends besides when there are fewer elements than points asked for.
std::vector<Vec2> pointsAlong(SegmentView set, std::size_t count) {
  double total = 0.0;
  for (const Segment& s : set) total += s.length();
  std::vector<Vec2> points;
  if (total <= 0.0) return points;
  const double step = total / static_cast<double>(std::max<std::size_t>(count, 1));
  const bool ends = set.size() <= count;
  double carried = 0.0;  // length since the last point, carried into the next element
  for (const Segment& s : set) {
    const double length = s.length();
    if (ends) points.push_back(s.start);
    for (double at = step - carried; at < length; at += step) points.push_back(s.pointAt(at / length));
    carried = std::fmod(carried + length, step);
  }
  return points;
}

/// The points' centroid and the angle of their major principal axis.
struct Moments {
  Vec2 centroid = Vec2::Zero();
  double axis = 0.0;
};

Moments momentsOf(const std::vector<Vec2>& points) {
  Moments m;
  for (const Vec2& p : points) m.centroid += p;
  m.centroid /= static_cast<double>(points.size());
  double sxx = 0, syy = 0, sxy = 0;
  for (const Vec2& p : points) {
    const Vec2 d = p - m.centroid;
    sxx += d.x() * d.x();
    syy += d.y() * d.y();
    sxy += d.x() * d.y();
  }
  m.axis = 0.5 * std::atan2(2 * sxy, sxx - syy);
  return m;
}

Vec2 turned(const Vec2& p, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * p.x() - s * p.y(), s * p.x() + c * p.y()};
}

Vec2 mirrored(const Vec2& p, bool mirror) { return mirror ? Vec2(-p.x(), p.y()) : p; }

/// The point of `to` nearest p: on the segment whose chord is nearest (exact on that segment).
Vec2 nearestPoint(const DeviationSet& to, const Vec2& p) {
  const Segment& s = to.owner(to.nearest(p).chord);
  return s.pointAt(s.parameterOf(p));
}

/// Iterative closest points from a starting placement; the rms of the last pairing.
Alignment refine(const std::vector<Vec2>& points, const DeviationSet& to, Placement p, std::size_t iterations) {
  Alignment out{p, std::numeric_limits<double>::infinity()};
  std::vector<Vec2> placed(points.size()), paired(points.size());
  for (std::size_t it = 0; it <= iterations; ++it) {
    Vec2 qMean = Vec2::Zero(), nMean = Vec2::Zero();
    double squares = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      placed[i] = p.apply(points[i]);
      paired[i] = nearestPoint(to, placed[i]);
      squares += (placed[i] - paired[i]).squaredNorm();
      qMean += placed[i];
      nMean += paired[i];
    }
    out = {p, std::sqrt(squares / static_cast<double>(points.size()))};
    if (it == iterations) break;
    qMean /= static_cast<double>(points.size());
    nMean /= static_cast<double>(points.size());
    double dot = 0.0, cross = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Vec2 q = placed[i] - qMean, n = paired[i] - nMean;
      dot += q.dot(n);
      cross += q.x() * n.y() - q.y() * n.x();
    }
    const double delta = std::atan2(cross, dot);
    const Vec2 shift = turned(p.shift - qMean, delta) + nMean;
    const bool still = std::abs(delta) < 1e-12 && (shift - p.shift).norm() < 1e-10;
    p.angle += delta;
    p.shift = shift;
    if (still) break;
  }
  return out;
}

}  // namespace

Vec2 Placement::apply(const Vec2& p) const { return turned(mirrored(p, mirror), angle) + shift; }

Segment Placement::apply(const Segment& s) const {
  Segment out = s;
  out.start = apply(s.start);
  out.end = apply(s.end);
  if (s.isArc()) {
    out.centre = apply(s.centre);
    if (mirror) out.sweep = -s.sweep;
  }
  return out;
}

Alignment align(SegmentView from, SegmentView to, const AlignOptions& options) {
  const std::vector<Vec2> points = pointsAlong(from, options.samples);
  const std::vector<Vec2> targets = pointsAlong(to, options.samples);
  if (points.empty() || targets.empty()) return {};
  const DeviationSet toSet(to, 1e-4);
  const Moments target = momentsOf(targets);
  // The candidates are screened on a tenth of the points; the best is refined on all of them.
  const std::vector<Vec2> few = pointsAlong(from, std::max<std::size_t>(options.samples / 10, 50));
  std::vector<Alignment> found{refine(few, toSet, Placement{}, options.iterations)};  // as placed
  for (const bool mirror : {false, true}) {
    if (mirror && !options.allowMirror) continue;
    std::vector<Vec2> flipped(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) flipped[i] = mirrored(points[i], mirror);
    const Moments source = momentsOf(flipped);
    for (int quarter = 0; quarter < 4; ++quarter) {
      Placement p;
      p.mirror = mirror;
      p.angle = target.axis - source.axis + quarter * kPi / 2;
      p.shift = target.centroid - turned(source.centroid, p.angle);
      found.push_back(refine(few, toSet, p, options.iterations));
    }
  }
  // A symmetric shape fits as well turned a quarter or mirrored: of the placements that fit as well
  // as the best, the one without a mirror and with the smallest turn is the one a reader expects.
  double least = std::numeric_limits<double>::infinity();
  for (const Alignment& a : found) least = std::min(least, a.rms);
  auto cost = [](const Alignment& a) {
    return (a.placement.mirror ? 10.0 : 0.0) + std::abs(std::remainder(a.placement.angle, 2 * kPi));
  };
  const Alignment* chosen = nullptr;
  for (const Alignment& a : found)
    if (a.rms <= least * (1 + 1e-3) + 1e-7 && (chosen == nullptr || cost(a) < cost(*chosen))) chosen = &a;
  Alignment best = refine(points, toSet, chosen->placement, options.iterations);
  best.placement.angle = std::remainder(best.placement.angle, 2 * kPi);
  return best;
}

}  // namespace kerf::geometry
