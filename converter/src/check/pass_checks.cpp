// The checks between the passes over one contour (pass_checks.h, docs/passes.md). Sides come from
// G41/G42 and the direction of the programmed contour (keptSide); offsets as the interpreter
// resolved them (the program's table, --offsets, the profile, --offset); stops from
// Toolpath::stops. Findings sit on the lower plane (z of the lower guide for a taper program).
#include "kerf/converter/check/pass_checks.h"
#include "finding.h"

#include "kerf/converter/nc/number_format.h"

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

namespace kerf::converter {
namespace {

/// "pass 2" or "pass 2 of contour 3" when the program has several contours.
std::string passName(std::size_t pass, std::size_t contour, std::size_t contours) {
  return "pass " + std::to_string(pass + 1) + (contours > 1 ? " of contour " + std::to_string(contour + 1) : "");
}

class PassChecker {
 public:
  PassChecker(const Toolpath& tp, const SourceFile* src, Diagnostics& diags, std::size_t contours)
      : tp_(tp),
        src_(src),
        diags_(diags),
        contours_(contours),
        z_(tp.isTaper() && tp.heights.known ? tp.heights.planes.lower : 0.0) {}

  void check(const Contour& c, std::size_t ci) {
    ci_ = ci;
    const std::vector<Pass>& ps = c.passes;
    std::size_t reference = ps.size();  // the first pass whose side is known
    for (std::size_t p = 0; p < ps.size(); ++p)
      if (keptSide(ps[p]) != 0) {
        reference = p;
        break;
      }
    if (reference < ps.size()) checkSides(ps, reference);
    checkOffsets(ps);
    checkWhatFalls(ps, reference < ps.size() ? keptSide(ps[reference]) : 0);
  }

 private:
  /// Every pass on the reference pass's side of the programmed contour.
  void checkSides(const std::vector<Pass>& ps, std::size_t reference) {
    const int side = keptSide(ps[reference]);
    for (std::size_t p = reference + 1; p < ps.size(); ++p) {
      if (keptSide(ps[p]) == 0 || keptSide(ps[p]) == side) continue;
      report(Severity::Error, Code::PassWrongSide, ps[p].first, tp_.moves[ps[p].first].lower.start,
             name(p) + " runs " + where(keptSide(ps[p])) + " its contour (" + offsetText(ps[p]) + ", " +
                 directionName(ps[p].direction) + ") where " + name(reference) + " runs " + where(side) + " it (" +
                 offsetText(ps[reference]) + ", " + directionName(ps[reference].direction) +
                 "): it cuts into what that pass kept",
             "G41 puts the wire left of the direction of travel, G42 right: a pass that reverses the direction "
             "takes the other code");
    }
  }

  /// Each skim's offset no larger than the offset of the pass before it (both known).
  void checkOffsets(const std::vector<Pass>& ps) {
    std::size_t before = ps.size();
    for (std::size_t p = 0; p < ps.size(); ++p) {
      if (ps[p].cutOff || !ps[p].offset || ps[p].side == WireOffset::Off) continue;
      if (before < ps.size() && *ps[p].offset > *ps[before].offset + 1e-9)
        report(Severity::Warning, Code::OffsetGrows, ps[p].first, tp_.moves[ps[p].first].lower.start,
               name(p) + "'s offset (" + offsetText(ps[p]) + ") is larger than " + name(before) + "'s (" +
                   offsetText(ps[before]) + "): it runs outside the path already cut and removes nothing",
               "skims take smaller offsets than the pass before them (the register's value, or the table)");
      before = p;
    }
  }

  /// A punch cut free before its skims, a cut-off without a stop, where a die's slug falls.
  void checkWhatFalls(const std::vector<Pass>& ps, int side) {
    for (std::size_t p = 0; p < ps.size(); ++p) {
      if (!ps[p].closes && !ps[p].cutOff) continue;
      const std::size_t last = ps[p].alongEnd - 1;
      const bool skimsAfter = std::any_of(ps.begin() + static_cast<std::ptrdiff_t>(p) + 1, ps.end(),
                                          [](const Pass& q) { return !q.cutOff; });
      if (side < 0 && skimsAfter)
        report(Severity::Warning, Code::PartFallsBeforeSkims, last, tp_.moves[last].lower.end,
               name(p) + " cuts the punch free: the passes after it skim a part that has fallen",
               "leave a tab in the rough cut and the skims, and cut it off last after a stop (M00 or M01)");
      if (side > 0)
        report(Severity::Note, Code::SlugFalls, last, tp_.moves[last].lower.end,
               "the slug falls free here, at the end of " + name(p) +
                   (ps[p].cutOff ? " (the cut-off through the tab)" : " (it closes the contour)"));
      break;  // the first pass that closes the contour, or cuts off its tab, is where the piece falls
    }
    for (std::size_t p = 1; p < ps.size(); ++p) {
      if (!ps[p].cutOff) continue;
      const std::size_t from = ps[p - 1].end, to = ps[p].first;
      const auto stop = std::lower_bound(tp_.stops.begin(), tp_.stops.end(), from);
      if (stop != tp_.stops.end() && *stop <= to) continue;
      report(Severity::Warning, Code::CutOffWithoutStop, ps[p].first, tp_.moves[ps[p].first].lower.start,
             name(p) + " cuts off the tab with no stop before it: the " + (side < 0 ? "part" : "slug") +
                 " is not secured when it falls",
             "put M00 or M01 before the cut-off, so the operator can secure it");
    }
  }

  std::string name(std::size_t pass) const { return passName(pass, ci_, contours_); }
  static const char* where(int side) { return side > 0 ? "inside" : "outside"; }

  void report(Severity sev, Code code, std::size_t move, const geometry::Vec2& at, std::string message,
              std::string help = {}) {
    diags_.report(finding(sev, code, src_, tp_.moves[move], move, at3(at, z_), std::move(message), std::move(help)));
  }

  const Toolpath& tp_;
  const SourceFile* src_;
  Diagnostics& diags_;
  std::size_t contours_;
  double z_;
  std::size_t ci_ = 0;
};

}  // namespace

void checkPasses(const Structure& structure, const Toolpath& toolpath, const SourceFile* src, Diagnostics& diags) {
  PassChecker checker(toolpath, src, diags, structure.contours.size());
  for (std::size_t ci = 0; ci < structure.contours.size(); ++ci)
    if (structure.contours[ci].passes.size() > 1) checker.check(structure.contours[ci], ci);
}

}  // namespace kerf::converter
