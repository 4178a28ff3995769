// 3B and 4B writers (docs/3b.md). Sections: 1. the order of the moves  2. one record  3. 3B  4. 4B
#include "kerf/converter/formats/3b/write_3b.h"

#include "kerf/converter/nc/number_format.h"
#include "three_b.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>

namespace kerf::converter {

namespace {

using geometry::kPi;
using geometry::Vec2;
using three_b::Axis;

// ---- 1. the order of the moves ---------------------------------------------------------------------

/// The moves to write, in order: all of them; with a start line, the cut moves from there
/// (startCutPathAt, as the point emitters do).
std::optional<std::vector<std::size_t>> moveOrder(const Toolpath& toolpath, const SourceFile* source,
                                                  std::optional<std::uint32_t> startLine, Diagnostics& diags) {
  if (std::none_of(toolpath.moves.begin(), toolpath.moves.end(), [](const Move& m) { return m.isCut(); })) {
    diags.error(Code::NothingToWrite, source, SourceSpan::wholeFile(),
                "nothing to write: the program has no cutting move");
    return std::nullopt;
  }
  std::vector<std::size_t> order;
  if (!startLine) {
    for (std::size_t i = 0; i < toolpath.moves.size(); ++i) order.push_back(i);
    return order;
  }
  CutPath path = cutPath(toolpath);
  if (!startCutPathAt(toolpath, path, *startLine, source, diags)) return std::nullopt;
  order = std::move(path.moveIndex);
  return order;
}

// ---- 2. one record -----------------------------------------------------------------------------------

using Micro = std::array<std::int64_t, 2>;

Micro toMicro(const Vec2& p) { return {std::llround(p.x() * 1000.0), std::llround(p.y() * 1000.0)}; }
Vec2 vec(const Micro& m) { return {static_cast<double>(m[0]), static_cast<double>(m[1])}; }

struct Record {
  std::uint64_t x = 0, y = 0, j = 0;
  Axis axis = Axis::X;
  bool arc = false, ccw = false;
  int quadrant = 1;
  std::uint64_t radius = 0;  ///< µm, arcs (4B)
};

std::string recordText(const Record& r, bool compact) {
  const char* sep = compact ? "" : " ";
  std::string z = r.arc ? std::string(r.ccw ? "NR" : "SR") : std::string("L");
  z += std::to_string(r.quadrant);
  return "B" + std::to_string(r.x) + sep + "B" + std::to_string(r.y) + sep + "B" + std::to_string(r.j) + sep + "G" +
         (r.axis == Axis::X ? "X" : "Y") + sep + z;
}

Record lineRecord(const Micro& d) {
  Record r;
  const double dx = static_cast<double>(d[0]), dy = static_cast<double>(d[1]);
  r.x = static_cast<std::uint64_t>(std::llabs(d[0]));
  r.y = static_cast<std::uint64_t>(std::llabs(d[1]));
  r.axis = three_b::lineAxis(dx, dy);
  r.j = r.axis == Axis::X ? r.x : r.y;
  r.quadrant = three_b::lineQuadrant(dx, dy);
  // On an axis x and y are written 0 and J is the length; L names the direction (seed 004: "终点在
  // 坐标轴上时,x、y值为零,计数长度j为线段长度", the form its controls and posts expect).
  if (d[0] == 0 || d[1] == 0) r.x = r.y = 0;
  return r;
}

/// The sweep from startRel to endRel in the arc's direction; a full turn when they coincide.
double sweepBetween(const Vec2& s, const Vec2& e, bool ccw) {
  double a = std::atan2(e.y(), e.x()) - std::atan2(s.y(), s.x());
  if (ccw) {
    while (a <= 0) a += 2 * kPi;
    while (a > 2 * kPi) a -= 2 * kPi;
  } else {
    while (a >= 0) a -= 2 * kPi;
    while (a < -2 * kPi) a += 2 * kPi;
  }
  return a;
}

/// The record of an arc from `from` to `to` (µm) about `centre` (µm).
Record arcRecord(const Micro& from, const Micro& to, const Micro& centre, bool ccw) {
  Record r;
  r.arc = true;
  r.ccw = ccw;
  const Vec2 s = vec(from) - vec(centre), e = vec(to) - vec(centre);
  r.x = static_cast<std::uint64_t>(std::llabs(from[0] - centre[0]));
  r.y = static_cast<std::uint64_t>(std::llabs(from[1] - centre[1]));
  r.quadrant = three_b::arcQuadrant(s.x(), s.y(), ccw);
  r.axis = three_b::arcAxis(e.x(), e.y());
  const double radius = s.norm();
  const double sweep = sweepBetween(s, e, ccw);
  const int ax = r.axis == Axis::X ? 0 : 1;
  r.j = static_cast<std::uint64_t>(
      std::llround(three_b::arcCount(std::atan2(s.y(), s.x()), sweep, radius, r.axis, s[ax], e[ax])));
  r.radius = static_cast<std::uint64_t>(std::llround(radius));
  return r;
}

/// Where a reader (and the machine) ends this arc record, on the µm grid, and the sweep it turns.
std::optional<Micro> arcRecordEnd(const Record& r, const Micro& from, double* sweepOut = nullptr) {
  const Vec2 signs = three_b::quadrantSigns(r.quadrant);
  const Vec2 startRel(signs.x() * static_cast<double>(r.x), signs.y() * static_cast<double>(r.y));
  Vec2 endRel;
  double sweep = 0;
  if (!three_b::arcEnd(startRel, r.ccw, r.axis, static_cast<double>(r.j), 1.0, endRel, sweep)) return std::nullopt;
  if (sweepOut) *sweepOut = sweep;
  const Vec2 d = endRel - startRel;
  return Micro{from[0] + std::llround(d.x()), from[1] + std::llround(d.y())};
}

/// How far (µm) an arc of radius `rr` about `d` (relative to the source centre), from angle `a0`
/// through `sweep`, strays from the source circle of radius `radius` about the origin: exact, not
/// sampled. The distance from the source centre along the arc is largest or smallest at its ends
/// or where its radius points along the line between the two centres.
double offCircle(const Vec2& d, double rr, double a0, double sweep, double radius) {
  auto off = [&](double a) { return std::abs((d + rr * Vec2(std::cos(a), std::sin(a))).norm() - radius); };
  double worst = std::max(off(a0), off(a0 + sweep));
  if (d.squaredNorm() > 0 && sweep != 0)
    for (double a : {std::atan2(d.y(), d.x()), std::atan2(-d.y(), -d.x())}) {
      double t = (a - a0) / sweep;  // the turn from the start to angle a, as a fraction of the sweep
      const double turn = 2 * kPi / std::abs(sweep);
      t -= std::floor(t / turn) * turn;
      if (t <= 1) worst = std::max(worst, off(a));
    }
  return worst;
}

/// The wire offset (µm) at which the writer also holds an arc to its source: the part edge, that
/// far from the path, moves with the centre (a corner arc's centre is the part's corner), where
/// the path itself hardly does. 0.15 mm is a common offset (docs/3b.md) [decided].
constexpr double kEdgeOffset = 150.0;

/// How far (µm) the arc a reader makes of record `r` from `from` (through `sweep`) strays from the
/// source arc (`centre`, `radius`, µm): the path itself, and the two curves kEdgeOffset either side
/// of it where they exist.
double offSource(const Record& r, const Micro& from, double sweep, const Vec2& centre, double radius) {
  const Vec2 signs = three_b::quadrantSigns(r.quadrant);
  const Vec2 startRel(signs.x() * static_cast<double>(r.x), signs.y() * static_cast<double>(r.y));
  const Vec2 d = vec(from) - startRel - centre;  // the read centre relative to the source centre
  const double rr = startRel.norm(), a0 = std::atan2(startRel.y(), startRel.x());
  double worst = offCircle(d, rr, a0, sweep, radius);
  worst = std::max(worst, offCircle(d, rr + kEdgeOffset, a0, sweep, radius + kEdgeOffset));
  // Inside, where the source's curve exists: a corner arc of the offset's radius (within the 2 µm
  // the drawing check allows, docs/drawing.md) shrinks to the corner point.
  if (radius > kEdgeOffset - 2.0)
    worst = std::max(worst, offCircle(d, rr - kEdgeOffset, a0, sweep, std::abs(radius - kEdgeOffset)));
  return worst;
}

/// How far (µm, per axis) the writer looks for a centre from which the count ends on the grid.
constexpr int kCentreSearch = 4;
/// How far (µm) a point on the µm grid can lie from the point it rounds: half a diagonal.
constexpr double kGridRounding = 0.7072;
/// What ending one micrometre beside the rounded end point costs a centre (µm): the exact end wins
/// unless another centre holds the arc nearer its source by more than this.
constexpr double kBesideEnd = 0.1;

/// An arc record, where the machine's count ends it, and whether its centre is not the source's
/// rounded.
struct ArcChoice {
  Record record;
  Micro end{};
  bool moved = false;
};

/// The arc record from `at` (µm grid) for the source arc `s`, which the writer rounded to end at
/// `to`. The source's centre rounded, when the machine's count from it ends on `to` and its arc
/// strays no more than the grid's own rounding; else, of the µm centres within kCentreSearch per
/// axis of the source's centre or of its foot on the bisector of at–to (where a centre must lie for
/// the count to end on `to`: far from the source's centre on a large, short arc), those from which
/// the count ends on `to` (or, unless `exactEnd`, a grid point next to it), the one whose arc (end
/// and part edge, see offSource) lies nearest the source's. Nothing when no count ends that near.
std::optional<ArcChoice> nearestArcRecord(const Micro& at, const Micro& to, const geometry::Segment& s, bool ccw,
                                          bool exactEnd) {
  const Vec2 centre = s.centre * 1000.0, sourceEnd = s.end * 1000.0;
  const double radius = s.radius() * 1000.0;
  const Micro c0 = toMicro(s.centre);
  std::optional<ArcChoice> found;
  double bestOff = 1e300;
  auto consider = [&](const Micro& c, double bias) {
    const Record r = arcRecord(at, to, c, ccw);
    double sweep = 0;
    const std::optional<Micro> e = arcRecordEnd(r, at, &sweep);
    const int beside = exactEnd ? 0 : 1;
    if (!e || std::abs((*e)[0] - to[0]) > beside || std::abs((*e)[1] - to[1]) > beside) return;
    const double off = std::max(offSource(r, at, sweep, centre, radius), (vec(*e) - sourceEnd).norm()) +
                       (*e == to ? 0.0 : kBesideEnd) + bias;
    if (off < bestOff) {
      bestOff = off;
      found = ArcChoice{r, *e, c != c0};
    }
  };
  consider(c0, 0.0);
  if (found && found->end == to && bestOff <= kGridRounding) return found;
  std::vector<Micro> around{c0};
  const Vec2 chord = vec(to) - vec(at);
  if (chord.squaredNorm() > 0) {
    const Vec2 mid = 0.5 * (vec(at) + vec(to)), n(-chord.y(), chord.x());
    const Vec2 foot = mid + n * ((centre - mid).dot(n) / n.squaredNorm());
    const Micro f{std::llround(foot.x()), std::llround(foot.y())};
    if (f != c0) {
      around.push_back(f);
      consider(f, 0.0);
    }
  }
  // Ring by ring outwards (Chebyshev distance k), until an arc within the grid's own rounding.
  for (int k = 1; k <= kCentreSearch && bestOff > kGridRounding; ++k)
    for (const Micro& a : around)
      for (int dx = -k; dx <= k; ++dx)
        for (int dy = -k; dy <= k; dy += (std::abs(dx) == k ? 1 : 2 * k))
          consider(Micro{a[0] + dx, a[1] + dy}, 1e-9 * (dx * dx + dy * dy));
  return found;
}

// ---- 3. 3B -----------------------------------------------------------------------------------------------

struct Written {
  std::vector<Record> records;
  std::vector<std::size_t> moveOf;  ///< the move of each record
  std::size_t rapids = 0, skipped = 0, centresMoved = 0, besideEnd = 0, flattened = 0;
  double largestMiss = 0.0;  ///< µm: an arc end the machine cannot reach on the grid
};

/// The records of the moves in `order`, each computed from rounded absolute positions.
Written records(const Toolpath& toolpath, const std::vector<std::size_t>& order, const SourceFile* source,
                Diagnostics& diags) {
  Written w;
  Micro at = toMicro(toolpath.moves[order.front()].lower.start);
  for (std::size_t i : order) {
    const Move& m = toolpath.moves[i];
    const geometry::Segment& s = m.lower;
    const Micro to = toMicro(s.end);
    if (!m.isCut()) ++w.rapids;
    if (!s.isArc()) {
      const Micro d{to[0] - at[0], to[1] - at[1]};
      if (d[0] == 0 && d[1] == 0) {
        ++w.skipped;
        continue;
      }
      w.records.push_back(lineRecord(d));
      w.moveOf.push_back(i);
      at = to;
      continue;
    }
    const bool ccw = s.sweep > 0;
    if (at == to && std::abs(s.sweep) < kPi) {  // a sliver of an arc that rounds to nothing
      ++w.skipped;
      continue;
    }
    // The last record ends exactly where the source does.
    const std::optional<ArcChoice> choice = nearestArcRecord(at, to, s, ccw, i == order.back());
    if (!choice && std::abs(s.sweep) < kPi && s.radius() * (1 - std::cos(std::abs(s.sweep) / 2)) < 0.0005) {
      // An arc that bulges from its chord by less than half a micrometre is, in whole
      // micrometres, the line of its chord; where no count lands on its end (a micro arc's count
      // runs on round the circle), it is written as that line.
      w.records.push_back(lineRecord(Micro{to[0] - at[0], to[1] - at[1]}));
      w.moveOf.push_back(i);
      ++w.flattened;
      at = to;
      continue;
    }
    Record best;
    std::optional<Micro> end;
    if (choice) {
      best = choice->record;
      end = choice->end;
      w.centresMoved += choice->moved ? 1 : 0;
      w.besideEnd += choice->end != to ? 1 : 0;
    } else {  // the rounded centre, and the miss said
      best = arcRecord(at, to, toMicro(s.centre), ccw);
      end = arcRecordEnd(best, at);
      if (end) w.largestMiss = std::max(w.largestMiss, (vec(*end) - vec(to)).norm());
    }
    w.records.push_back(best);
    w.moveOf.push_back(i);
    // The next record starts where the machine is: an arc that ends beside its grid point does not
    // shift the rest of the program (every later end is a rounded absolute position).
    at = end.value_or(to);
  }
  if (w.rapids > 0) {
    std::size_t first = 0;
    while (toolpath.moves[order[first]].isCut()) ++first;
    diags.warning(Code::NotInOutputFormat, source, toolpath.moves[order[first]].span,
                  "3B has no rapid move: " + std::to_string(w.rapids) + (w.rapids == 1 ? " rapid is" : " rapids are") +
                      " written as cut lines",
                  "3B controls cut every record; thread the wire where the program starts a new contour");
  }
  if (w.centresMoved > 0)
    diags.note(Code::OutputAdjusted, source, SourceSpan::wholeFile(),
               std::to_string(w.centresMoved) + (w.centresMoved == 1 ? " arc's centre was" : " arcs' centres were") +
                   " moved off the rounded centre so that the count ends on or beside the rounded end point, "
                   "nearest the source arc (docs/3b.md)");
  if (w.besideEnd > 0)
    diags.note(Code::OutputAdjusted, source, SourceSpan::wholeFile(),
               std::to_string(w.besideEnd) + (w.besideEnd == 1 ? " arc ends" : " arcs end") +
                   " one micrometre beside the rounded end point, which holds the arc nearer its source; the next "
                   "record starts there (docs/3b.md)");
  if (w.flattened > 0)
    diags.note(Code::OutputAdjusted, source, SourceSpan::wholeFile(),
               std::to_string(w.flattened) + (w.flattened == 1 ? " arc" : " arcs") +
                   " bulging less than half a micrometre from the chord, whose count could not end on the end point, "
                   "written as the line of the chord (docs/3b.md)");
  if (w.largestMiss > 0)
    diags.warning(Code::OutputAdjusted, source, SourceSpan::wholeFile(),
                  "an arc's count ends " + formatFixed(w.largestMiss, 1) +
                      " µm from its rounded end point, and no centre within " + std::to_string(kCentreSearch) +
                      " µm fixes it");
  return w;
}

std::string recordsText(const Written& w, const ThreeBWriteOptions& request, std::string header,
                        const std::function<std::string(const Record&, std::size_t)>& line) {
  std::string text = std::move(header);
  text.reserve(text.size() + w.records.size() * 28 + 4);
  for (std::size_t k = 0; k < w.records.size(); ++k) text += line(w.records[k], k) + "\n";
  if (!request.end.empty()) text += request.end + "\n";
  return text;
}

// ---- 4. 4B -----------------------------------------------------------------------------------------------

/// The signed area enclosed by a path closed by its chord (> 0 counter-clockwise).
double signedArea(const std::vector<geometry::Segment>& path) {
  double a = 0.0;
  for (const geometry::Segment& s : path) {
    a += 0.5 * (s.start.x() * s.end.y() - s.end.x() * s.start.y());
    if (s.isArc()) a += 0.5 * s.radius() * s.radius() * (s.sweep - std::sin(s.sweep));  // the cap beyond the chord
  }
  return a;
}

/// One 4B record; counterClockwise: the contour's orientation.
std::string fourBLine(const Record& r, const Move& m, bool counterClockwise, bool compact) {
  // Left of travel is inside a counter-clockwise contour: G41 there shrinks the part (-).
  const bool left = m.wireOffset == WireOffset::Left;
  const bool shrinks = m.wireOffset != WireOffset::Off && (left == counterClockwise);
  const char* sep = compact ? "" : " ";
  std::string text = std::string(shrinks ? "-" : "+") + "B" + std::to_string(r.x) + sep + "B" + std::to_string(r.y) +
                     sep + "B" + std::to_string(r.j) + sep + "B" + std::to_string(r.arc ? r.radius : 0) + sep + "G" +
                     (r.axis == Axis::X ? "X" : "Y") + sep;
  if (r.arc) text += std::string(r.ccw == counterClockwise ? "D" : "DD") + sep;
  text += (r.arc ? std::string(r.ccw ? "NR" : "SR") : std::string("L")) + std::to_string(r.quadrant);
  return text;
}

std::string summaryOf(const Written& w) {
  return std::to_string(w.records.size()) + (w.records.size() == 1 ? " record" : " records");
}

}  // namespace

std::optional<EmitOutput> writeThreeB(const Toolpath& toolpath, const SourceFile* source,
                                      const ThreeBWriteOptions& request, Diagnostics& diags) {
  const std::optional<std::vector<std::size_t>> order = moveOrder(toolpath, source, request.startLine, diags);
  if (!order) return std::nullopt;
  const Written w = records(toolpath, *order, source, diags);
  EmitOutput out;
  out.text = recordsText(w, request, {}, [&](const Record& r, std::size_t) { return recordText(r, request.compact); });
  out.what = summaryOf(w) + " of 3B code";
  out.detail = "; whole micrometres from rounded absolute positions (the end is exact)";
  return out;
}

std::optional<EmitOutput> writeFourB(const Toolpath& toolpath, const SourceFile* source,
                                     const ThreeBWriteOptions& request, Diagnostics& diags) {
  const std::optional<std::vector<std::size_t>> order = moveOrder(toolpath, source, request.startLine, diags);
  if (!order) return std::nullopt;
  const Written w = records(toolpath, *order, source, diags);
  std::vector<geometry::Segment> cut;
  for (std::size_t i : *order)
    if (toolpath.moves[i].isCut()) cut.push_back(toolpath.moves[i].lower);
  const bool ccw = signedArea(cut) >= 0;
  diags.note(Code::OutputUnsure, source, SourceSpan::wholeFile(),
             "the 4B layout is a textbook's, not a controller manual's [unsure]: check it against your control "
             "(docs/3b.md)");
  const std::string header =
      "; 4B code written by Kerf. Layout [unsure: from textbooks, no controller manual]: +-B x B y B J B R G D|DD Z\n"
      "; x y J G Z as in 3B (FORMATS 4, sourced); R the arc radius in um (0 for a line);\n"
      "; D a convex arc, DD a concave one, by the contour's orientation (textbook);\n"
      "; + the wire offset enlarges the part or there is none, - it shrinks it (G41/G42 in the source).\n";
  EmitOutput out;
  out.text = recordsText(w, request, header, [&](const Record& r, std::size_t k) {
    return fourBLine(r, toolpath.moves[w.moveOf[k]], ccw, request.compact);
  });
  out.what = summaryOf(w) + " of 4B code [unsure layout]";
  out.detail = "; whole micrometres from rounded absolute positions";
  return out;
}

}  // namespace kerf::converter
