// Contours and passes from the toolpath (passes.h): runs of cuts split where an offset run starts
// and after each return to the start hole; each pass's lead-in and lead-out, side, register,
// direction and closure from its programmed geometry.
#include "kerf/converter/structure/passes.h"

#include "kerf/converter/nc/number_format.h"
#include "kerf/geometry/chain.h"

#include <algorithm>
#include <cmath>

namespace kerf::converter {
namespace {

using geometry::Segment;
using geometry::Vec2;

class StructureFinder {
 public:
  StructureFinder(const Toolpath& tp, double tolerance) : tp_(tp), moves_(tp.moves), tol_(tolerance) {}

  Structure run() {
    Structure out;
    std::size_t i = 0;
    while (i < moves_.size()) {
      if (!moves_[i].isCut()) {
        ++i;
        continue;
      }
      Contour c;
      c.first = i;
      c.startHole = moves_[i].lower.start;
      std::size_t j = i + 1;
      while (j < moves_.size() && moves_[j].isCut()) ++j;
      c.end = j;
      splitPasses(c);
      // A run from the same start hole as the contour before (after a stop that secures the slug,
      // or a rapid back to the hole) holds more passes of that contour: a cut-off, a skim.
      if (!out.contours.empty() && atHole(out.contours.back(), c.startHole)) {
        Contour& before = out.contours.back();
        before.end = c.end;
        for (Pass& p : c.passes) before.passes.push_back(std::move(p));
      } else {
        out.contours.push_back(std::move(c));
      }
      i = j;
    }
    for (Contour& c : out.contours) {
      markCutOffs(c);
      orientOpenPasses(c);
    }
    return out;
  }

 private:
  /// The programmed geometry of move k: the contour as written, before the wire offset.
  const Segment& programmed(std::size_t k) const {
    return k < tp_.programmed.size() ? tp_.programmed[k] : moves_[k].lower;
  }
  bool atHole(const Contour& c, const Vec2& p) const { return (p - c.startHole).norm() <= tol_; }
  /// The offset runs (in order of their first moves) from the first that starts at or after move k.
  std::vector<OffsetSpan>::const_iterator spansFrom(std::size_t k) const {
    return std::lower_bound(tp_.offsetSpans.begin(), tp_.offsetSpans.end(), k,
                            [](const OffsetSpan& s, std::size_t at) { return s.first < at; });
  }
  /// The offset run that starts at move k, if one does.
  const OffsetSpan* spanStartingAt(std::size_t k) const {
    const auto it = spansFrom(k);
    return it != tp_.offsetSpans.end() && it->first == k ? &*it : nullptr;
  }

  /// Where the contour's passes start: its first move, each G41/G42 run's first move, and the move
  /// after a return to the start hole that ends a pass — one of at least three moves around some
  /// area, with at least three moves after it (a raster that steps back to the hole, or a last
  /// move away from a contour that starts on itself, is one pass).
  std::vector<std::size_t> passStarts(const Contour& c) const {
    std::vector<std::size_t> offsetStarts;
    for (auto it = spansFrom(c.first + 1); it != tp_.offsetSpans.end() && it->first < c.end; ++it)
      offsetStarts.push_back(it->first);
    std::vector<std::size_t> starts{c.first};
    auto nextOffset = offsetStarts.begin();
    std::size_t from = c.first;
    bool offsetSince = spanStartingAt(c.first) != nullptr;  // a G41/G42 run began in [from, k]
    // The area and length of the moves [from, summed), summed up to k only where a return to the
    // hole asks for them (the area of an arc takes a sine): the path back to the hole encloses area.
    double area = 0.0, length = 0.0;
    std::size_t summed = from;
    auto enclosesArea = [&](std::size_t k) {
      for (; summed <= k; ++summed) {
        const Segment& s = moves_[summed].lower;
        area += geometry::areaTerm(s);
        length += s.length();
      }
      return std::abs(area) > tol_ * length;
    };
    for (std::size_t k = c.first; k + 1 < c.end; ++k) {
      const Segment& s = moves_[k].lower;
      const bool offsetNext = nextOffset != offsetStarts.end() && *nextOffset == k + 1;
      if (offsetNext) ++nextOffset;
      // A G41/G42 run ends the pass before it, unless that is only an approach (a move or two
      // without an offset): then the run's pass takes it in.
      const bool offsetSplit = offsetNext && (offsetSince || k + 1 - from >= 3);
      const bool passBack = atHole(c, s.end) && k + 1 - from >= 3 && c.end - (k + 1) >= 3 && enclosesArea(k);
      if (offsetNext && !offsetSplit) offsetSince = true;
      if (!offsetSplit && !passBack) continue;
      starts.push_back(k + 1);
      from = k + 1;
      offsetSince = offsetNext;
      area = length = 0.0;
      summed = from;
    }
    return starts;
  }

