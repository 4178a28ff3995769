// Ruled surfaces (ruled_surface.h): the wire between its two contours, its measures, its sections
// at a height and its mesh.
// Sections: 1. points, normals and slope  2. measures of a patch  3. sections at a height  4. the mesh
#include "kerf/geometry/ruled_surface.h"

#include "kerf/geometry/tessellation.h"

#include "angles.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

namespace kerf::geometry {
namespace {

// ---- 1. points, normals and slope ---------------------------------------------------------------

/// dL/dt: the tangent scaled by the length (t runs over [0, 1]).
Vec2 derivative(const Segment& s, double t) { return s.tangentAt(t) * s.length(); }

Vec2 offsetAt(const Segment& lower, const Segment& upper, double t) { return upper.pointAt(t) - lower.pointAt(t); }

/// A segment's points at t = t0, t0 + dt, t0 + 2 dt, ... in turn: a line by t, an arc by rotating
/// its radius one step at a time (one sine and cosine for the walk, not one per point; a few
/// 1e-16 of the radius of drift per step).
class Walk {
 public:
  Walk(const Segment& s, double t0, double dt) : s_(s) {
    if (!s.isArc()) return;
    const double a = s.startAngle() + t0 * s.sweep, step = s.sweep * dt;
    radius_ = s.radius() * Vec2(std::cos(a), std::sin(a));
    rotation_ = Vec2(std::cos(step), std::sin(step));
  }
  /// The point at t, the parameter the walk has reached.
  [[nodiscard]] Vec2 point(double t) const { return s_.isArc() ? Vec2(s_.centre + radius_) : s_.pointAt(t); }
  /// dP/dt there.
  [[nodiscard]] Vec2 derivative() const {
    return s_.isArc() ? Vec2(s_.sweep * Vec2(-radius_.y(), radius_.x())) : Vec2(s_.end - s_.start);
  }
  void next() {
    if (!s_.isArc()) return;
    radius_ = Vec2(rotation_.x() * radius_.x() - rotation_.y() * radius_.y(),
                   rotation_.y() * radius_.x() + rotation_.x() * radius_.y());
  }

