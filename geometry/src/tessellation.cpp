#include "kerf/geometry/tessellation.h"

#include "angles.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace kerf::geometry {
namespace {

/// Angle of the chord of length k on a circle of radius r (capped at a half circle).
double stepAngle(double k, double r) {
  if (k >= 2 * r) return kPi;
  return 2 * std::asin(k / (2 * r));
}

/// Largest chord angle whose sagitta r (1 - cos(a/2)) stays within tol (capped at a half circle).
double toleranceAngle(double tol, double r) {
  if (tol >= r) return kPi;
  return 2 * std::acos(1 - tol / r);
}

/// How the arc is cut into chords: `full` chords of angle `span` and, in step mode, one last
/// chord of angle `rest` (0 when the sweep is a whole number of steps).
struct ChordPlan {
  std::size_t full = 0;
  double span = 0.0;
  double rest = 0.0;
  /// sin(span / 2) when the span is a chord's of length k (span = 2 asin(k / 2r)): k / 2r, of
  /// which the chord's errors need the cosine only as sqrt(1 - sin^2); 0 otherwise.
  double sinHalf = 0.0;
};

/// The chords of an arc of radius r (mm) turning by signedSweep (radians).
ChordPlan planChords(double r, double signedSweep, const Sampling& sampling) {
  const double sweep = std::abs(signedSweep);
  ChordPlan plan;
  if (sampling.mode == SamplingMode::Step) {
    plan.span = stepAngle(sampling.value, r);
    if (sampling.value < 2 * r) plan.sinHalf = sampling.value / (2 * r);
    // A remainder smaller than 1e-9 of a step is rounding noise, not a chord.
    const double q = sweep / plan.span;
    const double whole = std::floor(q + 1e-9);
    plan.full = static_cast<std::size_t>(whole);
    plan.rest = std::max(0.0, sweep - whole * plan.span);
    if (plan.rest <= 1e-9 * plan.span) plan.rest = 0.0;
    if (plan.full == 0) plan.rest = sweep;  // the whole arc is shorter than one step
  } else {
    const double maxSpan = toleranceAngle(sampling.value, r);
    plan.full = static_cast<std::size_t>(std::max(1.0, std::ceil(sweep / maxSpan - 1e-9)));
    plan.span = sweep / static_cast<double>(plan.full);
    plan.rest = 0.0;
  }
  return plan;
}

}  // namespace

namespace {

/// Below this chord angle (rad) the chord's errors come from their Taylor series, not from the
/// sine, cosine and logarithm. The chords of a real program's arcs are nearly all this short (a
/// 0.1 mm step on a 5 mm radius is 0.02 rad), and those calls were most of the summary's time
/// (12% of kerf check on the 6.1 MB benchmark, whose arcs' chords are 1.1 rad and keep them). The
/// series are also the more accurate there: the closed forms subtract numbers that agree in their
/// first digits (at 0.25 rad, 1 - cos(span/2) loses 2 of them, the mean error 3). Their terms up to
/// span^14 leave out less than 1e-17 of the value below 0.25 rad; the coefficients are sympy's
/// (tessellation_test.cpp checks both sides of the switch against mpmath).
constexpr double kSeriesSpan = 0.25;

/// 1 - cos x for |x| < kSeriesSpan / 2, by its series (Horner in x^2).
double oneMinusCosSeries(double x) {
  const double q = x * x;
  return q * (1.0 / 2 -
              q * (1.0 / 24 - q * (1.0 / 720 - q * (1.0 / 40320 -
                                                    q * (1.0 / 3628800 - q * (1.0 / 479001600 - q / 87178291200.0))))));
}

/// The mean relative error of a chord of angle span < kSeriesSpan: the series of
/// 1 - cos(span/2) (2/span) ln tan(pi/4 + span/4), which has no span^4 term:
/// span^2/12 + span^6/20160 + span^8/362880 + span^10/5322240 + 13 span^12/958003200
/// + 10753 span^14/10461394944000.
double meanRelativeErrorSeries(double span) {
  const double q = span * span;
  const double high =
      1.0 / 20160 +
      q * (1.0 / 362880 + q * (1.0 / 5322240 + q * (13.0 / 958003200 + q * (10753.0 / 10461394944000.0))));
  return q / 12 + q * q * q * high;
}

/// The mean relative error of a chord of angle span >= kSeriesSpan, the average over phi in
/// [-span/2, span/2] of 1 - cos(span/2) / cos(phi), with the cosine and sine of span / 2 given:
/// the sagitta needs the cosine too, and the two come from one call. ln tan(pi/4 + span/4) is
/// taken as ln((1 + sin(span/2)) / cos(span/2)) (tan(pi/4 + x) = (1 + sin 2x) / cos 2x), a sine
/// that comes with the cosine instead of a tangent.
double meanRelativeErrorClosed(double span, double cosHalf, double sinHalf) {
  return 1 - cosHalf * (2 / span) * std::log((1 + sinHalf) / cosHalf);
}

/// A chord of angle span on a circle of radius r: its sagitta r (1 - cos(span/2)), the deviation
/// at its middle, and its mean relative error (0 and 0 for no angle).
struct ChordError {
  double sagitta = 0.0;
  double meanRelative = 0.0;
};
ChordError chordError(double r, double span) {
  if (span <= 0) return {};
  if (span < kSeriesSpan) return {r * oneMinusCosSeries(span / 2), meanRelativeErrorSeries(span)};
  const double cosHalf = std::cos(span / 2), sinHalf = std::sin(span / 2);
  return {r * (1 - cosHalf), meanRelativeErrorClosed(span, cosHalf, sinHalf)};
}

/// chordError of a chord (span > 0) whose half angle's sine is known (ChordPlan::sinHalf): its
/// cosine is sqrt((1 - s)(1 + s)), within a unit of the last place of cos(asin s), without the
/// sine and cosine calls; 1 - that cosine is s^2 / (1 + cosine), which does not cancel.
ChordError chordErrorOfSine(double r, double span, double sinHalf) {
  const double cosHalf = std::sqrt((1 - sinHalf) * (1 + sinHalf));
  return {r * (sinHalf * sinHalf / (1 + cosHalf)),
          span < kSeriesSpan ? meanRelativeErrorSeries(span) : meanRelativeErrorClosed(span, cosHalf, sinHalf)};
}

}  // namespace

