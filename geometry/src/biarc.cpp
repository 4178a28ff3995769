#include "kerf/geometry/biarc.h"

#include <unsupported/Eigen/Splines>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <vector>

namespace kerf::geometry {

namespace {

/// The largest arc radius a fit makes, mm: the readers take no coordinate beyond 1e6 mm.
constexpr double kLargestArcRadius = 1e6;
/// A spline through fit points whose control points lie farther than this many times the points'
/// extent outside their bounding box swings far from them: refused (BiarcFit::swings).
constexpr double kMostSwing = 10.0;

/// The arc that leaves p along the unit tangent u and ends at q (a line where q lies on the
/// tangent, or the circle would be immense).
Segment tangentArc(const Vec2& p, const Vec2& u, const Vec2& q) {
  const Vec2 w = q - p;
  const Vec2 n = leftNormal(u);
  const double k = w.dot(n), ww = w.squaredNorm();
  if (std::abs(k) <= 1e-12 * std::max(1.0, ww)) return Segment::line(p, q);
  const double r = ww / (2 * k);  // signed: > 0, the centre on the left (counter-clockwise)
  // Beyond the readers' range (1e6 mm) an arc is its chord: the fit measures the chord against the
  // curve as it would the arc, so a span it does not fit is shortened.
  if (std::abs(r) > kLargestArcRadius) return Segment::line(p, q);
  return Segment::arc(p, q, p + r * n, r > 0 ? ArcDirection::CounterClockwise : ArcDirection::Clockwise);
}

/// A B-spline of degree at most 3 evaluated by de Boor's algorithm with no allocation: Eigen's
/// Spline::operator() allocates its basis on every call, and the biarc fit calls it thousands of
/// times (a 247-point spline took over 10 s under the sanitizers, found by the DXF fuzzer).
struct BSpline {
  std::vector<double> knots;
  std::vector<Vec2> control;
  std::size_t degree = 3;

  [[nodiscard]] Vec2 at(double u) const {
    const std::size_t n = control.size(), p = degree;
    // The knot span: the last k in [p, n) with knots[k] <= u.
    const auto it = std::upper_bound(knots.begin() + static_cast<std::ptrdiff_t>(p),
                                     knots.begin() + static_cast<std::ptrdiff_t>(n), u);
    const std::size_t k = std::max<std::size_t>(p, static_cast<std::size_t>(it - knots.begin()) - 1);
    std::array<Vec2, 4> d;
    for (std::size_t j = 0; j <= p; ++j) d[j] = control[k - p + j];
    for (std::size_t r = 1; r <= p; ++r)
      for (std::size_t j = p; j >= r; --j) {
        const std::size_t i = k - p + j;
        const double den = knots[i + p + 1 - r] - knots[i];
        const double alpha = den > 0 ? (u - knots[i]) / den : 0.0;
        d[j] = (1 - alpha) * d[j - 1] + alpha * d[j];
      }
    return d[p];
  }

  /// The derivative, a B-spline of one degree less on the inner knots (degree 0: zero).
  [[nodiscard]] BSpline derivative() const {
    BSpline out;
    if (degree == 0) {
      out.degree = 0;
      out.knots = knots;
      out.control.assign(control.size(), Vec2(0, 0));
      return out;
    }
    out.degree = degree - 1;
    out.knots.assign(knots.begin() + 1, knots.end() - 1);
    for (std::size_t i = 0; i + 1 < control.size(); ++i) {
      const double den = knots[i + degree + 1] - knots[i + 1];
      out.control.push_back(den > 0 ? Vec2(static_cast<double>(degree) * (control[i + 1] - control[i]) / den)
                                    : Vec2(0, 0));
    }
    return out;
  }
};

/// A step of the walk is the longest span that fits to within this fraction of its length.
constexpr double kSpanPrecision = 64;
/// Past this many spans the errors are not equalised: the greedy walk's spans are all within the
/// tolerance already, and each equalising walk would cost as much again (a curve out 990 m and back
/// needs 6,000 spans).
constexpr std::size_t kMostEqualisedSpans = 1000;
/// equalise's target error is the smallest to within this fraction of the tolerance.
constexpr double kEqualisePrecision = 16;

Vec2 unit(const Vec2& v) {
  const double n = v.norm();
  return n > 0 ? Vec2(v / n) : Vec2(0, 0);
}

class Fitter {
 public:
  Fitter(const ParametricCurve& c, const BiarcOptions& o) : c_(c), o_(o) {}