  /// A later pass under half as long as an earlier one that leaves a tab, from where that one
  /// stopped to where it began, cuts the tab off.
  void markCutOffs(Contour& c) const {
    std::vector<Pass>& ps = c.passes;
    for (std::size_t q = 0; q < ps.size(); ++q) {
      if (ps[q].closes) continue;
      for (std::size_t p = q + 1; p < ps.size(); ++p)
        if ((ps[p].from - ps[q].to).norm() <= tol_ && (ps[p].to - ps[q].from).norm() <= tol_ &&
            ps[p].alongLength < 0.5 * ps[q].alongLength)
          ps[p].cutOff = true;
    }
  }

  /// A pass that does not close runs along part of its contour: its direction is the way it travels
  /// along the pass that closes the contour (or the longest), not the sign of the area its stretch
  /// and the chord enclose — over a notch that sign is the other (a skim forward over a tooth of a
  /// counter-clockwise die encloses clockwise area). Its elements (at most 64, evenly spread) that
  /// lie on the reference's programmed path vote by their tangents, weighted by length; a pass none
  /// of whose elements lies there keeps its area's direction. Each vote looks through the
  /// reference's elements: the votes of a contour are bounded by kVoteBudget element visits, shared
  /// by its open passes (a pass past the budget keeps its area's direction).
  void orientOpenPasses(Contour& c) const {
    std::vector<Pass>& ps = c.passes;
    std::size_t ref = ps.size();
    for (std::size_t p = 0; p < ps.size() && ref == ps.size(); ++p)
      if (ps[p].closes && !ps[p].cutOff) ref = p;
    if (ref == ps.size())
      for (std::size_t p = 0; p < ps.size(); ++p)
        if (ref == ps.size() || ps[p].alongLength > ps[ref].alongLength) ref = p;
    if (ref == ps.size() || ps[ref].direction == 0) return;
    constexpr std::size_t kVoteBudget = 20'000'000;
    const std::size_t refElements = std::max<std::size_t>(1, ps[ref].alongEnd - ps[ref].alongFirst);
    std::size_t open = 0;
    for (std::size_t p = 0; p < ps.size(); ++p) open += p != ref && !ps[p].closes && !ps[p].cutOff;
    if (open == 0) return;
    const std::size_t voters = std::min<std::size_t>(64, kVoteBudget / (refElements * open));
    if (voters == 0) return;
    for (std::size_t p = 0; p < ps.size(); ++p) {
      if (p == ref || ps[p].closes || ps[p].cutOff) continue;
      const double vote = travelAlong(ps[p], ps[ref], voters);
      if (vote != 0) ps[p].direction = vote > 0 ? ps[ref].direction : -ps[ref].direction;
    }
  }

  /// > 0 where pass p's elements (at most `voters`, evenly spread) run the same way as ref's
  /// programmed path, < 0 the other way, 0 where none of them lies on it.
  double travelAlong(const Pass& p, const Pass& ref, std::size_t voters) const {
    const std::size_t count = p.alongEnd - p.alongFirst;
    const std::size_t stride = std::max<std::size_t>(1, (count + voters - 1) / voters);
    double vote = 0.0;
    for (std::size_t k = p.alongFirst; k < p.alongEnd; k += stride) {
      const Segment& s = programmed(k);
      const Vec2 mid = s.pointAt(0.5);
      for (std::size_t r = ref.alongFirst; r < ref.alongEnd; ++r) {
        const Segment& on = programmed(r);
        if (on.distanceTo(mid) > tol_) continue;
        vote += s.length() * s.tangentAt(0.5).dot(on.tangentAt(on.parameterOf(mid)));
        break;
      }
    }
    return vote;
  }