double chordMeanRelativeError(double span) { return chordError(1.0, span).meanRelative; }

std::size_t sampleCount(const Segment& seg, const Sampling& sampling) {
  if (!seg.isArc()) return 1;
  const ChordPlan plan = planChords(seg.radius(), seg.sweep, sampling);
  return plan.full + (plan.rest > 0 ? 1 : 0);
}

namespace {

/// sample() of an arc of radius r (its radius(), taken once by the caller).
ArcSampleStats sampleArc(const Segment& seg, double r, const Sampling& sampling, std::vector<Vec2>* out) {
  ArcSampleStats stats;
  const ChordPlan plan = planChords(r, seg.sweep, sampling);
  const double dir = seg.sweep >= 0 ? 1.0 : -1.0;
  const std::size_t total = plan.full + (plan.rest > 0 ? 1 : 0);
  stats.points = total;
  if (out) {
    out->reserve(out->size() + total);
    const double a0 = seg.startAngle();
    for (std::size_t i = 1; i < total; ++i) {
      const double a = a0 + dir * plan.span * static_cast<double>(i);
      out->push_back(seg.centre + r * direction(a));
    }
    out->push_back(seg.end);
  }
  const double sweep = std::abs(seg.sweep);
  double weighted = 0.0;
  if (plan.full > 0) {
    const ChordError e = plan.sinHalf > 0 ? chordErrorOfSine(r, plan.span, plan.sinHalf) : chordError(r, plan.span);
    stats.maxDeviation = e.sagitta;
    weighted += static_cast<double>(plan.full) * plan.span * e.meanRelative;
  }
  if (plan.rest > 0) {
    const ChordError e = chordError(r, plan.rest);
    stats.maxDeviation = std::max(stats.maxDeviation, e.sagitta);
    weighted += plan.rest * e.meanRelative;
  }
  stats.meanRelativeError = sweep > 0 ? weighted / sweep : 0.0;
  return stats;
}

}  // namespace

ArcSampleStats sample(const Segment& seg, const Sampling& sampling, std::vector<Vec2>* out) {
  if (!seg.isArc()) {
    if (out) out->push_back(seg.end);
    return ArcSampleStats{.points = 1};
  }
  return sampleArc(seg, seg.radius(), sampling, out);
}

double PathSampler::add(const Segment& seg) {
  if (stats_.points == 0) {
    first_ = seg.start;
    last_ = seg.start;
    stats_.points = 1;
    if (out_) out_->push_back(last_);
  }
  if ((seg.start - last_).norm() > 1e-9) {
    ++stats_.points;
    if (out_) out_->push_back(seg.start);
  }
  last_ = seg.end;
  if (!seg.isArc()) {
    stats_.points += sample(seg, sampling_, out_).points;
    return seg.length();
  }
  const double r = seg.radius();  // once, for its sampling and its length (r |sweep|: Segment::length)
  const ArcSampleStats s = sampleArc(seg, r, sampling_, out_);
  stats_.points += s.points;
  ++stats_.arcs;
  stats_.maxDeviation = std::max(stats_.maxDeviation, s.maxDeviation);
  const double len = r * std::abs(seg.sweep);
  stats_.arcLength += len;
  weighted_ += len * s.meanRelativeError;
  return len;
}

