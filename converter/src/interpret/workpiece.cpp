// The part between the work's faces (workpiece.h).
#include "kerf/converter/interpret/workpiece.h"

#include "kerf/converter/nc/number_format.h"
#include "kerf/geometry/ruled_surface.h"

#include <algorithm>
#include <cmath>

namespace kerf::converter {
namespace {

using geometry::Segment;

/// How many pieces move i becomes between the faces at s0 and s1 (fractions of the planes'
/// height): 1 where both sections are exact, else the finer of the two sections' polylines.
std::size_t piecesOf(const Segment& lo, const Segment& up, double s0, double s1, double tolerance, bool& exact) {
  std::vector<Segment> scratch;
  const bool e0 = geometry::appendSection(lo, up, s0, tolerance, scratch, 1) && scratch.size() == 1;
  scratch.clear();
  const bool e1 = geometry::appendSection(lo, up, s1, tolerance, scratch, 1) && scratch.size() == 1;
  exact = e0 && e1;
  if (exact) return 1;
  return std::max<std::size_t>(
      {1, geometry::sectionPieces(lo, up, s0, tolerance), geometry::sectionPieces(lo, up, s1, tolerance)});
}

}  // namespace

bool cutBetweenFaces(Toolpath& toolpath, double z0, double z1, double tolerance, std::size_t maxMoves,
                     const SourceFile* source, Diagnostics& diags) {
  const PlaneHeights& h = toolpath.heights;
  auto refuse = [&](const std::string& why) {
    diags.error(Code::HeightsMissing, source, SourceSpan::wholeFile(), "--workpiece: " + why,
                "--workpiece Z0,Z1 takes the work's faces on a 4-axis program whose planes are the machine's "
                "(a foam cutter's carriages)");
    return false;
  };
  if (!toolpath.isTaper()) return refuse("a 2-axis program's wire stands upright: it has no faces to cut between");
  if (!h.known) return refuse("the program's plane heights are not known (give --thickness or --upper-z)");
  if (!(z0 < z1) || std::abs(z0) > 1e5 || std::abs(z1) > 1e5)
    return refuse("the faces must be Z0 < Z1 within 100 m, not " + formatFixed(z0, 3) + ", " + formatFixed(z1, 3));
  const double s0 = (z0 - h.planes.lower) / h.planes.height(), s1 = (z1 - h.planes.lower) / h.planes.height();
  // Counted before anything is made: a budget is refused before it is spent.
  std::vector<std::size_t> pieces(toolpath.moves.size());
  std::vector<bool> exact(toolpath.moves.size());
  std::size_t total = 0;
  for (std::size_t i = 0; i < toolpath.moves.size(); ++i) {
    bool e = false;
    pieces[i] = piecesOf(toolpath.moves[i].lower, toolpath.upper[i], s0, s1, tolerance, e);
    exact[i] = e;
    total += pieces[i];
    if (total > maxMoves)
      return refuse("the faces' sections need more than " + std::to_string(maxMoves) + " moves within " +
                    formatFixed(tolerance, 4) + " mm");
  }
  std::vector<MoveRow> rows;
  rows.reserve(total);
  std::vector<std::uint32_t> newIndex(toolpath.moves.size() + 1);
  std::vector<Segment> section;
  for (std::size_t i = 0; i < toolpath.moves.size(); ++i) {
    newIndex[i] = static_cast<std::uint32_t>(rows.size());
    const Segment& lo = toolpath.moves[i].lower;
    const Segment& up = toolpath.upper[i];
    auto add = [&](const Segment& a, const Segment& b, bool first) {
      MoveRow row = toolpath.rowOf(i);
      Move& m = row.move;
      m.lower = a;
      if (m.isCut()) m.kind = a.isArc() || b.isArc() ? MoveKind::Arc : MoveKind::Line;
      if (!first || (!a.isArc() && m.centreForm != CentreForm::None)) m.centreForm = CentreForm::None;
      row.upper = b;
      if (!first) row.centreWords = geometry::Vec2(0, 0);
      rows.push_back(row);
    };
    if (exact[i]) {
      section.clear();
      geometry::appendSection(lo, up, s0, tolerance, section, 1);
      const Segment a = section.front();
      section.clear();
      geometry::appendSection(lo, up, s1, tolerance, section, 1);
      add(a, section.front(), true);
      continue;
    }
    // Both faces at the same t, so each piece stays one position of the wire.
    const std::size_t n = pieces[i];
    auto at = [&](double t, double s) {
      const geometry::Vec2 l = t >= 1.0 ? lo.end : lo.pointAt(t), u = t >= 1.0 ? up.end : up.pointAt(t);
      return geometry::Vec2(l + s * (u - l));
    };
    for (std::size_t k = 0; k < n; ++k) {
      const double t0 = static_cast<double>(k) / static_cast<double>(n);
      const double t1 = static_cast<double>(k + 1) / static_cast<double>(n);
      add(Segment::line(at(t0, s0), at(t1, s0)), Segment::line(at(t0, s1), at(t1, s1)), k == 0);
    }
  }
  newIndex[toolpath.moves.size()] = static_cast<std::uint32_t>(rows.size());
  const geometry::Planes machine = h.planes;
  const geometry::Vec2 start =
      toolpath.moves.empty() ? toolpath.start
                             : geometry::Vec2(toolpath.moves.front().lower.start +
                                              s0 * (toolpath.upper.front().start - toolpath.moves.front().lower.start));
  toolpath.replaceMoves(std::move(rows), newIndex);
  toolpath.start = start;
  PlaneHeights& heights = toolpath.heights;
  if (!heights.guides) {
    heights.guides = machine;
    heights.guidesSource = "the program's planes (its carriages: --workpiece)";
  }
  heights.planes = {z0, z1};
  heights.programZ = std::clamp(heights.programZ, z0, z1);
  heights.source = "--workpiece (the work's faces; the program's planes at z " + formatFixed(machine.lower, 3) +
                   " and " + formatFixed(machine.upper, 3) + " are the machine's)";
  return true;
}

}  // namespace kerf::converter