  Vec2 tangent(double t) const {
    Vec2 d = c_.derivative ? c_.derivative(t) : Vec2(0, 0);
    if (!c_.derivative || d.norm() < 1e-14) {
      // Central differences inside; at the ends of the range (the curve may not exist beyond
      // them) the one-sided second-order formula, so that the end tangents are as exact as the
      // inner ones and a closed curve's seam has no corner.
      const double range = std::max(1e-12, c_.t1 - c_.t0);
      const double h = 1e-6 * range;
      if (t - h < c_.t0) {
        const double k = 1e-5 * range;
        d = 4.0 * c_.point(t + k) - 3.0 * c_.point(t) - c_.point(t + 2 * k);
      } else if (t + h > c_.t1) {
        const double k = 1e-5 * range;
        d = 3.0 * c_.point(t) - 4.0 * c_.point(t - k) + c_.point(t - 2 * k);
      } else {
        d = c_.point(t + h) - c_.point(t - h);
      }
    }
    return unit(d);
  }

  /// The biarc of [a, b] and its largest sampled distance from the curve (infinite: none).
  double span(double a, double b, std::vector<Segment>& out) const {
    out = biarc(c_.point(a), tangent(a), c_.point(b), tangent(b));
    if (out.empty()) return INFINITY;
    double worst = 0.0;
    for (int k = 1; k <= o_.samples; ++k) {
      const Vec2 p = c_.point(a + (b - a) * k / (o_.samples + 1));
      double best = INFINITY;
      for (const Segment& s : out) best = std::min(best, s.distanceTo(p));
      worst = std::max(worst, best);
      if (!(worst <= 1e300)) return INFINITY;
    }
    return worst;
  }

  /// Whether span(a, b, out) <= e, the same answer with fewer points of the curve: the samples in an
  /// order that spreads them over the span from the first (the middle, the quarters, the eighths:
  /// k in bit-reversed order), and none more once one lies farther than e. Most trials of the walk's
  /// bisection fail, and most of those on one of the first few samples: a curve given as
  /// expressions (--curve) costs a muparser evaluation a point, most of kerf cam's time.
  bool fits(double a, double b, double e, std::vector<Segment>& out) const {
    // Every trial of one step of the walk starts at the same node: its point and tangent once.
    if (!(startT_ == a)) {
      startT_ = a;
      startP_ = c_.point(a);
      startU_ = tangent(a);
    }
    out = biarc(startP_, startU_, c_.point(b), tangent(b));
    if (out.empty()) return false;
    for (const int k : sampleOrder()) {
      const Vec2 p = c_.point(a + (b - a) * k / (o_.samples + 1));
      double best = INFINITY;
      for (const Segment& s : out) best = std::min(best, s.distanceTo(p));
      if (!(best <= e) || !(best <= 1e300)) return false;
    }
    return true;
  }