  void splitPasses(Contour& c) const {
    const std::vector<std::size_t> starts = passStarts(c);
    for (std::size_t p = 0; p < starts.size(); ++p) {
      Pass pass;
      pass.first = starts[p];
      pass.end = p + 1 < starts.size() ? starts[p + 1] : c.end;
      describe(c, pass);
      c.passes.push_back(std::move(pass));
    }
  }

  /// Lead-in and lead-out: the offset run's own start-up and cancel moves; without an offset, a
  /// first move from the start hole and a last move back to it around a contour that closes, or a
  /// first move from the start hole alone when the moves after it close (no lead-out: the wire
  /// stops where the contour began, as kerf cam's wire paths do).
  void findLeads(const Contour& c, Pass& pass, const OffsetSpan* span) const {
    pass.alongFirst = pass.first;
    pass.alongEnd = pass.end;
    if (span) {
      if (span->first + 2 <= pass.end) pass.alongFirst = span->first + 1;
      if (span->cancelled && span->end <= pass.end && span->end - 1 > pass.alongFirst) pass.alongEnd = span->end - 1;
      return;
    }
    if (pass.end - pass.first < 2) return;
    const std::size_t last = pass.end - 1;
    if (!atHole(c, moves_[pass.first].lower.start)) return;
    if (!atHole(c, moves_[last].lower.end)) {
      if ((programmed(last).end - programmed(pass.first + 1).start).norm() <= tol_) pass.alongFirst = pass.first + 1;
      return;
    }
    if (pass.end - pass.first < 3) return;
    if ((programmed(last - 1).end - programmed(pass.first + 1).start).norm() > tol_) return;
    pass.alongFirst = pass.first + 1;
    pass.alongEnd = last;
  }

  void describe(const Contour& c, Pass& pass) const {
    // The pass's G41/G42 run: the first that starts in it (after an approach, if it has one).
    const auto it = spansFrom(pass.first);
    const OffsetSpan* span = it != tp_.offsetSpans.end() && it->first < pass.end ? &*it : nullptr;
    findLeads(c, pass, span);
    if (span) {
      pass.side = span->side;
      pass.offsetRegister = span->offsetRegister;
      pass.offset = span->value;
    }
    pass.firstLine = moves_[pass.first].line;
    pass.lastLine = moves_[pass.end - 1].line;
    const Vec2 from = programmed(pass.alongFirst).start, to = programmed(pass.alongEnd - 1).end;
    pass.from = from;
    pass.to = to;
    pass.gap = (to - from).norm();
    pass.closes = pass.gap <= tol_;
    // The pass's length, and the length and area along its contour (the programmed path). Where
    // that is the moves themselves (no wire offset), one pass over the moves gives both lengths,
    // each summed in the moves' order as alone.
    double along = 0.0, area = 0.0;
    const bool same = tp_.programmed.empty();
    for (std::size_t k = pass.first; k < pass.end; ++k) {
      const double length = moves_[k].lower.length();
      pass.length += length;
      if (same && k >= pass.alongFirst && k < pass.alongEnd) {
        along += length;
        area += geometry::areaTerm(moves_[k].lower);
      }
    }
    if (!same)
      for (std::size_t k = pass.alongFirst; k < pass.alongEnd; ++k) {
        const Segment& s = programmed(k);
        along += s.length();
        area += geometry::areaTerm(s);
      }
    pass.alongLength = along;
    if (!pass.closes) area += geometry::areaTerm(Segment::line(to, from));  // an open contour closed by its chord
    // An area smaller than a band of the tolerance's width along the contour is none.
    pass.direction = std::abs(area) <= tol_ * along ? 0 : area > 0 ? 1 : -1;
  }