 private:
  const Segment& s_;
  Vec2 radius_{0, 0};
  Vec2 rotation_{1, 0};
};

/// A point of a segment and its first two derivatives in t (an arc: one sine and cosine).
struct PointJet {
  Vec2 p, d, dd;
};
PointJet jetAt(const Segment& s, double t) {
  if (!s.isArc()) return {s.pointAt(t), s.end - s.start, Vec2::Zero()};
  const double a = s.startAngle() + t * s.sweep;
  const Vec2 r = s.radius() * Vec2(std::cos(a), std::sin(a));
  // The ends exactly, as pointAt gives them (the samples use those).
  const Vec2 p = t <= 0.0 ? s.start : t >= 1.0 ? s.end : Vec2(s.centre + r);
  return {p, s.sweep * Vec2(-r.y(), r.x()), -s.sweep * s.sweep * r};
}

/// A smooth function of t, its slope and curvature.
struct Jet {
  double v, d1, d2;
};

/// The maximum of a smooth g (g(t) gives its Jet) near the best of the samples, h apart: Newton's
/// steps on g' = 0 inside a bracket [t - h, t + h] that each slope's sign narrows (the maximum is
/// uphill), bisection where a step would leave it or g curves up; to 1e-12 in t. About four
/// evaluations for a smooth extreme where Brent's method without derivatives took a dozen.
template <typename G>
double newtonMax(G&& g, double t0, double h) {
  double a = std::max(0.0, t0 - h), b = std::min(1.0, t0 + h), t = std::clamp(t0, a, b);
  for (int iteration = 0; iteration < 100 && b - a > 1e-12; ++iteration) {
    const Jet j = g(t);
    if (j.d1 > 0)
      a = t;
    else if (j.d1 < 0)
      b = t;
    else
      break;
    double next = j.d2 < 0 ? t - j.d1 / j.d2 : 0.5 * (a + b);
    if (!(next > a && next < b)) next = 0.5 * (a + b);
    const bool done = std::abs(next - t) <= 1e-13;
    t = next;
    if (done) break;
  }
  return t;
}

/// Tangent angle of travel at t (unwrapped: linear in t).
double tangentAngle(const Segment& s, double t) {
  if (!s.isArc()) return angleOf(s.end - s.start);
  const double turn = s.sweep >= 0 ? kPi / 2 : -kPi / 2;
  return s.startAngle() + t * s.sweep + turn;
}

double wrapSigned(double a) {
  double r = detail::wrapPositive(a);
  return r > kPi ? r - kTwoPi : r;
}

}  // namespace

Vec3 surfacePoint(const Segment& lower, const Segment& upper, const Planes& planes, double t, double s) {
  const Vec2 p = (1.0 - s) * lower.pointAt(t) + s * upper.pointAt(t);
  return {p.x(), p.y(), planes.lower + s * planes.height()};
}

Vec3 surfaceNormal(const Segment& lower, const Segment& upper, const Planes& planes, double t, double s) {
  const Vec2 dt = (1.0 - s) * derivative(lower, t) + s * derivative(upper, t);
  const Vec2 off = offsetAt(lower, upper, t);
  const Vec3 pt(dt.x(), dt.y(), 0.0), ps(off.x(), off.y(), planes.height());
  const Vec3 n = pt.cross(ps);
  const double len = n.norm();
  return len > 0 ? Vec3(n / len) : Vec3(Vec3::Zero());
}

double slopeAt(const Segment& lower, const Segment& upper, const Planes& planes, double t) {
  return std::atan2(offsetAt(lower, upper, t).norm(), planes.height());
}

// ---- 2. measures of a patch ---------------------------------------------------------------------

PatchMeasures measurePatch(const Segment& lower, const Segment& upper, const Planes& planes) {
  PatchMeasures m;
  const double h0 = planes.height();
  if (!lower.isArc() && !upper.isArc()) {
    // The offset a + t b is linear in t: |.| is convex, so the maximum is at an end and the
    // minimum at the foot of the perpendicular from the origin.
    m.exact = true;
    const Vec2 a = upper.start - lower.start, b = (upper.end - lower.end) - a;
    const double bb = b.squaredNorm();
    const double tMin = bb > 0 ? std::clamp(-a.dot(b) / bb, 0.0, 1.0) : 0.0;
    const double n0 = a.norm(), n1 = (a + b).norm();
    m.minSlope = {std::atan2((a + tMin * b).norm(), h0), tMin};
    m.maxSlope = n1 > n0 ? Extreme{std::atan2(n1, h0), 1.0} : Extreme{std::atan2(n0, h0), 0.0};
    m.maxOffsetX = std::abs(a.x() + b.x()) > std::abs(a.x()) ? Extreme{std::abs(a.x() + b.x()), 1.0}
                                                             : Extreme{std::abs(a.x()), 0.0};
    m.maxOffsetY = std::abs(a.y() + b.y()) > std::abs(a.y()) ? Extreme{std::abs(a.y() + b.y()), 1.0}
                                                             : Extreme{std::abs(a.y()), 0.0};
    return m;
  }
  // One pass of samples for all four measures, then each extreme refined where it was best. The
  // samples walk each arc by a fixed rotation (no sine or cosine per sample; 64 steps drift by
  // a few 1e-16 of the radius), ends exact.
  Extreme big{-1, 0}, small{-1, 0}, bx{-1, 0}, by{-1, 0};
  Walk lw(lower, 0.0, 1.0 / kExtremeSamples), uw(upper, 0.0, 1.0 / kExtremeSamples);
  for (int i = 0; i <= kExtremeSamples; ++i) {
    const double t = static_cast<double>(i) / kExtremeSamples;
    const Vec2 o = i == kExtremeSamples ? Vec2(upper.end - lower.end) : Vec2(uw.point(t) - lw.point(t));
    lw.next();
    uw.next();
    const double n = o.norm();
    if (n > big.value) big = {n, t};
    if (-n > small.value || small.value == -1) small = {-n, t};
    if (std::abs(o.x()) > bx.value) bx = {std::abs(o.x()), t};
    if (std::abs(o.y()) > by.value) by = {std::abs(o.y()), t};
  }
  const double h = 1.0 / kExtremeSamples;
  // The offset o = U - L and its derivatives; each measure is the maximum of a smooth function of
  // them: |o|^2, -|o|^2, o.x^2, o.y^2.
  auto offsetJet = [&](double t) {
    const PointJet u = jetAt(upper, t), l = jetAt(lower, t);
    return PointJet{u.p - l.p, u.d - l.d, u.dd - l.dd};
  };
  auto squaredNorm = [&](double t) {
    const PointJet o = offsetJet(t);
    return Jet{o.p.squaredNorm(), 2 * o.p.dot(o.d), 2 * (o.d.squaredNorm() + o.p.dot(o.dd))};
  };
  auto axis = [&](int k) {
    return [&, k](double t) {
      const PointJet o = offsetJet(t);
      return Jet{o.p[k] * o.p[k], 2 * o.p[k] * o.d[k], 2 * (o.d[k] * o.d[k] + o.p[k] * o.dd[k])};
    };
  };
  // The refined point replaces the sample only where it is better (exactly computed, both).
  auto better = [](Extreme sample, double t, double value) {
    return value > sample.value ? Extreme{value, t} : sample;
  };
  {
    const double t = newtonMax(squaredNorm, big.t, h);
    big = better(big, t, offsetAt(lower, upper, t).norm());
  }
  {
    const double t = newtonMax(
        [&](double x) {
          const Jet j = squaredNorm(x);
          return Jet{-j.v, -j.d1, -j.d2};
        },
        small.t, h);
    small = better(small, t, -offsetAt(lower, upper, t).norm());
  }
  m.maxSlope = {std::atan2(big.value, h0), big.t};
  m.minSlope = {std::atan2(-small.value, h0), small.t};
  {
    const double t = newtonMax(axis(0), bx.t, h);
    m.maxOffsetX = better(bx, t, std::abs(offsetAt(lower, upper, t).x()));
  }
  {
    const double t = newtonMax(axis(1), by.t, h);
    m.maxOffsetY = better(by, t, std::abs(offsetAt(lower, upper, t).y()));
  }
  return m;
}

double patchArea(const Segment& lower, const Segment& upper, const Planes& planes) {
  // 5-point Gauss-Legendre on [0, 1].
  static constexpr std::array<double, 5> kNode = {0.046910077030668, 0.230765344947158, 0.5, 0.769234655052842,
                                                  0.953089922969332};
  static constexpr std::array<double, 5> kWeight = {0.118463442528095, 0.239314335249683, 0.284444444444444,
                                                    0.239314335249683, 0.118463442528095};
  auto pieces = [](const Segment& s) {
    return s.isArc() ? std::max(1, static_cast<int>(std::ceil(std::abs(s.sweep) / (kPi / 8)))) : 1;
  };
  const int n = std::max(pieces(lower), pieces(upper));
  const double h = planes.height();
  // Node i of piece k is at t = (k + node_i) / n: for each node, a walk over the pieces.
  double area = 0.0;
  for (std::size_t i = 0; i < kNode.size(); ++i) {
    Walk lw(lower, kNode[i] / n, 1.0 / n), uw(upper, kNode[i] / n, 1.0 / n);
    for (int k = 0; k < n; ++k, lw.next(), uw.next()) {
      const double t = (k + kNode[i]) / n;
      const Vec2 dl = lw.derivative(), du = uw.derivative();
      const Vec2 off = uw.point(t) - lw.point(t);
      const Vec3 ps(off.x(), off.y(), h);
      double inner = 0.0;
      for (std::size_t j = 0; j < kNode.size(); ++j) {
        const Vec2 dt = (1.0 - kNode[j]) * dl + kNode[j] * du;
        inner += kWeight[j] * Vec3(dt.x(), dt.y(), 0.0).cross(ps).norm();
      }
      area += kWeight[i] * inner / n;
    }
  }
  return area;
}

TwistMeasure measureTwist(const Segment& lower, const Segment& upper) {
  TwistMeasure m;
  constexpr double kShort = 1e-9;
  if (lower.length() <= kShort || upper.length() <= kShort) return m;
  m.defined = true;
  // d(t) = d0 + t (d1 - d0) unwrapped; the angle between the directions is |wrap(d(t))|.
  const double d0 = wrapSigned(tangentAngle(upper, 0.0) - tangentAngle(lower, 0.0));
  const double d1 = d0 + (upper.isArc() ? upper.sweep : 0.0) - (lower.isArc() ? lower.sweep : 0.0);
  const double lo = std::min(d0, d1), hi = std::max(d0, d1);
  // Does [lo, hi] contain an odd multiple of pi (directions exactly opposite)?
  const double k = std::ceil((lo - kPi) / kTwoPi);
  const double oddPi = kPi + k * kTwoPi;
  if (oddPi <= hi) {
    m.maxAngle = kPi;
    m.t = d1 != d0 ? (oddPi - d0) / (d1 - d0) : 0.0;
    return m;
  }
  const double a0 = std::abs(wrapSigned(d0)), a1 = std::abs(wrapSigned(d1));
  m.maxAngle = std::max(a0, a1);
  m.t = a1 > a0 ? 1.0 : 0.0;
  return m;
}

std::optional<double> foldAtJoint(const Segment& lowerA, const Segment& upperA, const Segment& lowerB,
                                  const Segment& upperB) {
  // Section directions at the joint: dA(s) = a + s b (end of A), dB(s) = c + s d (start of B).
  const Vec2 a = derivative(lowerA, 1.0), b = derivative(upperA, 1.0) - a;
  const Vec2 c = derivative(lowerB, 0.0), d = derivative(upperB, 0.0) - c;
  const double k0 = cross(a, c), k1 = cross(a, d) + cross(b, c), k2 = cross(b, d);
  double roots[2];
  int count = 0;
  const double scale = std::max({a.squaredNorm(), b.squaredNorm(), c.squaredNorm(), d.squaredNorm(), 1e-300});
  if (std::abs(k2) <= 1e-14 * scale) {
    if (std::abs(k1) > 1e-14 * scale) roots[count++] = -k0 / k1;
  } else {
    const double disc = k1 * k1 - 4 * k2 * k0;
    if (disc >= 0) {
      const double q = -0.5 * (k1 + std::copysign(std::sqrt(disc), k1));
      roots[count++] = q / k2;
      if (q != 0.0) roots[count++] = k0 / q;
    }
  }
  std::optional<double> best;
  for (int i = 0; i < count; ++i) {
    const double s = roots[i];
    if (!(s > 1e-9 && s < 1.0 - 1e-9)) continue;
    const Vec2 da = a + s * b, db = c + s * d;
    if (da.norm() <= 1e-12 || db.norm() <= 1e-12) continue;
    if (da.dot(db) < 0 && (!best || s < *best)) best = s;
  }
  return best;
}

namespace {

// ---- 3. sections at a height --------------------------------------------------------------------

/// The section of a patch at s as one exact segment (a line, or an arc), if it is one.
std::optional<Segment> singleSection(const Segment& lower, const Segment& upper, double s, double tolerance,
                                     bool& exact) {
  const Vec2 a = (1.0 - s) * lower.start + s * upper.start;
  const Vec2 b = (1.0 - s) * lower.end + s * upper.end;
  exact = true;
  if (!lower.isArc() && !upper.isArc()) return Segment::line(a, b);
  if (lower.isArc() && upper.isArc()) {
    // Two arcs turning at the same rate: (1-s)(cL + rL e(aL + w t)) + s(cU + rU e(aU + w t)) is
    // c_s + |z| e(arg z + w t) with z = (1-s) rL e(aL) + s rU e(aU): again an arc. When the
    // sweeps differ by d (rounding in the program), the arc with the mean sweep is within
    // d max(rL, rU) of the true section; that is accepted up to half the tolerance.
    const double d = std::abs(lower.sweep - upper.sweep);
    const Vec2 z =
        (1.0 - s) * lower.radius() * direction(lower.startAngle()) + s * upper.radius() * direction(upper.startAngle());
    if (d * std::max(lower.radius(), upper.radius()) <= tolerance / 2 && z.norm() > tolerance) {
      Segment arc = lower;
      arc.centre = (1.0 - s) * lower.centre + s * upper.centre;
      arc.start = a;
      arc.end = b;
      arc.sweep = (1.0 - s) * lower.sweep + s * upper.sweep;
      exact = d == 0.0;
      return arc;
    }
  }
  return std::nullopt;
}

std::size_t polylinePieces(const Segment& lower, const Segment& upper, double tolerance) {
  const Sampling tol = Sampling::tolerance(tolerance);
  return std::min(kMaxSectionPieces, std::max<std::size_t>({2, sampleCount(lower, tol), sampleCount(upper, tol)}));
}

}  // namespace

std::size_t sectionPieces(const Segment& lower, const Segment& upper, double s, double tolerance) {
  bool exact = false;
  if (singleSection(lower, upper, s, tolerance, exact)) return 1;
  return polylinePieces(lower, upper, tolerance);
}

bool appendSection(const Segment& lower, const Segment& upper, double s, double tolerance, std::vector<Segment>& out,
                   std::size_t maxPieces) {
  bool exact = false;
  if (std::optional<Segment> one = singleSection(lower, upper, s, tolerance, exact)) {
    out.push_back(*one);
    return exact;
  }
  const Vec2 a = (1.0 - s) * lower.start + s * upper.start;
  const Vec2 b = (1.0 - s) * lower.end + s * upper.end;
  const std::size_t n = std::max<std::size_t>(2, std::min(maxPieces, polylinePieces(lower, upper, tolerance)));
  Vec2 prev = a;
  for (std::size_t i = 1; i <= n; ++i) {
    const double t = static_cast<double>(i) / static_cast<double>(n);
    const Vec2 p = i == n ? b : Vec2((1.0 - s) * lower.pointAt(t) + s * upper.pointAt(t));
    out.push_back(Segment::line(prev, p));
    prev = p;
  }
  return false;
}

// ---- 4. the mesh --------------------------------------------------------------------------------

namespace {

struct Generator {
  Vec2 bottom, top;
  std::uint32_t cuts = 1;  ///< pieces along s
  std::uint32_t firstVertex = 0;
};

/// Pieces along s that keep the cell between generators a and b within tol of the bilinear
/// surface: the triangles of a bilinear cell deviate by at most |P00 + P11 - P10 - P01| / 4.
std::uint32_t cutsFor(const Generator& a, const Generator& b, double tol) {
  const double twist = ((a.bottom + b.top) - (b.bottom + a.top)).norm();
  const double need = std::ceil(twist / (4.0 * tol));
  return static_cast<std::uint32_t>(std::clamp(need, 1.0, static_cast<double>(kMaxMeshCuts)));
}

/// Ear clipping of a simple polygon given as vertex indices; triangles follow the polygon's
/// winding. False when no ear is found (the polygon is not simple).
///
/// The polygon is a linked ring; the search for the next ear goes on from the last one clipped
/// instead of starting over, and only reflex (and flat) vertices are tested for lying inside a
/// candidate ear — no other vertex can lie inside a convex triangle of a simple polygon, and
/// clipping never makes a convex vertex reflex (D. Eberly, Triangulation by Ear Clipping, 2002).
/// Caps of real parts are mostly convex: about n² / 2 cheap steps instead of n³.
bool earClip(const std::vector<Vec3>& v, std::vector<std::uint32_t> poly, bool reverse,
             std::vector<std::array<std::uint32_t, 3>>& result) {
  if (reverse) std::reverse(poly.begin(), poly.end());
  const std::size_t n = poly.size();
  if (n < 3) return false;
  auto p = [&](std::size_t i) { return Vec2(v[poly[i]].x(), v[poly[i]].y()); };
  double area2 = 0.0;
  for (std::size_t i = 0; i < n; ++i) area2 += cross(p(i), p((i + 1) % n));
  const double sign = area2 >= 0 ? 1.0 : -1.0;
  std::vector<std::size_t> prev(n), next(n);
  for (std::size_t i = 0; i < n; ++i) {
    prev[i] = (i + n - 1) % n;
    next[i] = (i + 1) % n;
  }
  auto turnAt = [&](std::size_t i) {
    const Vec2 a = p(prev[i]), b = p(i), c = p(next[i]);
    return sign * cross(b - a, c - b);
  };
  auto flatAt = [&](std::size_t i) {
    const Vec2 a = p(prev[i]), b = p(i), c = p(next[i]);
    return std::abs(turnAt(i)) <= 1e-12 * (b - a).norm() * (c - b).norm() && (b - a).dot(c - b) > 0;
  };
  // Reflex or flat: the only vertices that can lie inside an ear. The list only shrinks.
  std::vector<char> blocking(n, 0), alive(n, 1);
  std::vector<std::size_t> blockers;
  for (std::size_t i = 0; i < n; ++i)
    if (turnAt(i) <= 0 || flatAt(i)) {
      blocking[i] = 1;
      blockers.push_back(i);
    }
  std::vector<std::array<std::uint32_t, 3>> out;
  out.reserve(n - 2);
  std::size_t left = n, cur = 0, stalled = 0;
  int pass = 0;  // 0: a proper (convex) ear; 1: a flat one (a vertex in a straight run), when no proper ear is left
  while (left > 3) {
    const std::size_t ia = prev[cur], ic = next[cur];
    const double turn = turnAt(cur);
    const bool flat = flatAt(cur);
    bool ear = pass == 0 ? turn > 0 && !flat : flat;
    if (ear) {
      const Vec2 a = p(ia), b = p(cur), c = p(ic);
      for (const std::size_t q : blockers) {
        if (!alive[q] || !blocking[q] || q == ia || q == cur || q == ic) continue;
        const Vec2 x = p(q);
        if (sign * cross(b - a, x - a) > 0 && sign * cross(c - b, x - b) > 0 && sign * cross(a - c, x - c) > 0) {
          ear = false;
          break;
        }
      }
    }
    if (!ear) {
      cur = next[cur];
      if (++stalled > left) {
        if (pass == 1) return false;
        pass = 1;
        stalled = 0;
      }
      continue;
    }
    out.push_back({poly[ia], poly[cur], poly[ic]});
    alive[cur] = 0;
    next[ia] = ic;
    prev[ic] = ia;
    --left;
    for (const std::size_t k : {ia, ic})
      if (blocking[k] && turnAt(k) > 0 && !flatAt(k)) blocking[k] = 0;
    cur = ia;
    stalled = 0;
    pass = 0;
  }
  out.push_back({poly[prev[cur]], poly[cur], poly[next[cur]]});
  result.insert(result.end(), out.begin(), out.end());
  return true;
}

}  // namespace

namespace {

constexpr double kJoin = 1e-9;  ///< mm: ends this close join two patches into one strip

/// The generators of the strip of patches [i, j): every patch cut into pieces within the chord
/// tolerance (at least minTaperPieces where the wire leans), while the cells stay within maxCells.
/// `k` is set to the first patch not made; `cellPatch` receives each cell's patch.
std::vector<Generator> stripGenerators(std::span<const Segment> lower, std::span<const Segment> upper, std::size_t i,
                                       std::size_t j, const MeshOptions& options, std::size_t maxCells, std::size_t& k,
                                       std::vector<std::uint32_t>& cellPatch) {
  const Sampling sampling = Sampling::tolerance(options.tolerance / 2);
  std::vector<Generator> gens;
  gens.push_back({lower[i].start, upper[i].start});
  for (k = i; k < j && gens.size() <= maxCells; ++k) {
    const bool leans = (upper[k].start - lower[k].start).norm() > kJoin || (upper[k].end - lower[k].end).norm() > kJoin;
    std::size_t forced = leans ? options.minTaperPieces : std::size_t{1};
    if (forced > 1 && options.minForcedPieceLength > 0.0) {
      const double fit = std::max(lower[k].length(), upper[k].length()) / options.minForcedPieceLength;
      forced = std::clamp<std::size_t>(static_cast<std::size_t>(std::min(fit, 1e9)), 1, forced);
    }
    const std::size_t pieces =
        std::min(kMaxMeshPieces, std::max({sampleCount(lower[k], sampling), sampleCount(upper[k], sampling), forced}));
    for (std::size_t q = 1; q <= pieces; ++q) {
      const double t = static_cast<double>(q) / static_cast<double>(pieces);
      gens.push_back({lower[k].pointAt(t), upper[k].pointAt(t)});
      cellPatch.push_back(static_cast<std::uint32_t>(k));
    }
  }
  return gens;
}

/// Each generator's points along the wire, lower plane to upper: the first `own` generators (a
/// closed strip's last one is its first).
void addStripVertices(Mesh& mesh, std::vector<Generator>& gens, std::size_t own, const Planes& planes) {
  for (std::size_t g = 0; g < own; ++g) {
    gens[g].firstVertex = static_cast<std::uint32_t>(mesh.vertices.size());
    const auto slope = static_cast<float>(std::atan2((gens[g].top - gens[g].bottom).norm(), planes.height()));
    for (std::uint32_t q = 0; q <= gens[g].cuts; ++q) {
      const double s = static_cast<double>(q) / gens[g].cuts;
      const Vec2 p = (1.0 - s) * gens[g].bottom + s * gens[g].top;
      mesh.vertices.emplace_back(p.x(), p.y(), planes.lower + s * planes.height());
      mesh.vertexSlope.push_back(slope);
    }
  }
}

/// Neighbouring generators zipped together, advancing whichever has the lower next s.
void zipStrip(Mesh& mesh, const std::vector<Generator>& gens, const std::vector<std::uint32_t>& cellPatch) {
  for (std::size_t c = 0; c + 1 < gens.size(); ++c) {
    const Generator& a = gens[c];
    const Generator& b = gens[c + 1];
    std::uint32_t ia = 0, ib = 0;
    while (ia < a.cuts || ib < b.cuts) {
      const bool advanceA =
          ia < a.cuts && (ib == b.cuts || static_cast<double>(ia + 1) / a.cuts <= static_cast<double>(ib + 1) / b.cuts);
      if (advanceA) {
        mesh.triangles.push_back({a.firstVertex + ia, b.firstVertex + ib, a.firstVertex + ia + 1});
        ++ia;
      } else {
        mesh.triangles.push_back({a.firstVertex + ia, b.firstVertex + ib, b.firstVertex + ib + 1});
        ++ib;
      }
      mesh.trianglePatch.push_back(cellPatch[c]);
    }
  }
}

/// A closed strip's caps on the planes asked for. The side triangles run along the bottom edge
/// forwards and the top edge backwards, so the lower cap takes the contour reversed and the upper
/// cap as it is.
void capStrip(Mesh& mesh, const std::vector<Generator>& gens, std::size_t own, const MeshOptions& options) {
  std::vector<std::uint32_t> bottom, top;
  for (std::size_t g = 0; g < own; ++g) {
    bottom.push_back(gens[g].firstVertex);
    top.push_back(gens[g].firstVertex + gens[g].cuts);
  }
  std::vector<std::array<std::uint32_t, 3>> caps;
  if (options.lowerCap && earClip(mesh.vertices, bottom, true, caps)) ++mesh.capsMade;
  if (options.upperCap && earClip(mesh.vertices, top, false, caps)) ++mesh.capsMade;
  for (const auto& tri : caps) {
    mesh.triangles.push_back(tri);
    mesh.trianglePatch.push_back(kCapPatch);
  }
}

}  // namespace

Mesh meshRuledSurface(std::span<const Segment> lower, std::span<const Segment> upper, const Planes& planes,
                      const MeshOptions& options) {
  Mesh mesh;
  const std::size_t n = std::min(lower.size(), upper.size());
  const double twistTol = options.tolerance / 2;
  std::size_t i = 0;
  while (i < n) {
    // One strip: patches joined end to start on both planes.
    std::size_t j = i + 1;
    while (j < n && (lower[j].start - lower[j - 1].end).norm() <= kJoin &&
           (upper[j].start - upper[j - 1].end).norm() <= kJoin)
      ++j;
    // Every cell between two generators makes at least two triangles: stop making generators
    // once the cells alone would pass the budget, so memory follows the budget, not the moves.
    const std::size_t budget = options.maxTriangles - std::min(options.maxTriangles, mesh.triangles.size());
    if (budget == 0) {
      mesh.truncated = true;
      return mesh;
    }
    std::size_t k = i;
    std::vector<std::uint32_t> cellPatch;
    std::vector<Generator> gens = stripGenerators(lower, upper, i, j, options, budget / 2, k, cellPatch);
    bool closed = k == j && j - i > 1 && (gens.back().bottom - gens.front().bottom).norm() <= kJoin &&
                  (gens.back().top - gens.front().top).norm() <= kJoin;
    for (std::size_t c = 0; c + 1 < gens.size(); ++c) {
      const std::uint32_t cuts = cutsFor(gens[c], gens[c + 1], twistTol);
      gens[c].cuts = std::max(gens[c].cuts, cuts);
      gens[c + 1].cuts = std::max(gens[c + 1].cuts, cuts);
    }
    if (closed) gens.front().cuts = gens.back().cuts = std::max(gens.front().cuts, gens.back().cuts);
    // Count the strip's triangles (cell c makes a.cuts + b.cuts) before making any vertex: the
    // cells past the budget are never made, and the mesh says it is incomplete.
    std::size_t fit = 0;
    for (std::size_t used = 0; fit + 1 < gens.size(); ++fit) {
      const std::size_t cell = std::size_t{gens[fit].cuts} + gens[fit + 1].cuts;
      if (used + cell > budget) break;
      used += cell;
    }
    const bool truncated = fit + 1 < gens.size() || k < j;
    if (fit + 1 < gens.size()) {
      gens.resize(fit + 1);
      closed = false;
    }
    const std::size_t own = closed ? gens.size() - 1 : gens.size();
    addStripVertices(mesh, gens, own, planes);
    if (closed) gens.back().firstVertex = gens.front().firstVertex;
    zipStrip(mesh, gens, cellPatch);
    if (closed && (options.lowerCap || options.upperCap) && own >= 3 && own <= options.maxCapVertices)
      capStrip(mesh, gens, own, options);
    if (truncated) {
      mesh.truncated = true;
      return mesh;
    }
    i = j;
  }
  return mesh;
}

}  // namespace kerf::geometry