  /// The greedy walk with target error e: the nodes, or empty when over budget. Each step takes
  /// the longest span from t that fits, found to within 1/kSpanPrecision of its length (the walk
  /// needs a long span, not the longest to the last bit): the span of the step before, doubled,
  /// is tried first, so a curve of even spans costs a few trials a step, not a bisection of the
  /// whole rest of the range.
  std::vector<double> walk(double e, bool& ok) const {
    std::vector<double> nodes{c_.t0};
    std::vector<Segment> scratch;
    ok = true;
    double t = c_.t0, step = c_.t1 - c_.t0;
    while (t < c_.t1) {
      if (nodes.size() > o_.maxSpans) return {};
      if (fits(t, c_.t1, e, scratch)) {
        nodes.push_back(c_.t1);
        break;
      }
      double lo = t, hi = c_.t1;  // span(t, lo) fits (or lo = t), span(t, hi) does not
      if (const double guess = t + 2 * step; guess < c_.t1) {
        if (fits(t, guess, e, scratch))
          lo = guess;
        else
          hi = guess;
      }
      for (int i = 0; i < 60 && hi - lo > std::max(o_.minSpan, (hi - t) / kSpanPrecision); ++i) {
        const double mid = 0.5 * (lo + hi);
        if (fits(t, mid, e, scratch))
          lo = mid;
        else
          hi = mid;
      }
      if (lo - t <= o_.minSpan) {  // nothing fits: a corner or a cusp; step over it
        ok = false;
        lo = std::min(c_.t1, hi);
      }
      step = lo - t;
      nodes.push_back(lo);
      t = lo;
    }
    return nodes;
  }

 private:
  /// 1 .. samples, each once, in the order of their bits reversed (for 63: 32, 16, 48, 8, ...).
  const std::vector<int>& sampleOrder() const {
    if (order_.empty()) {
      const int n = std::max(0, o_.samples);
      int bits = 0;
      while ((1 << bits) <= n) ++bits;
      for (int r = 0; r < (1 << bits); ++r) {
        int k = 0;
        for (int b = 0; b < bits; ++b) k |= ((r >> b) & 1) << (bits - 1 - b);
        if (k >= 1 && k <= n) order_.push_back(k);
      }
    }
    return order_;
  }

