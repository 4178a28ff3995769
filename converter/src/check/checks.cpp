// The checks of a toolpath (checks.h): each plane's contours, the ruled surface, the cut runs.
// Sections: 1. contacts that close a contour  2. a contour's self-intersection and closure
//           3. the ruled surface  4. the cut runs and the toolpath
#include "kerf/converter/check/checks.h"
#include "finding.h"

#include "kerf/converter/structure/passes.h"

#include "kerf/converter/check/pass_checks.h"
#include "kerf/converter/check/summary.h"
#include "kerf/converter/nc/number_format.h"
#include "kerf/geometry/contour.h"
#include "kerf/geometry/intersection.h"
#include "kerf/geometry/parallel.h"
#include "kerf/geometry/ruled_surface.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <span>
#include <string>
#include <utility>

namespace kerf::converter {
namespace {

// ---- 1. contacts that close a contour -----------------------------------------------------------

std::string deg(double radians) { return formatFixed(radians * geometry::kDegreesPerRadian, 3) + "°"; }

/// A lead-out over the lead-in: the later move runs back along the earlier one, in the opposite
/// direction, and ends where the earlier one started (the start hole). The kerf there is open
/// already, so the wire cuts nothing new.
bool isRetrace(const geometry::Segment& earlier, const geometry::Segment& later, const geometry::Contact& c,
               double tol) {
  return c.opposite && (later.end - earlier.start).norm() <= tol;
}

/// A touch that closes the contour: the loop from the first visit of the point to the second is
/// the part, and nothing is cut after it — the path ends there, or runs back along its way in (a
/// lead-out over the lead-in written in one block). The same path with that block split at the
/// point meets itself only at shared vertices, which is no contact: this keeps the verdict the
/// same however the blocks are split.
bool closesTheContour(geometry::SegmentView path, const geometry::Contact& x, double tol) {
  const geometry::Segment& a = path[x.first];
  const geometry::Segment& b = path[x.second];
  const double ta = a.parameterOf(x.point), tb = b.parameterOf(x.point);
  double head = ta * a.length(), tail = (1.0 - tb) * b.length();
  for (std::size_t k = 0; k < x.first; ++k) head += path[k].length();
  for (std::size_t k = x.second + 1; k < path.size(); ++k) tail += path[k].length();
  if (tail <= tol) return true;
  if ((path.back().end - path.front().start).norm() > tol) return false;
  if (std::abs(tail - head) > 4 * tol + 1e-9 * (head + tail)) return false;
  auto onHead = [&](const geometry::Vec2& p) {
    for (std::size_t k = 0; k <= x.first; ++k)
      if (path[k].distanceTo(p) <= tol) return true;
    return false;
  };
  for (double s : {0.0, 0.25, 0.5, 0.75, 1.0})
    if (!onHead(b.pointAt(tb + (1.0 - tb) * s))) return false;
  for (std::size_t k = x.second + 1; k < path.size(); ++k)
    for (double s : {0.0, 0.25, 0.5, 0.75, 1.0})
      if (!onHead(path[k].pointAt(s))) return false;
  return true;
}

using MovePairs = std::set<std::pair<std::size_t, std::size_t>>;

/// Two moves whose lower segments share an end point: where a taper starts and finishes at the
/// same place (the start point of a closed contour), the wire leans one way on the way in and the
/// other way on the way out, so above the lower plane their patches touch or overlap. The kerf
/// there is cut already; this is the taper's seam, not a fault.
/// Where the programmed contour lies between the planes (0: lower, 1: upper).
double programLevel(const Toolpath& tp) {
  const PlaneHeights& h = tp.heights;
  return h.known ? std::clamp((h.programZ - h.planes.lower) / h.planes.height(), 0.0, 1.0) : 0.0;
}

/// Move i's end points on the programmed contour's plane.
std::pair<geometry::Vec2, geometry::Vec2> programEnds(const Toolpath& tp, std::size_t i) {
  const double s = programLevel(tp);
  const geometry::Segment& l = tp.moves[i].lower;
  const geometry::Segment& u = tp.upperOf(i);
  return {(1.0 - s) * l.start + s * u.start, (1.0 - s) * l.end + s * u.end};
}

bool atSeam(const Toolpath& tp, std::size_t a, std::size_t b, double tol) {
  const auto [ps, pe] = programEnds(tp, a);
  const auto [qs, qe] = programEnds(tp, b);
  return (ps - qe).norm() <= tol || (pe - qs).norm() <= tol || (ps - qs).norm() <= tol || (pe - qe).norm() <= tol;
}

/// The seam's contacts on one contour, or in all the sections of one surface, said in one note at
/// the first (a new user's first screen should say what matters, not the same note three times).
class SeamNote {
 public:
  /// The later move mj meets the earlier move mi at p, at the seam.
  void add(std::size_t mi, std::size_t mj, const geometry::Vec3& p) {
    if (pairs_.empty()) point_ = p;
    pairs_.emplace_back(mi, mj);
  }