  const Toolpath& tp_;
  const MoveList& moves_;
  double tol_;
};

}  // namespace

bool Structure::multiPass() const {
  return std::any_of(contours.begin(), contours.end(), [](const Contour& c) { return c.passes.size() > 1; });
}

bool cutsFree(const Contour& contour) {
  return std::any_of(contour.passes.begin(), contour.passes.end(), [](const Pass& p) { return p.closes || p.cutOff; });
}

int keptSide(const Pass& pass) {
  if (pass.side == WireOffset::Off || pass.direction == 0 || pass.cutOff) return 0;
  const int left = pass.side == WireOffset::Left ? 1 : -1;  // G41: the wire left of the direction of travel
  return left * pass.direction;                             // left of a counter-clockwise contour is inside it
}

Structure findStructure(const Toolpath& toolpath, double tolerance) {
  Structure st = StructureFinder(toolpath, tolerance).run();
  // Each pass's machining condition: the last one selected at or before its first move along the
  // contour (a condition is usually written on the lead-in's block or just before it).
  if (!toolpath.conditions.empty())
    for (Contour& c : st.contours)
      for (Pass& p : c.passes) {
        const std::size_t at = p.alongFirst < p.alongEnd ? p.alongFirst : p.first;
        for (const Toolpath::ConditionChange& change : toolpath.conditions)
          if (change.from <= at) p.condition = change.name;
      }
  return st;
}

const char* directionName(int direction) {
  return direction > 0 ? "counter-clockwise" : direction < 0 ? "clockwise" : "neither";
}

std::string offsetText(const Pass& p) {
  if (p.side == WireOffset::Off) return "no offset";
  std::string t = p.side == WireOffset::Left ? "G41" : "G42";
  if (!p.offsetRegister.empty()) t += " " + p.offsetRegister;
  if (p.offset) return t + (p.offsetRegister.empty() ? " " : " = ") + formatFixed(*p.offset, 3) + " mm";
  return t + " (offset at the machine)";
}

const char* passRole(const Pass& pass, std::size_t index) {
  return pass.cutOff ? "the cut-off through the tab" : index == 0 ? "the rough cut" : "a skim";
}

std::string passName(std::size_t contour, std::size_t index) {
  return "pass " + std::to_string(index + 1) + " of contour " + std::to_string(contour + 1);
}

std::vector<std::uint8_t> movePasses(const Structure& structure, std::size_t moves) {
  std::vector<std::uint8_t> out(moves, 0);
  for (const Contour& c : structure.contours)
    for (std::size_t k = 0; k < c.passes.size(); ++k)
      for (std::size_t m = c.passes[k].first; m < c.passes[k].end && m < moves; ++m)
        out[m] = static_cast<std::uint8_t>(std::min<std::size_t>(k + 1, 255));
  return out;
}

std::optional<Toolpath> toolpathOfPass(const Toolpath& toolpath, const Structure& structure, std::size_t pass,
                                       double tolerance) {
  const std::vector<std::uint8_t> number = movePasses(structure, toolpath.moves.size());
  if (pass == 0 || std::find(number.begin(), number.end(), std::min<std::size_t>(pass, 255)) == number.end())
    return std::nullopt;
  std::vector<MoveRow> rows;
  std::vector<std::uint32_t> newIndex(toolpath.moves.size() + 1, 0);
  for (std::size_t i = 0; i < toolpath.moves.size(); ++i) {
    newIndex[i] = static_cast<std::uint32_t>(rows.size());
    const Move& m = toolpath.moves[i];
    if (m.isCut() && number[i] != pass) continue;
    if (!rows.empty() && (rows.back().move.lower.end - m.lower.start).norm() > tolerance) {
      MoveRow join = toolpath.rowOf(i);  // a rapid to where this move starts, in its block's place
      join.move.kind = MoveKind::Rapid;
      join.move.centreForm = CentreForm::None;
      join.move.wireOffset = WireOffset::Off;
      join.move.lower = geometry::Segment::line(rows.back().move.lower.end, m.lower.start);
      join.upper = geometry::Segment::line(rows.back().upper.end, toolpath.upperOf(i).start);
      join.programmed = join.move.lower;
      join.offsetRole = OffsetRole::None;
      join.centreWords = geometry::Vec2(0, 0);
      rows.push_back(join);
    }
    newIndex[i] = static_cast<std::uint32_t>(rows.size());
    rows.push_back(toolpath.rowOf(i));
  }
  newIndex[toolpath.moves.size()] = static_cast<std::uint32_t>(rows.size());
  Toolpath out = toolpath;
  out.replaceMoves(std::move(rows), newIndex);
  return out;
}

}  // namespace kerf::converter