  const ParametricCurve& c_;
  const BiarcOptions& o_;
  mutable std::vector<int> order_;
  mutable double startT_ = NAN;  // fits: the node its cached point and tangent are at
  mutable Vec2 startP_ = Vec2::Zero(), startU_ = Vec2::Zero();
};

}  // namespace

std::vector<Segment> biarc(const Vec2& p0, const Vec2& u0, const Vec2& p1, const Vec2& u1) {
  const Vec2 v = p1 - p0;
  const double vv = v.squaredNorm();
  if (vv < 1e-24) return {};
  const double c = u0.dot(u1);
  const double vt = v.dot(u0 + u1);
  double d;
  const double denom = 2 * (1 - c);
  if (denom < 1e-12) {  // parallel tangents, the same way
    const double vu = v.dot(u1);
    if (vu <= 0) return {};
    d = vv / (4 * vu);
  } else {
    d = (-vt + std::sqrt(vt * vt + denom * vv)) / denom;
  }
  if (!(d > 0) || !std::isfinite(d)) return {};
  const Vec2 a = p0 + d * u0, b = p1 - d * u1;
  const Vec2 joint = 0.5 * (a + b);
  const Vec2 uj = unit(b - a);
  if (uj.norm() == 0) {  // the control points coincide: a single arc through the joint
    return {tangentArc(p0, u0, p1)};
  }
  std::vector<Segment> out;
  const Segment first = tangentArc(p0, u0, joint), second = tangentArc(joint, uj, p1);
  if ((joint - p0).norm() > 1e-12) out.push_back(first);
  if ((p1 - joint).norm() > 1e-12) out.push_back(second);
  return out;
}

BiarcFit fitBiarcs(const ParametricCurve& curve, const BiarcOptions& options) {
  BiarcFit fit;
  if (!(curve.t1 > curve.t0)) {
    fit.ok = false;
    return fit;
  }
  const Fitter f(curve, options);
  bool ok = true;
  std::vector<double> nodes = f.walk(options.tolerance, ok);
  if (nodes.empty()) {
    fit.overBudget = true;
    fit.ok = false;
    return fit;
  }
  if (options.equalise && ok && nodes.size() > 2 && nodes.size() <= kMostEqualisedSpans) {
    // The smallest target that still needs as many spans: the last span takes its share.
    const std::size_t n = nodes.size();
    double lo = 0.0, hi = options.tolerance;
    for (int i = 0; i < 24 && hi - lo > options.tolerance / kEqualisePrecision; ++i) {
      const double mid = 0.5 * (lo + hi);
      bool midOk = true;
      const std::vector<double> trial = f.walk(mid, midOk);
      if (midOk && !trial.empty() && trial.size() == n) {
        hi = mid;
        nodes = trial;
      } else {
        lo = mid;
      }
    }
  }
  fit.ok = ok;
  std::vector<Segment> pieces;
  for (std::size_t i = 0; i + 1 < nodes.size(); ++i) {
    BiarcSpan s;
    s.t0 = nodes[i];
    s.t1 = nodes[i + 1];
    s.error = f.span(s.t0, s.t1, pieces);
    if (!std::isfinite(s.error)) {  // a corner stepped over: join with a line
      pieces = {Segment::line(curve.point(s.t0), curve.point(s.t1))};
      s.error = 0.0;
      for (int k = 1; k <= options.samples; ++k)
        s.error =
            std::max(s.error, pieces[0].distanceTo(curve.point(s.t0 + (s.t1 - s.t0) * k / (options.samples + 1))));
    }
    s.first = fit.segments.size();
    s.count = pieces.size();
    fit.segments.insert(fit.segments.end(), pieces.begin(), pieces.end());
    fit.maxError = std::max(fit.maxError, s.error);
    fit.spans.push_back(s);
  }
  return fit;
}

BiarcFit fitPointList(const std::vector<Vec2>& points, const BiarcOptions& options) {
  std::vector<Vec2> pts;
  for (const Vec2& p : points)
    if (pts.empty() || (p - pts.back()).norm() > 1e-12) pts.push_back(p);
  if (pts.size() < 2 || pts.size() > kMostFitPoints) {
    BiarcFit none;
    none.ok = false;
    return none;
  }
  using Spline = Eigen::Spline<double, 2>;
  Eigen::Matrix<double, 2, Eigen::Dynamic> m(2, static_cast<Eigen::Index>(pts.size()));
  for (std::size_t i = 0; i < pts.size(); ++i) m.col(static_cast<Eigen::Index>(i)) = pts[i];
  const Eigen::Index degree = std::min<Eigen::Index>(3, static_cast<Eigen::Index>(pts.size()) - 1);
  const Spline spline = Eigen::SplineFitting<Spline>::Interpolate(m, degree);
  // A cubic B-spline lies in the hull of its control points: far outside the points' box, the
  // interpolation swings out between them (points very unevenly spaced), and the curve is no
  // drawing's.
  Box box;
  for (const Vec2& p : pts) box.add(p);
  const double reach = kMostSwing * std::max((box.max - box.min).norm(), 1.0);
  for (Eigen::Index i = 0; i < spline.ctrls().cols(); ++i) {
    const Vec2 c = spline.ctrls().col(i);
    const Vec2 outside = (box.min - c).cwiseMax(c - box.max).cwiseMax(Vec2::Zero());
    if (!std::isfinite(c.x()) || !std::isfinite(c.y()) || outside.norm() > reach) {
      BiarcFit none;
      none.ok = false;
      none.swings = true;
      return none;
    }
  }
  // Its knots and control points, evaluated without allocating (BSpline).
  auto curveOf = std::make_shared<BSpline>();
  curveOf->degree = static_cast<std::size_t>(spline.degree());
  for (Eigen::Index i = 0; i < spline.knots().size(); ++i) curveOf->knots.push_back(spline.knots()(i));
  for (Eigen::Index i = 0; i < spline.ctrls().cols(); ++i) curveOf->control.push_back(spline.ctrls().col(i));
  auto slopeOf = std::make_shared<BSpline>(curveOf->derivative());
  ParametricCurve curve;
  curve.point = [curveOf](double u) -> Vec2 { return curveOf->at(std::clamp(u, 0.0, 1.0)); };
  curve.derivative = [slopeOf](double u) -> Vec2 { return slopeOf->at(std::clamp(u, 0.0, 1.0)); };
  curve.t0 = 0.0;
  curve.t1 = 1.0;
  return fitBiarcs(curve, options);
}

}  // namespace kerf::geometry