  void report(const Toolpath& tp, const SourceFile* src, const std::string& where, Diagnostics& diags) const {
    if (pairs_.empty()) return;
    std::set<std::uint32_t> earlier, later;
    for (const auto& [mi, mj] : pairs_) {
      earlier.insert(tp.moves[mi].line);
      later.insert(tp.moves[mj].line);
    }
    const std::size_t mj = pairs_.front().second;
    const std::string message =
        pairs_.size() == 1
            ? "the wire passes the start point twice" + where + " (the move on line " +
                  std::to_string(tp.moves[pairs_.front().first].line) + " leans the other way): the taper's seam"
            : "the wire passes the start point twice" + where + ": the " + linesText(later) + " meet the " +
                  linesText(earlier) + ", which lean the other way: the taper's seam";
    diags.report(finding(Severity::Note, Code::TaperSeam, src, tp.moves[mj], mj, point_, message));
  }

 private:
  /// "move on line 21", "moves on lines 12 and 13", "moves on lines 3, 5 and 9".
  static std::string linesText(const std::set<std::uint32_t>& lines) {
    std::string text = lines.size() == 1 ? "move on line " : "moves on lines ";
    std::size_t k = 0;
    for (const std::uint32_t l : lines) {
      if (k > 0) text += k + 1 == lines.size() ? " and " : ", ";
      text += std::to_string(l);
      ++k;
    }
    return text;
  }

