#include "kerf/converter/checks.h"

#include "kerf/converter/points.h"
#include "kerf/converter/summary.h"
#include "kerf/geometry/contour.h"
#include "kerf/geometry/intersection.h"

#include <string>

namespace kerf::converter {
namespace {

std::string at(const geometry::Vec2& p) { return "(" + formatFixed(p.x(), 3) + ", " + formatFixed(p.y(), 3) + ")"; }

Diagnostic finding(Severity sev, Code code, const SourceFile* src, const Move& move, std::size_t moveIndex,
                   const geometry::Vec2& p, std::string message, std::string help = {}) {
  Diagnostic d;
  d.severity = sev;
  d.code = code;
  d.source = src;
  d.span = move.span;
  d.message = std::move(message);
  d.help = std::move(help);
  d.move = moveIndex;
  d.point = geometry::Vec3(p.x(), p.y(), 0.0);
  return d;
}

/// A lead-out over the lead-in: the later move runs back along the earlier one, in the opposite
/// direction, and ends where the earlier one started (the start hole). The kerf there is open
/// already, so the wire cuts nothing new.
bool isRetrace(const geometry::Segment& earlier, const geometry::Segment& later, const geometry::Contact& c,
               double tol) {
  return c.opposite && (later.end - earlier.start).norm() <= tol;
}

}  // namespace

void checkToolpath(const Toolpath& toolpath, const SourceFile* src, const CheckOptions& options, Diagnostics& diags) {
  const CutPath path = cutPath(toolpath);
  if (path.segments.empty()) {
    // With errors, those say why; alone, this says the program is empty of cuts.
    if (!diags.hasErrors())
      diags.warning(Code::NothingCut, src, SourceSpan::wholeFile(),
                    "the program cuts nothing (no G01, G02 or G03 move)");
    return;
  }
  const auto& moves = toolpath.moves;

  // Rapids between the first and the last cut.
  for (std::size_t i = path.moveIndex.front(); i < path.moveIndex.back(); ++i) {
    if (moves[i].isCut()) continue;
    diags.report(finding(Severity::Warning, Code::RapidInsideCut, src, moves[i], i, moves[i].lower.end,
                         "rapid move between cuts: a point-driven controller would cut along it",
                         "wire programs usually thread the wire again (M-code) at a new start hole"));
  }

  // Closure.
  const geometry::ClosureReport closure = geometry::analyseClosure(path.segments, options.tolerance);
  if (!closure.loopFrom) {
    const Move& last = moves[path.moveIndex.back()];
    diags.report(finding(Severity::Warning, Code::PathOpen, src, last, path.moveIndex.back(), last.lower.end,
                         "the cut path never closes a loop: the part stays attached (the end is " +
                             formatFixed(closure.gap, 3) + " mm from the start)"));
  }

  // Self-intersection, exact on lines and arcs.
  geometry::SelfIntersectionOptions so;
  so.tolerance = options.tolerance;
  so.closed = closure.endsAtStart;
  so.maxContacts = options.maxContacts;
  const geometry::SelfIntersectionResult result = geometry::findSelfIntersections(path.segments, so);
  for (const geometry::Contact& c : result.contacts) {
    const std::size_t mi = path.moveIndex[c.first], mj = path.moveIndex[c.second];
    const Move& later = moves[mj];
    const std::string other = "line " + std::to_string(moves[mi].line);
    switch (c.kind) {
      case geometry::ContactKind::Crossing:
        diags.report(
            finding(Severity::Error, Code::PathCrossesItself, src, later, mj, c.point,
                    "the cut path crosses itself at " + at(c.point) + ": this move crosses the move on " + other));
        break;
      case geometry::ContactKind::Touch:
        diags.report(
            finding(Severity::Error, Code::PathTouchesItself, src, later, mj, c.point,
                    "the cut path touches itself at " + at(c.point) + ": this move meets the move on " + other));
        break;
      case geometry::ContactKind::Overlap:
        if (isRetrace(path.segments[c.first], path.segments[c.second], c, options.tolerance)) {
          diags.report(finding(Severity::Note, Code::PathRetraces, src, later, mj, c.point,
                               "the wire leaves along its way in (" + other + "): a lead-out over the lead-in"));
        } else if (c.adjacent && c.second == c.first + 1) {
          diags.report(finding(Severity::Error, Code::PathOverlapsItself, src, later, mj, c.point,
                               "this move folds back over the previous one (" + other + ") near " + at(c.point)));
        } else {
          diags.report(finding(
              Severity::Error, Code::PathOverlapsItself, src, later, mj, c.point,
              "the cut path runs over itself near " + at(c.point) + ": this move overlaps the move on " + other));
        }
        break;
    }
  }
  if (result.truncated) {
    diags.warning(Code::TooManyDiagnostics, src, SourceSpan::wholeFile(),
                  "stopped after " + std::to_string(options.maxContacts) + " self-intersections");
  }
}

}  // namespace kerf::converter