void PathSampler::append(const PathSampler& later) {
  if (later.stats_.points == 0) return;
  if (stats_.points == 0) {
    first_ = later.first_;
    stats_.points = later.stats_.points;
  } else {
    // add() counts a start that is not the last end; later counted its first start regardless.
    stats_.points += later.stats_.points - ((later.first_ - last_).norm() > 1e-9 ? 0 : 1);
  }
  stats_.arcs += later.stats_.arcs;
  stats_.maxDeviation = std::max(stats_.maxDeviation, later.stats_.maxDeviation);
  stats_.arcLength += later.stats_.arcLength;
  weighted_ += later.weighted_;
  last_ = later.last_;
}

PathSampleStats PathSampler::stats() const {
  PathSampleStats stats = stats_;
  stats.meanRelativeError = stats.arcLength > 0 ? weighted_ / stats.arcLength : 0.0;
  return stats;
}

PathSampleStats samplePath(SegmentView path, const Sampling& sampling, std::vector<Vec2>* out) {
  PathSampler sampler(sampling, out);
  for (const Segment& seg : path) sampler.add(seg);
  return sampler.stats();
}

namespace {

std::size_t countPoints(std::span<const Segment> path, const Sampling& sampling) {
  if (path.empty()) return 0;
  std::size_t n = 1;
  Vec2 last = path.front().start;
  for (const Segment& seg : path) {
    if ((seg.start - last).norm() > 1e-9) ++n;
    n += sampleCount(seg, sampling);
    last = seg.end;
  }
  return n;
}

}  // namespace

CapacityFit fitToCapacity(std::span<const Segment> path, std::size_t maxPoints, SamplingMode mode) {
  CapacityFit fit;
  double maxRadius = 0.0;
  for (const Segment& s : path)
    if (s.isArc()) maxRadius = std::max(maxRadius, s.radius());
  // Coarsest possible sampling: every arc in half circles (and no finer).
  const double coarsest = mode == SamplingMode::Step ? 2 * maxRadius : maxRadius;
  const Sampling coarse{mode, std::max(coarsest, 1e-9)};
  fit.fewestPossible = countPoints(path, coarse);
  if (fit.fewestPossible > maxPoints) {
    fit.fits = false;
    fit.sampling = coarse;
    fit.points = fit.fewestPossible;
    return fit;
  }
  if (maxRadius == 0.0) {  // no arcs: the count does not depend on the step
    fit.fits = true;
    fit.sampling = Sampling{mode, 0.0};
    fit.points = fit.fewestPossible;
    return fit;
  }
  // The count is non-increasing in the step: bisect on a log scale between a step that is far
  // too fine (or fits already) and the coarsest one.
  double hi = coarsest;
  double lo = coarsest * 1e-12;
  if (countPoints(path, Sampling{mode, lo}) <= maxPoints) {
    fit.fits = true;
    fit.sampling = Sampling{mode, lo};
    fit.points = countPoints(path, fit.sampling);
    return fit;
  }
  for (int i = 0; i < 200 && hi - lo > 1e-9 * hi; ++i) {
    const double mid = std::sqrt(lo * hi);
    const double m = (mid <= lo || mid >= hi) ? (lo + hi) / 2 : mid;
    if (countPoints(path, Sampling{mode, m}) <= maxPoints)
      hi = m;
    else
      lo = m;
  }
  fit.fits = true;
  fit.sampling = Sampling{mode, hi};
  fit.points = countPoints(path, fit.sampling);
  assert(fit.points <= maxPoints);
  return fit;
}

SeedArcAngles seedAngles(const Segment& arc, double k) {
  SeedArcAngles a;
  // The seed measures angles clockwise from +X, so its angle is minus ours.
  a.alpha = detail::wrapPositive(-arc.startAngle());
  a.beta = a.alpha - arc.sweep;  // clockwise sweep (G2) makes delta grow
  a.gamma = stepAngle(k, arc.radius());
  return a;
}

std::vector<Vec2> seedArcPoints(const Segment& arc, double k) {
  const SeedArcAngles a = seedAngles(arc, k);
  std::vector<Vec2> points;
  const bool clockwise = arc.sweep < 0;  // G2: delta grows by gamma; G3: it falls by gamma
  const double r = arc.radius();
  const double total = std::abs(a.beta - a.alpha);
  // Same rounding rule as sample(): a remainder below 1e-9 of a step is no chord.
  const auto steps = static_cast<std::size_t>(std::floor(total / a.gamma + 1e-9));
  for (std::size_t i = 1; i <= steps; ++i) {
    const double delta = a.alpha + (clockwise ? 1.0 : -1.0) * a.gamma * static_cast<double>(i);
    if (std::abs(delta - a.alpha) >= total - 1e-9 * a.gamma) break;  // reached beta
    points.emplace_back(arc.centre.x() + std::cos(delta) * r, arc.centre.y() - std::sin(delta) * r);
  }
  points.push_back(arc.end);
  return points;
}

}  // namespace kerf::geometry
