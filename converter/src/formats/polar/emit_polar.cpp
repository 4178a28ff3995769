// Polar X/C output for mill-turn lathes without a Y axis (seed 002, docs/polar.md).
#include "kerf/converter/formats/emit.h"

#include "kerf/converter/nc/number_format.h"
#include "kerf/geometry/polar.h"

#include <cmath>

namespace kerf::converter {

namespace {
/// No polar file is built longer than this (points): a tolerance far too fine is refused.
constexpr std::size_t kMaxPolarPoints = 20'000'000;
}  // namespace

std::optional<EmitOutput> writePolar(const Toolpath& toolpath, const SourceFile* source, const EmitRequest& request,
                                     Diagnostics& diags) {
  using geometry::PolarPoint;
  if (toolpath.moves.empty()) {
    diags.error(Code::NothingCut, source, SourceSpan::wholeFile(), "nothing to write: the program has no move");
    return std::nullopt;
  }
  const int decimals = request.decimals.value_or(3);
  const double xScale = request.polarX == PolarX::Diameter ? 2.0 : 1.0;
  const double tol = request.tolerance;
  std::string text;
  text += "(written by Kerf: polar X/C from " + (source ? source->name() : std::string("a program")) + "; X " +
          (request.polarX == PolarX::Diameter ? "diameter" : "radius") +
          ", C degrees unwrapped; the spiral between points within " + formatFixed(tol, 4) + " mm)\n";
  // A diameter is twice the radius rounded to the decimals, as seed 002's post writes it (every X
  // of its O31 listing is even in the last digit: 64.404 = 2 x 32.202, where 2 x 32.20248 rounds
  // to 64.405), so the X written is exactly twice a radius on the grid.
  const double f = std::pow(10.0, decimals);
  auto point = [&](const PolarPoint& q) {
    return "X" + formatFixed(std::nearbyint(q.radius * f) / f * xScale, decimals) + " C" + formatFixed(q.c, decimals);
  };
  PolarPoint at = geometry::toPolar(toolpath.moves.front().lower.start, 0.0);
  text += "G00 " + point(at) + "\n";
  std::size_t points = 1;
  double worst = 0.0, feed = 0.0;
  bool rapidMode = true;
  for (std::size_t i = 0; i < toolpath.moves.size(); ++i) {
    const Move& m = toolpath.moves[i];
    if (m.kind == MoveKind::Rapid) {
      at = geometry::toPolar(m.lower.end, at.c);
      text += "G00 " + point(at) + "\n";
      rapidMode = true;
      ++points;
      continue;
    }
    const geometry::PolarSubdivision sub =
        geometry::subdivideForPolar(m.lower, at.c, tol, kMaxPolarPoints - points, std::max(tol, 1e-6));
    if (sub.throughCentre) {
      diags.error(Code::PolarThroughCentre, source, m.span,
                  "this move passes through the centre of the face, where C is undefined: the table would have to "
                  "turn 180 degrees at once",
                  "move the part's centre off the path, or split the path so it goes around the centre");
      return std::nullopt;
    }
    if (sub.overBudget) {
      diags.error(Code::CapacityTooSmall, source, m.span,
                  "the tolerance " + formatFixed(tol, 6) + " mm needs more than " + std::to_string(kMaxPolarPoints) +
                      " X/C points",
                  "use a coarser --tolerance");
      return std::nullopt;
    }
    worst = std::max(worst, sub.maxDeviation);
    if (sub.leadTurn) {  // at the centre: turn the table to the direction the move leaves in
      text += (rapidMode ? "G01 " : "") + point(sub.lead) + "\n";
      rapidMode = false;
      ++points;
    }
    for (std::size_t k = 0; k < sub.points.size(); ++k) {
      std::string line = rapidMode ? "G01 " : "";
      rapidMode = false;
      line += point(sub.points[k]);
      if (const double mf = toolpath.feedOf(i); mf > 0 && mf != feed) {
        line += " F" + formatFixed(mf, 3);
        feed = mf;
      }
      text += line + "\n";
    }
    points += sub.points.size();
    if (!sub.points.empty()) at = sub.points.back();
  }
  text += "M30\n";
  EmitOutput out;
  out.text = std::move(text);
  out.what = std::to_string(points) + " X/C points";
  out.detail = "; tolerance " + formatFixed(tol, 6) + " mm, largest deviation of the machine's spiral " +
               formatFixed(worst, 6) + " mm";
  return out;
}

}  // namespace kerf::converter