  std::vector<std::pair<std::size_t, std::size_t>> pairs_;
  geometry::Vec3 point_ = geometry::Vec3::Zero();
};

// ---- 2. a contour's self-intersection and closure -----------------------------------------------

/// One plane's contour: the segments of the cut moves in order and each one's move.
/// One contour to test: views of segments and their moves held elsewhere (the cut path is not
/// copied again for it).
struct PlaneContour {
  geometry::SegmentView segments;
  MoveIndex moveIndex;
  std::string name = "the cut path";  ///< how messages name it
  double z = 0.0;
  bool upperPlane = false;
  bool seamAllowed = false;  ///< a taper program: contacts at the taper's seam are notes
};

/// A contour's self-intersections, exact on lines and arcs, and its closure: the first loop
/// comes from the same sweep when it met every pair, else from the closure's own search.
struct ContourTest {
  geometry::SelfIntersectionResult result;
  geometry::ClosureReport closure;
};

ContourTest testContour(const PlaneContour& c, const CheckOptions& options) {
  ContourTest t;
  const geometry::SegmentView& s = c.segments;
  t.closure.gap = (s.back().end - s.front().start).norm();
  t.closure.endsAtStart = t.closure.gap <= options.tolerance;
  geometry::SelfIntersectionOptions so;
  so.tolerance = options.tolerance;
  so.closed = t.closure.endsAtStart;
  so.maxContacts = options.maxContacts;
  so.findLoop = true;
  t.result = geometry::findSelfIntersections(s, so);
  if (t.result.loopKnown) {
    t.closure.loopFrom = t.result.loopFrom;
    t.closure.loopTo = t.result.loopTo;
  } else {
    t.closure = geometry::analyseClosure(s, options.tolerance);
  }
  return t;
}

/// Reports the self-intersections of one contour. The pairs found go to seen.
void checkContour(const PlaneContour& c, const geometry::SelfIntersectionResult& result, const Toolpath& toolpath,
                  const SourceFile* src, const CheckOptions& options, Diagnostics& diags, MovePairs& seen) {
  const auto& moves = toolpath.moves;
  const std::string name = c.name;
  SeamNote seam;
  for (const geometry::Contact& x : result.contacts) {
    const std::size_t mi = c.moveIndex[x.first], mj = c.moveIndex[x.second];
    seen.insert({mi, mj});
    const Move& later = moves[mj];
    const std::string other = "line " + std::to_string(moves[mi].line);
    const geometry::Vec3 p = at3(x.point, c.z);
    if (c.seamAllowed && !x.adjacent &&
        !(x.kind == geometry::ContactKind::Overlap &&
          isRetrace(c.segments[x.first], c.segments[x.second], x, options.tolerance)) &&
        atSeam(toolpath, mi, mj, options.tolerance)) {
      seam.add(mi, mj, p);
      continue;
    }
    // Where the loop comes back to its start smoothly (a T onto the lead-in's end), an arc whose
    // programmed end lies off its circle (its radius mismatch) or whose end was rounded to the
    // program's resolution (1 um: 3B's unit, ISO's third decimal) passes the closing point by that
    // much: a crossing that close to the end of the last move is the loop closing, rounded.
    constexpr double kResolution = 0.001;  // mm
    const double slack =
        std::max({std::abs(moves[mi].radiusError()), std::abs(later.radiusError()), kResolution}) + options.tolerance;
    const bool closingCrossing = x.kind == geometry::ContactKind::Crossing && !x.adjacent &&
                                 (c.segments[x.second].end - x.point).norm() <= slack &&
                                 closesTheContour(c.segments, x, slack);
    // Neighbours that meet within that rounding of their shared vertex meet at the joint (an arc
    // of a huge radius written to the micrometre, at a sharp tip): not a crossing. A sideways
    // error of `slack` moves the meeting point along a wedge of opening angle a by slack / sin(a).
    if (x.adjacent && x.kind != geometry::ContactKind::Overlap) {
      const bool inOrder = x.second == x.first + 1;
      const geometry::Segment& in = c.segments[inOrder ? x.first : x.second];
      const geometry::Segment& out = c.segments[inOrder ? x.second : x.first];
      const geometry::Vec2 joint = in.end;
      const double opening = std::acos(std::clamp(-in.tangentAt(1.0).dot(out.tangentAt(0.0)), -1.0, 1.0));
      const double along = slack / std::max(std::sin(std::min(opening, geometry::kPi / 2)), 0.05);
      if ((x.point - joint).norm() <= along) continue;
    }
    if (closingCrossing) {
      diags.report(finding(Severity::Note, Code::LoopClosesInsideMove, src, later, mj, p,
                           name + " closes its loop at " + formatPoint(x.point) +
                               ", where this move meets the move on " + other + ": it passes the closing point by " +
                               formatFixed((c.segments[x.second].end - x.point).norm() * 1000, 2) +
                               " um, within the program's rounding"));
      continue;
    }
    switch (x.kind) {
      case geometry::ContactKind::Crossing:
        diags.report(
            finding(Severity::Error, Code::PathCrossesItself, src, later, mj, p,
                    name + " crosses itself at " + formatPoint(x.point) + ": this move crosses the move on " + other));
        break;
      case geometry::ContactKind::Touch:
        if (closesTheContour(c.segments, x, options.tolerance)) {
          const double tail = (1.0 - c.segments[x.second].parameterOf(x.point)) * c.segments[x.second].length();
          const bool ends = tail <= options.tolerance && x.second + 1 == c.segments.size();
          diags.report(finding(Severity::Note, Code::LoopClosesInsideMove, src, later, mj, p,
                               name + " closes its loop at " + formatPoint(x.point) +
                                   ", where this move meets the move on " + other +
                                   (ends ? ": the cut ends there" : ": what follows runs back along the way in") +
                                   " (as if the block were split at that point)"));
        } else {
          diags.report(
              finding(Severity::Error, Code::PathTouchesItself, src, later, mj, p,
                      name + " touches itself at " + formatPoint(x.point) + ": this move meets the move on " + other));
        }
        break;
      case geometry::ContactKind::Overlap:
        if (isRetrace(c.segments[x.first], c.segments[x.second], x, options.tolerance)) {
          diags.report(finding(Severity::Note, Code::PathRetraces, src, later, mj, p,
                               "the wire leaves along its way in (" + other + "): a lead-out over the lead-in" +
                                   (c.upperPlane ? std::string(" on the upper plane") : std::string{})));
        } else if (x.adjacent && x.second == x.first + 1) {
          diags.report(finding(Severity::Error, Code::PathOverlapsItself, src, later, mj, p,
                               "this move folds back over the previous one (" + other + ") near " +
                                   formatPoint(x.point) +
                                   (c.z != 0.0 || name != "the cut path" ? std::string(" on ") + name : "")));
        } else {
          diags.report(finding(
              Severity::Error, Code::PathOverlapsItself, src, later, mj, p,
              name + " runs over itself near " + formatPoint(x.point) + ": this move overlaps the move on " + other));
        }
        break;
    }
  }
  seam.report(toolpath, src, c.upperPlane ? " on the upper plane" : " on the lower plane", diags);
  if (result.truncated) {
    diags.warning(Code::TooManyDiagnostics, src, SourceSpan::wholeFile(),
                  "stopped after " + std::to_string(options.maxContacts) + " self-intersections of " + name);
  }
}

/// What the surface checks of one taper program (heights known) read, and where they report.
struct SurfaceCheck {
  const Toolpath& toolpath;
  const CutView& path;
  bool closed = false;
  const SourceFile* src = nullptr;
  const CheckOptions& options;
  Diagnostics& diags;
};

// ---- 3. the ruled surface -----------------------------------------------------------------------

/// Each patch on its own: the wire's slope against --max-taper, the guides' distance against the
/// U/V range, and an upper side that runs against the lower one (a twist or a crossing).
void checkPatches(const SurfaceCheck& c, const SurfaceMeasures& m) {
  const auto& moves = c.toolpath.moves;
  const geometry::Planes& planes = c.toolpath.heights.planes;
  const double limit = c.options.maxTaperDegrees / geometry::kDegreesPerRadian;
  for (std::size_t k = 0; k < c.path.moveIndex.size(); ++k) {
    const std::size_t i = c.path.moveIndex[k];
    const geometry::Segment& lo = moves[i].lower;
    const geometry::Segment& up = c.toolpath.upper[i];
    const geometry::PatchMeasures& pm = m.patches[i];
    if (pm.maxSlope.value > limit) {
      c.diags.report(finding(Severity::Error, Code::TaperTooSteep, c.src, moves[i], i,
                             at3(lo.pointAt(pm.maxSlope.t), planes.lower),
                             "the wire leans " + deg(pm.maxSlope.value) + " from vertical here, beyond the machine's " +
                                 formatFixed(c.options.maxTaperDegrees, 3) + "°",
                             "the limit is --max-taper (default 30°)"));
    }
    if (c.options.uvRange) {
      // Between the guides when their heights are known (what U V travel), else between the faces.
      const std::optional<geometry::Planes>& guides = c.toolpath.heights.guides;
      const double spread = guides ? guides->height() / planes.height() : 1.0;
      const geometry::Extreme& e = pm.maxOffsetX.value >= pm.maxOffsetY.value ? pm.maxOffsetX : pm.maxOffsetY;
      if (e.value * spread > *c.options.uvRange)
        c.diags.report(finding(
            Severity::Error, Code::UvOutOfRange, c.src, moves[i], i, at3(lo.pointAt(e.t), planes.lower),
            (guides ? "the upper guide is " : "the upper face is ") + formatFixed(e.value * spread, 3) +
                " mm from the lower " + (guides ? "one" : "face") + " along " + (&e == &pm.maxOffsetX ? "X" : "Y") +
                ", beyond the U/V range " + formatFixed(*c.options.uvRange, 3) + " mm" +
                (guides ? " (the guides at z " + formatFixed(guides->lower, 3) + " and " +
                              formatFixed(guides->upper, 3) + ", " + c.toolpath.heights.guidesSource + ")"
                        : std::string(": give the guides' heights (--guides) to check it where "
                                      "the axes are"))));
    }
    const geometry::TwistMeasure tw = geometry::measureTwist(lo, up);
    if (tw.defined && !lo.isArc() && !up.isArc() && tw.maxAngle >= geometry::kPi - 1e-12) {
      // Opposite lines: every generator passes through one point, at s = |L'| / (|L'| + |U'|).
      const double s = lo.length() / (lo.length() + up.length());
      c.diags.report(finding(
          Severity::Error, Code::WireCrossing, c.src, moves[i], i, geometry::surfacePoint(lo, up, planes, 0.0, s),
          "the upper side runs exactly against the lower one: every position of the wire in this move "
          "passes through one point, at z " +
              formatFixed(planes.lower + s * planes.height(), 3)));
    } else if (tw.defined && tw.maxAngle > geometry::kPi / 2 + 1e-9) {
      c.diags.report(finding(Severity::Error, Code::PatchTwisted, c.src, moves[i], i,
                             geometry::surfacePoint(lo, up, planes, tw.t, 0.5),
                             "the upper contour runs against the lower one here: their directions differ by " +
                                 deg(tw.maxAngle) + ", so the wire turns over and the surface twists through itself"));
    }
  }
}

/// Folds at the joints between neighbouring patches, exact; returns the pairs of moves reported.
MovePairs checkJoints(const SurfaceCheck& c) {
  const auto& moves = c.toolpath.moves;
  const geometry::Planes& planes = c.toolpath.heights.planes;
  MovePairs reported;
  const std::size_t count = c.path.moveIndex.size();
  for (std::size_t k = 0; k + 1 < count || (c.closed && k + 1 == count && count > 2); ++k) {
    const std::size_t i = c.path.moveIndex[k], j = c.path.moveIndex[(k + 1) % count];
    if ((moves[i].lower.end - moves[j].lower.start).norm() > c.options.tolerance) continue;
    if (k + 1 == count) {
      // The wrap from the lead-out back to the lead-in at a start hole turns round by design.
      const double sp = programLevel(c.toolpath);
      auto velocity = [](const geometry::Segment& g, double t) { return geometry::Vec2(g.tangentAt(t) * g.length()); };
      const geometry::Vec2 out = (1.0 - sp) * velocity(moves[i].lower, 1.0) + sp * velocity(c.toolpath.upper[i], 1.0);
      const geometry::Vec2 in = (1.0 - sp) * velocity(moves[j].lower, 0.0) + sp * velocity(c.toolpath.upper[j], 0.0);
      if (std::abs(geometry::cross(out, in)) <= 1e-9 * out.norm() * in.norm() && out.dot(in) < 0) continue;
    }
    const std::optional<double> s =
        geometry::foldAtJoint(moves[i].lower, c.toolpath.upper[i], moves[j].lower, c.toolpath.upper[j]);
    if (!s) continue;
    reported.insert({std::min(i, j), std::max(i, j)});
    const geometry::Vec3 p = geometry::surfacePoint(moves[j].lower, c.toolpath.upper[j], planes, 0.0, *s);
    c.diags.report(finding(Severity::Error, Code::SurfaceFold, c.src, moves[j], j, p,
                           "the surface folds back at the start of this move, at z " + formatFixed(p.z(), 3) +
                               ": the wire turns round by 180° there (after line " + std::to_string(moves[i].line) +
                               ")"));
  }
  return reported;
}

/// One horizontal section of the surface, with its contacts.
struct Section {
  PlaneContour section;  // views of segments and moveIndex
  std::vector<geometry::Segment> segments;
  std::vector<std::uint32_t> moveIndex;
  geometry::SelfIntersectionResult r;
  std::size_t wanted = 0, share = geometry::kMaxSectionPieces;
};

/// The section at level / levels of the height, made within the section tolerance (coarser past the
/// section budget: share is then each twisted patch's pieces) and swept for contacts.
void makeSection(const SurfaceCheck& c, int level, int levels, Section& out) {
  const auto& moves = c.toolpath.moves;
  const geometry::Planes& planes = c.toolpath.heights.planes;
  const double s = static_cast<double>(level) / levels;
  PlaneContour& section = out.section;
  section.z = planes.lower + s * planes.height();
  // Count before making: huge twisted arcs ask for thousands of pieces a patch. Past the budget,
  // each polyline patch gets its share of it (at least 2 pieces), and a note says so once.
  std::size_t polylines = 0, exact = 0;  // patches made as polylines; single segments
  for (const std::size_t i : c.path.moveIndex) {
    const std::size_t n = geometry::sectionPieces(moves[i].lower, c.toolpath.upper[i], s, c.options.sectionTolerance);
    out.wanted += n;
    (n == 1 ? exact : polylines) += 1;
  }
  if (out.wanted > c.options.sectionBudget && polylines > 0) {
    const std::size_t room = c.options.sectionBudget > exact ? c.options.sectionBudget - exact : 0;
    out.share = std::max<std::size_t>(2, room / polylines);
  }
  for (std::size_t k = 0; k < c.path.moveIndex.size(); ++k) {
    const std::size_t i = c.path.moveIndex[k];
    const std::size_t before = out.segments.size();
    geometry::appendSection(moves[i].lower, c.toolpath.upper[i], s, c.options.sectionTolerance, out.segments,
                            out.share);
    out.moveIndex.insert(out.moveIndex.end(), out.segments.size() - before, static_cast<std::uint32_t>(k));
  }
  section.segments = out.segments;
  section.moveIndex = out.moveIndex;
  geometry::SelfIntersectionOptions so;
  so.tolerance = c.options.tolerance;
  so.closed = c.closed;
  so.maxContacts = c.options.maxContacts;
  out.r = geometry::findSelfIntersections(section.segments, so);
}

/// A section's contacts as findings, in order, but for the pairs of moves seen or reported already
/// (reported grows) and retraces; the first coarsened section says so once (coarsened).
void reportSection(const SurfaceCheck& c, const Section& level, const MovePairs& seen, MovePairs& reported,
                   bool& coarsened, SeamNote& seam) {
  const auto& moves = c.toolpath.moves;
  const geometry::Planes& planes = c.toolpath.heights.planes;
  const PlaneContour& section = level.section;
  const geometry::SelfIntersectionResult& r = level.r;
  if (level.share != geometry::kMaxSectionPieces && !coarsened) {
    coarsened = true;
    const std::size_t head = c.path.moveIndex.front();
    c.diags.report(finding(
        Severity::Note, Code::SectionsCoarsened, c.src, moves[head], head, at3(moves[head].lower.start, planes.lower),
        "the sections of the surface would need " + std::to_string(level.wanted) + " pieces, more than the budget of " +
            std::to_string(c.options.sectionBudget) + ": the twisted patches are tested as polylines of at most " +
            std::to_string(level.share) +
            " pieces, coarser than the section tolerance, so a wire crossing closer than their "
            "chord error may be missed"));
  }
  const std::size_t n = c.path.moveIndex.size();
  for (const geometry::Contact& x : r.contacts) {
    const std::size_t ka = section.moveIndex[x.first], kb = section.moveIndex[x.second];
    const std::size_t mi = c.path.moveIndex[ka], mj = c.path.moveIndex[kb];
    if (seen.count({mi, mj}) || reported.count({mi, mj})) continue;
    if (x.kind == geometry::ContactKind::Overlap &&
        isRetrace(section.segments[x.first], section.segments[x.second], x, c.options.tolerance))
      continue;
    reported.insert({mi, mj});
    const bool neighbours = kb == ka + 1 || (c.closed && ka == 0 && kb + 1 == n);
    if (ka != kb && !neighbours && atSeam(c.toolpath, mi, mj, c.options.tolerance)) {
      seam.add(mi, mj, at3(x.point, section.z));
      continue;
    }
    const geometry::Vec3 p = at3(x.point, section.z);
    const std::string where = " at z " + formatFixed(section.z, 3) + ", " + formatPoint(x.point);
    if (ka == kb) {
      c.diags.report(finding(Severity::Error, Code::WireCrossing, c.src, moves[mj], mj, p,
                             "the wire crosses its own path inside this move" + where +
                                 ": two positions of the wire meet between the planes"));
    } else if (neighbours && x.kind == geometry::ContactKind::Overlap) {
      c.diags.report(finding(
          Severity::Error, Code::SurfaceFold, c.src, moves[mj], mj, p,
          "the surface folds back over the previous move (line " + std::to_string(moves[mi].line) + ")" + where));
    } else if (neighbours) {
      c.diags.report(finding(Severity::Error, Code::WireCrossing, c.src, moves[mj], mj, p,
                             "the wire of this move crosses the wire of the previous move (line " +
                                 std::to_string(moves[mi].line) + ")" + where));
    } else {
      c.diags.report(finding(Severity::Error, Code::SurfaceSelfIntersection, c.src, moves[mj], mj, p,
                             "the surface the wire sweeps meets itself" + where +
                                 ": this move meets the move on line " + std::to_string(moves[mi].line)));
    }
  }
}

/// The surface checks of a taper program whose heights are known: each patch, the joints, then
/// horizontal sections between the planes, each tested exactly: made and swept a few at a time on
/// every core (a batch of one per worker in memory at once), reported in order of height.
void checkSurface(const Toolpath& toolpath, const CutView& path, bool closed, const SourceFile* src,
                  const CheckOptions& options, Diagnostics& diags, const SurfaceMeasures& m, MovePairs& seen) {
  const SurfaceCheck c{toolpath, path, closed, src, options, diags};
  checkPatches(c, m);
  MovePairs reported = checkJoints(c);
  const int levels = std::max(2, options.surfaceLevels);
  bool coarsened = false;
  SeamNote seam;
  const int batchSize = static_cast<int>(std::max(1u, geometry::workerCount()));
  for (int first = 1; first < levels; first += batchSize) {
    std::vector<Section> batch(static_cast<std::size_t>(std::min(batchSize, levels - first)));
    geometry::parallelFor(batch.size(), 1, [&](std::size_t b, std::size_t e) {
      for (std::size_t k = b; k < e; ++k) makeSection(c, first + static_cast<int>(k), levels, batch[k]);
    });
    for (const Section& level : batch) reportSection(c, level, seen, reported, coarsened, seam);
  }
  seam.report(toolpath, src, " between the planes", diags);
}

/// A run of cut moves checked as one path: the program's cuts, or one pass of a contour.
struct CutRun {
  const CutView& path;
  std::string lowerName;  ///< how messages name its lower contour (its only one on a 2-axis program)
  std::string upperName;
  bool warnOpen = true;  ///< warn when the lower contour closes no loop (K0605)
};

// ---- 4. the cut runs and the toolpath -----------------------------------------------------------

/// The lower contour's self-intersections and closure; on a taper program the upper contour's,
/// their closures against each other and, with the heights known, the surface's (measures are then
/// measureSurface(toolpath)).
void checkCutRun(const CutRun& run, const Toolpath& toolpath, const SourceFile* src, const CheckOptions& options,
                 Diagnostics& diags, const SurfaceMeasures* measures) {
  // The lower contour's self-intersections and closure.
  const CutView& path = run.path;
  const auto& moves = toolpath.moves;
  const bool taper = toolpath.isTaper();
  const double zLower = taper ? toolpath.heights.planes.lower : 0.0;
  PlaneContour lower{path.segments, path.moveIndex, run.lowerName, zLower, false, taper};
  ContourTest lowerTest = testContour(lower, options);
  const geometry::ClosureReport& closure = lowerTest.closure;
  if (!closure.loopFrom && run.warnOpen) {
    const Move& last = moves[path.moveIndex.back()];
    diags.report(finding(Severity::Warning, Code::PathOpen, src, last, path.moveIndex.back(),
                         at3(last.lower.end, zLower),
                         "the cut path never closes a loop: the part stays attached (the end is " +
                             formatFixed(closure.gap, 3) + " mm from the start)"));
  }

  MovePairs seen;
  checkContour(lower, lowerTest.result, toolpath, src, options, diags, seen);
  lowerTest.result = {};
  if (!taper) return;

  PlaneContour upper;
  upper.name = run.upperName;
  upper.upperPlane = true;
  upper.seamAllowed = true;
  upper.z = toolpath.heights.known ? toolpath.heights.planes.upper : 0.0;
  upper.moveIndex = path.moveIndex;
  // In place when the cuts are contiguous, like the lower contour.
  std::vector<geometry::Segment> upperSegments;
  if (path.copy.empty()) {
    upper.segments =
        std::span<const geometry::Segment>(toolpath.upper).subspan(path.moveIndex.front(), path.moveIndex.size());
  } else {
    upperSegments.reserve(path.moveIndex.size());
    for (std::size_t i : path.moveIndex) upperSegments.push_back(toolpath.upper[i]);
    upper.segments = upperSegments;
  }
  ContourTest upperTest = testContour(upper, options);
  const geometry::ClosureReport& upperClosure = upperTest.closure;
  if (closure.loopFrom.has_value() != upperClosure.loopFrom.has_value()) {
    const std::size_t i = path.moveIndex.back();
    const bool lowerClosed = closure.loopFrom.has_value();
    diags.report(
        finding(Severity::Error, Code::ClosureMismatch, src, moves[i], i,
                at3(lowerClosed ? upper.segments.back().end : moves[i].lower.end, lowerClosed ? upper.z : zLower),
                std::string("the ") + (lowerClosed ? "lower" : "upper") + " contour closes a loop but the " +
                    (lowerClosed ? "upper" : "lower") + " one does not (it ends " +
                    formatFixed(lowerClosed ? upperClosure.gap : closure.gap, 3) +
                    " mm from its start): the wire cannot release the part on both planes"));
  }
  checkContour(upper, upperTest.result, toolpath, src, options, diags, seen);
  upperTest.result = {};
  if (!toolpath.heights.known) return;
  checkSurface(toolpath, path, closure.endsAtStart && upperClosure.endsAtStart, src, options, diags, *measures, seen);
}

}  // namespace

void checkToolpath(const Toolpath& toolpath, const SourceFile* src, const CheckOptions& options, Diagnostics& diags,
                   const SurfaceMeasures* measures, const Structure* structure) {
  const CutView path = cutView(toolpath);
  if (path.segments.empty()) {
    // With errors, those say why; alone, this says the program is empty of cuts. It points at
    // the first move (a rapid), or where the program starts when nothing moves.
    if (!diags.hasErrors())
      diags.error(Code::NothingCut, src, toolpath.moves.empty() ? SourceSpan{0, 0} : toolpath.moves.front().span,
                  "the program cuts nothing (no G01, G02 or G03 move)",
                  "a wire program needs at least one cutting move");
    return;
  }
  const auto& moves = toolpath.moves;
  const bool taper = toolpath.isTaper();
  const double zLower = taper ? toolpath.heights.planes.lower : 0.0;

  // Rapids between the first and the last cut: a warning, unless the wire may be cut and threaded
  // again between the cuts on either side (M00, M01 or the profile's rethread codes). A view
  // without a table saw only cuts there (cutView): then there is none, and no pass to make.
  std::size_t previousCut = path.moveIndex.front();
  const std::size_t rapidsTo = path.table.empty() ? previousCut : path.moveIndex.back();
  for (std::size_t i = path.moveIndex.front(); i < rapidsTo; ++i) {
    if (moves[i].isCut()) {
      previousCut = i;
      continue;
    }
    std::size_t nextCut = i + 1;
    while (nextCut < moves.size() && !moves[nextCut].isCut()) ++nextCut;
    const auto stop = std::upper_bound(toolpath.stops.begin(), toolpath.stops.end(), previousCut);
    if (stop != toolpath.stops.end() && *stop <= nextCut) {
      if (i == previousCut + 1)
        diags.report(finding(Severity::Note, Code::RapidInsideCut, src, moves[i], i, at3(moves[i].lower.end, zLower),
                             "the wire goes to a new start hole: a stop (M00, M01 or the machine's rethread code) "
                             "lies between the cuts, where the wire is cut and threaded again"));
      continue;
    }
    diags.report(finding(Severity::Warning, Code::RapidInsideCut, src, moves[i], i, at3(moves[i].lower.end, zLower),
                         "rapid move between cuts: a point-driven controller would cut along it",
                         "wire programs usually thread the wire again (M-code) at a new start hole"));
  }

  // The surface's measures and the passes, once for every run of cuts checked.
  SurfaceMeasures ownMeasures;
  if (taper && toolpath.heights.known && !(measures && measures->patches.size() == moves.size())) {
    ownMeasures = measureSurface(toolpath);
    measures = &ownMeasures;
  }
  const Structure ownStructure = structure ? Structure{} : findStructure(toolpath, options.tolerance);
  const Structure& passes = structure ? *structure : ownStructure;
  if (!passes.multiPass()) {
    checkCutRun({path, taper ? "the lower contour" : "the cut path", "the upper contour", true}, toolpath, src, options,
                diags, measures);
    return;
  }
  // Several passes over one contour: each pass is tested alone (a skim retraces its rough cut, it
  // does not meet itself), and a contour must close in some pass.
  for (std::size_t ci = 0; ci < passes.contours.size(); ++ci) {
    const Contour& contour = passes.contours[ci];
    const std::string of = passes.contours.size() > 1 ? " of contour " + std::to_string(ci + 1) : "";
    for (std::size_t pi = 0; pi < contour.passes.size(); ++pi) {
      const Pass& pass = contour.passes[pi];
      CutView view;
      view.segments = geometry::SegmentView::members(
          std::span<const Move>(moves).subspan(pass.first, pass.end - pass.first), &Move::lower);
      view.moveIndex = MoveIndex(static_cast<std::uint32_t>(pass.first), pass.end - pass.first);
      const std::string name = "pass " + std::to_string(pi + 1) + of;
      checkCutRun({view, taper ? name + " (lower contour)" : name, name + " (upper contour)", false}, toolpath, src,
                  options, diags, measures);
    }
    if (!cutsFree(contour)) {
      const std::size_t last = contour.end - 1;
      diags.report(finding(Severity::Warning, Code::PathOpen, src, moves[last], last,
                           at3(moves[last].lower.end, zLower),
                           "no pass of this contour closes it and none cuts off what the others leave: the part "
                           "stays attached (the last pass ends " +
                               formatFixed(contour.passes.back().gap, 3) + " mm from where it started)"));
    }
  }
  checkPasses(passes, toolpath, src, diags);
}

}  // namespace kerf::converter
