// A block's construction (construction.h). Sections: 1. marks  2. words  3. modes and pass
#include "kerf/converter/report/construction.h"

#include "figures.h"

#include "kerf/converter/interpret/machine.h"
#include "kerf/converter/nc/diagnostics.h"
#include "kerf/converter/nc/number_format.h"
#include "kerf/geometry/arc.h"
#include "kerf/geometry/ruled_surface.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iterator>

namespace kerf::converter {

namespace {

using geometry::kPi;
using geometry::Segment;
using geometry::Vec2;
using Mark = ConstructionMark;

using figures::deg;
using figures::mm;
/// An angle in [0, 2 pi), counter-clockwise from +X.
double ccwAngle(double a) {
  a = std::fmod(a, 2 * kPi);
  if (a < 0) a += 2 * kPi;
  return a >= 2 * kPi - 1e-12 ? 0.0 : a;  // a turn less a rounding error is the +X ray
}

/// The text of move i's block; empty when the move has none of its own (a corner the wire offset
/// added, a drawing's contour).
std::string blockTextOf(const SourceFile& source, const Move& m) {
  if (m.span.isWholeFile() || static_cast<std::size_t>(m.span.offset) + m.span.length > source.text().size()) return {};
  return std::string(source.text().substr(m.span.offset, m.span.length));
}

/// The G41/G42 run move i is cut under, or null (Move::wireOffset is cleared where the offset was
/// applied: the path is then the wire's centre).
const OffsetSpan* offsetSpanOf(const Toolpath& tp, std::size_t i) {
  // The runs are in program order and do not overlap: the last one starting at or before i.
  const auto after = std::upper_bound(tp.offsetSpans.begin(), tp.offsetSpans.end(), i,
                                      [](std::size_t move, const OffsetSpan& span) { return move < span.first; });
  if (after == tp.offsetSpans.begin()) return nullptr;
  const OffsetSpan& span = *std::prev(after);
  return i < span.end ? &span : nullptr;
}

std::string sideName(WireOffset side) {
  return side == WireOffset::Left ? "left of travel (G41)" : side == WireOffset::Right ? "right of travel (G42)" : "";
}

// ---- 1. marks ----------------------------------------------------------------------------------------

void add(std::vector<Mark>& marks, Mark::Kind kind, Mark::Role role, const Segment& s, std::string label = {},
         bool upper = false) {
  marks.push_back(Mark{kind, role, s, upper, std::move(label)});
}

/// An arc from R: the chord, its bisector through both candidate centres, the one taken and the one
/// the sign of R rejects (seed 000's zn), the radius.
void radiusConstruction(std::vector<Mark>& marks, const Segment& d, double r) {
  const Vec2 mid = 0.5 * (d.start + d.end);
  const Vec2 taken = d.centre, rejected = 2.0 * mid - d.centre;
  const int zn = geometry::seedSignFactor(d.direction(), r);
  add(marks, Mark::Kind::Point, Mark::Role::Centre, Segment::line(taken, taken),
      "centre taken: R " + std::string(r > 0 ? "> 0, the arc of at most 180 deg" : "< 0, the arc over 180 deg") +
          " (zn = " + (zn > 0 ? "+1" : "-1") + ")");
  add(marks, Mark::Kind::Point, Mark::Role::Rejected, Segment::line(rejected, rejected),
      std::string("rejected: the centre of the ") + (r > 0 ? "longer" : "shorter") + " arc");
  add(marks, Mark::Kind::Segment, Mark::Role::Chord, Segment::line(d.start, d.end),
      "chord " + mm((d.end - d.start).norm()) + " mm");
  // The bisector runs through both centres and a little beyond; when they coincide (a half circle)
  // it is drawn a quarter of the radius either side.
  Vec2 along = rejected - taken;
  if (along.norm() < 1e-9 * std::max(1.0, d.radius())) {
    const Vec2 chord = (d.end - d.start).normalized();
    along = 0.5 * d.radius() * Vec2(-chord.y(), chord.x());
  }
  add(marks, Mark::Kind::Segment, Mark::Role::Bisector, Segment::line(taken - 0.15 * along, rejected + 0.15 * along),
      "perpendicular bisector of the chord");
  add(marks, Mark::Kind::Segment, Mark::Role::Radius, Segment::line(taken, d.start), "R " + mm(r));
}

/// An arc from I J (or 3B's x y): the vector the words give, and the radius that follows.
void vectorConstruction(std::vector<Mark>& marks, const Toolpath& tp, std::size_t i, const Segment& d) {
  const Vec2 w = tp.programmedCentreWords(i);
  const std::string ij = "(" + mm(w.x()) + ", " + mm(w.y()) + ")";
  if (tp.format == InputFormat::ThreeB) {
    add(marks, Mark::Kind::Arrow, Mark::Role::Vector, Segment::line(d.centre, d.start), "x y = start - centre = " + ij);
  } else {
    const ArcCentreMode convention = arcCentreOf(tp.moves[i].centreForm);
    const std::string rule = arcCentreRule(convention);
    if (convention == ArcCentreMode::Absolute)  // from the program's origin, wherever G92 put it
      add(marks, Mark::Kind::Arrow, Mark::Role::Vector, Segment::line(d.centre - w, d.centre),
          rule + " = " + ij + " from the program's origin");
    else
      add(marks, Mark::Kind::Arrow, Mark::Role::Vector, Segment::line(d.start, d.centre), rule + "; I J = " + ij);
  }
  add(marks, Mark::Kind::Point, Mark::Role::Centre, Segment::line(d.centre, d.centre), "centre");
  // The vector already joins the start and the centre: the radius is drawn to the end, which lies
  // on the circle within the accepted tolerance.
  add(marks, Mark::Kind::Segment, Mark::Role::Radius, Segment::line(d.centre, d.end),
      "r = |start - centre| = " + mm(d.radius()));
}

/// The angles about the centre: the +X ray they are measured from, the start and end angles
/// (counter-clockwise, and seed 000's clockwise alpha and beta), the sweep and direction.
void angleConstruction(std::vector<Mark>& marks, const Segment& s, const geometry::SeedArcAngles& seed) {
  const Vec2 c = s.centre;
  const double r = s.radius();
  add(marks, Mark::Kind::Segment, Mark::Role::Angle, Segment::line(c, c + Vec2(0.45 * r, 0)), "+X");
  auto angleArc = [&](double a, double radius, std::string label) {
    const double to = ccwAngle(a);
    if (to < 1e-9) {  // on the +X ray itself: a point names it
      add(marks, Mark::Kind::Point, Mark::Role::Angle, Segment::line(c + Vec2(radius, 0), c + Vec2(radius, 0)),
          std::move(label));
      return;
    }
    add(marks, Mark::Kind::Segment, Mark::Role::Angle,
        Segment::arc(c + Vec2(radius, 0), c + radius * geometry::direction(to), c,
                     geometry::ArcDirection::CounterClockwise),
        std::move(label));
  };
  angleArc(s.startAngle(), 0.3 * r,
           "start " + deg(ccwAngle(s.startAngle())) + " deg ccw; alpha " + deg(seed.alpha) + " (seed, cw)");
  angleArc(s.startAngle() + s.sweep, 0.2 * r,
           "end " + deg(ccwAngle(s.startAngle() + s.sweep)) + " deg ccw; beta " + deg(seed.beta) + " (seed, cw)");
}

/// The chords at the sampling and the largest deviation, marked on the first chord (every full
/// chord spans the same angle; the last, shorter one deviates less).
std::optional<double> chordConstruction(std::vector<Mark>& marks, const Segment& s, const geometry::Sampling& sampling,
                                        const geometry::SeedArcAngles& seed) {
  constexpr std::size_t kMostChordsDrawn = 2000;  // a finer sampling draws only the worst chord
  std::vector<Vec2> points;
  const geometry::ArcSampleStats st = geometry::sample(s, sampling, &points);
  if (points.empty()) return std::nullopt;
  Vec2 from = s.start;
  if (points.size() <= kMostChordsDrawn)
    for (const Vec2& p : points) {
      add(marks, Mark::Kind::Segment, Mark::Role::Sample, Segment::line(from, p));
      from = p;
    }
  const Vec2 a = s.start, b = points.front(), m = 0.5 * (a + b);
  add(marks, Mark::Kind::Segment, Mark::Role::Deviation, Segment::line(a, b));  // the worst chord
  const Vec2 onArc = (m - s.centre).norm() > 0 ? s.centre + s.radius() * (m - s.centre).normalized() : m;
  const bool step = sampling.mode == geometry::SamplingMode::Step;
  add(marks, Mark::Kind::Segment, Mark::Role::Deviation, Segment::line(m, onArc),
      "max deviation " + formatFixed(st.maxDeviation, 6) + " mm" +
          (step ? ", gamma = 2 asin(k / 2R) = " + deg(seed.gamma) + " deg" : std::string()) + "; " +
          std::to_string(st.points) + (st.points == 1 ? " chord" : " chords"));
  return st.maxDeviation;
}

/// A taper move: the upper segment, the wire at both ends, the slope there.
void taperConstruction(std::vector<Mark>& marks, const Toolpath& tp, std::size_t i) {
  const Segment& s = tp.moves[i].lower;
  const Segment& u = tp.upper[i];
  add(marks, Mark::Kind::Segment, Mark::Role::Upper, u, "upper", true);
  std::string atStart = "wire at the start", atEnd = "wire at the end";
  if (tp.heights.known) {
    atStart += ", slope " + formatFixed(geometry::slopeAt(s, u, tp.heights.planes, 0.0) * 180.0 / kPi, 3) + " deg";
    atEnd += ", slope " + formatFixed(geometry::slopeAt(s, u, tp.heights.planes, 1.0) * 180.0 / kPi, 3) + " deg";
  }
  add(marks, Mark::Kind::Wire, Mark::Role::Upper, Segment::line(s.start, u.start), atStart);
  add(marks, Mark::Kind::Wire, Mark::Role::Upper, Segment::line(s.end, u.end), atEnd);
}

/// A wire-offset move: the segment as programmed and the offset from it to the wire's centre.
void offsetConstruction(std::vector<Mark>& marks, const Toolpath& tp, std::size_t i) {
  const OffsetRole role = tp.offsetRole[i];
  if (role == OffsetRole::None) return;
  const Segment& p = tp.programmed[i];
  const Segment& s = tp.moves[i].lower;
  const OffsetSpan* span = offsetSpanOf(tp, i);
  const std::string side = span ? sideName(span->side) : std::string();
  if (role == OffsetRole::Corner) {
    add(marks, Mark::Kind::Point, Mark::Role::Programmed, Segment::line(p.start, p.start), "the programmed corner");
  } else {
    add(marks, Mark::Kind::Segment, Mark::Role::Programmed, p, "as programmed");
  }
  const Vec2 from = p.pointAt(0.5), to = s.pointAt(0.5);
  if ((to - from).norm() > 1e-9)
    add(marks, Mark::Kind::Arrow, Mark::Role::Offset, Segment::line(from, to),
        "offset " + mm((to - from).norm()) + " mm " + side);
}

/// The corner a block's `,R` / `,C` (or NCVC's R) made that move i is, or is followed by; null.
const Toolpath::CornerMade* cornerOf(const Toolpath& tp, std::size_t i, bool following) {
  return tp.cornerAt(following ? i + 1 : i);
}

/// A corner rounded or chamfered at a block's end: where the elements met, the ends trimmed from
/// them, and a fillet's centre and radii to its tangent points.
void cornerConstruction(std::vector<Mark>& marks, const Toolpath::CornerMade& c, const Segment& s) {
  add(marks, Mark::Kind::Point, Mark::Role::Programmed, Segment::line(c.sharp, c.sharp),
      "the sharp corner " + formatPoint(c.sharp));
  add(marks, Mark::Kind::Segment, Mark::Role::Programmed, Segment::line(s.start, c.sharp), "trimmed");
  add(marks, Mark::Kind::Segment, Mark::Role::Programmed, Segment::line(c.sharp, s.end), "trimmed");
  if (!s.isArc()) return;
  add(marks, Mark::Kind::Point, Mark::Role::Centre, Segment::line(s.centre, s.centre),
      "fillet centre " + formatPoint(s.centre));
  add(marks, Mark::Kind::Segment, Mark::Role::Radius, Segment::line(s.centre, s.start), "R " + mm(c.size));
  add(marks, Mark::Kind::Segment, Mark::Role::Radius, Segment::line(s.centre, s.end));
}

/// What a corner word says: the fillet or chamfer it made (lowerMeaning, kerf explain).
std::string cornerMeaning(const Toolpath& tp, std::size_t i) {
  const Toolpath::CornerMade* c = cornerOf(tp, i, false);
  if (!c) c = cornerOf(tp, i, true);
  if (!c || c->move >= tp.moves.size())
    return "rounds or chamfers the corner at the block's end (not made: see the error)";
  const Segment& s = tp.moves[c->move].lower;
  if (c->chamfer)
    return "chamfers the corner at the block's end: the elements met at " + formatPoint(c->sharp) + "; a line from " +
           formatPoint(s.start) + " to " + formatPoint(s.end) + ", each " + mm(c->size) + " mm from that corner";
  return "rounds the corner at the block's end with radius " + mm(c->size) + " mm: the elements met at " +
         formatPoint(c->sharp) + "; the fillet's centre is " + formatPoint(s.centre) + ", its tangent points " +
         formatPoint(s.start) + " and " + formatPoint(s.end) + " (both elements trimmed to them)";
}

std::vector<Mark> marksOf(const Toolpath& tp, std::size_t i, const geometry::Sampling& sampling,
                          std::optional<double>& maxDeviation) {
  std::vector<Mark> marks;
  const Move& m = tp.moves[i];
  const Segment& s = m.lower;
  add(marks, Mark::Kind::Segment, Mark::Role::Path, s);
  add(marks, Mark::Kind::Point, Mark::Role::Path, Segment::line(s.start, s.start), "start " + formatPoint(s.start));
  add(marks, Mark::Kind::Point, Mark::Role::Path, Segment::line(s.end, s.end), "end " + formatPoint(s.end));
  const bool offset = i < tp.offsetRole.size() && tp.offsetRole[i] != OffsetRole::None;
  if (offset) offsetConstruction(marks, tp, i);
  if (m.kind == MoveKind::Arc) {
    // The words build the programmed arc; the wire's keeps its centre (a corner arc has no words).
    const Segment& d = offset && tp.offsetRole[i] == OffsetRole::Element ? tp.programmed[i] : s;
    if (!offset || tp.offsetRole[i] != OffsetRole::Corner) {
      if (m.centreForm == CentreForm::Radius && tp.programmedRadius(i) != 0)
        radiusConstruction(marks, d, tp.programmedRadius(i));
      else if (m.centreForm != CentreForm::None)
        vectorConstruction(marks, tp, i, d);
    }
    const double k = sampling.mode == geometry::SamplingMode::Step ? sampling.value : 1.0;
    const geometry::SeedArcAngles seed = geometry::seedAngles(s, k);
    angleConstruction(marks, s, seed);
    marks[0].label = "sweep " + deg(std::abs(s.sweep)) + " deg " +
                     (s.sweep < 0 ? "clockwise (G02)" : "counter-clockwise (G03)") + ", radius " + mm(s.radius());
    maxDeviation = chordConstruction(marks, s, sampling, seed);
  } else {
    marks[0].label = std::string(m.kind == MoveKind::Rapid ? "rapid" : "line") + ", length " + mm(s.length()) + " mm";
  }
  if (const Toolpath::CornerMade* c = cornerOf(tp, i, false)) cornerConstruction(marks, *c, s);
  if (const Toolpath::CornerMade* c = cornerOf(tp, i, true)) {  // the block's corner word made the next move
    const Segment& corner = tp.moves[c->move].lower;
    add(marks, Mark::Kind::Segment, Mark::Role::Path, corner,
        std::string(c->chamfer ? "chamfer " : "corner R ") + mm(c->size));
    cornerConstruction(marks, *c, corner);
  }
  if (tp.isTaper() && i < tp.upper.size()) taperConstruction(marks, tp, i);
  return marks;
}

// ---- 2. words ----------------------------------------------------------------------------------------

std::string gMeaning(long code) {
  switch (code) {
    case 0: return "rapid move, not cut (modal: until another motion code)";
    case 1: return "straight cut (modal: until another motion code)";
    case 2: return "arc clockwise (modal)";
    case 3: return "arc counter-clockwise (modal)";
    case 4: return "dwell";
    case 17: return "plane XY";
    case 20: return "lengths in inches from here on";
    case 21: return "lengths in millimetres from here on";
    case 40: return "wire offset off";
    case 41: return "wire offset to the left of travel";
    case 42: return "wire offset to the right of travel";
    case 50: return "taper off";
    case 51: return "taper: the wire leans left of travel";
    case 52: return "taper: the wire leans right of travel";
    case 90: return "absolute coordinates from here on";
    case 91: return "incremental coordinates from here on";
    case 92: return "sets the position the wire is at: no motion";
    default: return "G" + std::to_string(code) + ": no effect on the path drawn (docs/interpreter.md)";
  }
}

std::string mMeaning(long code) {
  switch (code) {
    case 0: return "program stop: the operator may cut and thread the wire";
    case 1: return "optional stop";
    case 2:
    case 30: return "end of program";
    default: return "machine function M" + std::to_string(code) + ": no effect on the path";
  }
}

/// What a lower-side word of move i sets.
std::string lowerMeaning(const Word& w, const Toolpath& tp, std::size_t i) {
  const Move& m = tp.moves[i];
  // The words build the programmed segment; where the wire offset was applied, the wire's differs.
  const bool offset = i < tp.offsetRole.size() && tp.offsetRole[i] != OffsetRole::None;
  const Segment& s = offset ? tp.programmed[i] : m.lower;
  const bool incremental = (m.modes & kModeIncremental) != 0;
  if (w.corner) return cornerMeaning(tp, i);
  switch (w.letter) {
    case 'G': return gMeaning(std::lround(w.value));
    case 'M': return mMeaning(std::lround(w.value));
    case 'X':
    case 'Y': {
      const int axis = w.letter == 'X' ? 0 : 1;
      const Toolpath::CornerMade* corner = cornerOf(tp, i, true);
      const std::string end = corner
                                  ? mm(corner->sharp[axis]) + " mm, where the corner at the block's end trims it to " +
                                        mm(s.end[axis]) + " mm"
                                  : mm(s.end[axis]) + " mm";
      return std::string(incremental ? "the distance from the start along " : "the end point's ") + w.letter +
             (incremental ? "" : " (absolute)") + ": the end's " + static_cast<char>(std::tolower(w.letter)) + " is " +
             end;
    }
    case 'I':
    case 'J': {
      const int axis = w.letter == 'I' ? 0 : 1;
      const char* how = arcCentreMeaning(arcCentreOf(m.centreForm));
      return std::string("the arc's centre, ") + how + " in " + (axis == 0 ? "x" : "y") + ": the centre's " +
             (axis == 0 ? "x" : "y") + " is " + mm(s.centre[axis]) + " mm";
    }
    case 'C':  // a mill-turn face program (docs/polar.md)
      return "the C axis: under polar interpolation (G112) the face plane's second coordinate, else the "
             "table's angle; the face point's y is " +
             mm(s.end.y()) + " mm";
    case 'R':
      if (m.centreForm != CentreForm::Radius && (cornerOf(tp, i, false) || cornerOf(tp, i, true)))
        return cornerMeaning(tp, i);  // NCVC's bare R: the corner (profile corner_r = bare)
      return "the radius; " + std::string(w.value > 0 ? "positive: the arc of at most 180 degrees"
                                                      : "negative: the arc of more than 180 degrees");
    case 'F': return "the feed, " + mm(tp.feedOf(i)) + " mm/min (modal)";
    case 'N': return "a sequence number: a label, no effect on the path";
    case 'D':
    case 'H': return "the offset register: which wire offset value G41/G42 take";
    default: return "not used for the path";
  }
}

}  // namespace

const char* markRoleName(ConstructionMark::Role role) {
  using Role = ConstructionMark::Role;
  switch (role) {
    case Role::Path: return "path";
    case Role::Upper: return "upper";
    case Role::Chord: return "chord";
    case Role::Bisector: return "bisector";
    case Role::Centre: return "centre";
    case Role::Rejected: return "rejected";
    case Role::Vector: return "vector";
    case Role::Radius: return "radius";
    case Role::Angle: return "angle";
    case Role::Sample: return "sample";
    case Role::Deviation: return "deviation";
    case Role::Programmed: return "programmed";
    case Role::Offset: return "offset";
  }
  return "mark";
}

std::vector<WordMeaning> blockWords(const SourceFile& source, const Toolpath& tp, std::size_t i,
                                    const ParseOptions& parse) {
  const Move& m = tp.moves[i];
  const std::string text = blockTextOf(source, m);
  std::vector<WordMeaning> out;
  if (text.empty()) return out;
  if (tp.format == InputFormat::ThreeB) {
    const bool arc = m.kind == MoveKind::Arc;
    out.push_back({"B x B y", arc ? "the start relative to the centre, in whole micrometres, signs from Z's quadrant"
                                  : "the line's direction (its end relative to its start), signs from Z's quadrant"});
    out.push_back({"B J", "the count: micrometres travelled along the count axis G"});
    out.push_back({"G", "the count axis: GX counts x, GY counts y"});
    out.push_back({"Z", arc ? "SR clockwise, NR counter-clockwise, with the start's quadrant"
                            : "L1-L4: the quadrant (or axis) the line runs into"});
    return out;
  }
  const SourceFile block("block", text);
  Diagnostics ignored;
  const Program program = parseProgram(block, ignored, parse);
  if (program.blocks.empty()) return out;
  WordReader reader(program);
  const Block& b = program.blocks.front();
  const std::span<const Word> words = reader.words(b);
  for (std::size_t k = 0; k < words.size(); ++k) {
    const Word& w = words[k];
    WordMeaning meaning;
    meaning.word = text.substr(w.offset, w.length);
    if (k >= b.upperFrom && tp.isTaper())
      meaning.sets = std::string("the upper contour (") + dialectName(tp.dialect) +
                     "): " + formatPoint(tp.upper[i].end) + " at its end";
    else
      meaning.sets = lowerMeaning(w, tp, i);
    out.push_back(std::move(meaning));
  }
  return out;
}

// ---- 3. modes and pass ----------------------------------------------------------------------------------

std::vector<std::string> blockModes(const Toolpath& tp, std::size_t i) {
  const Move& m = tp.moves[i];
  std::vector<std::string> out;
  if (tp.format == InputFormat::ThreeB) {
    out.push_back("3B: each record is relative to where the last one ended, in whole micrometres");
  } else {
    out.push_back((m.modes & kModeIncremental) ? "incremental (G91): X Y are distances from the start"
                                               : "absolute (G90): X Y are the end point in the program's coordinates");
    out.push_back((m.modes & kModeInch) ? "inches (G20): every length is read times 25.4" : "millimetres (G21)");
    out.push_back("plane XY (G17): the only plane a wire machine cuts in");
    out.push_back(std::string("arc centres from I J: ") + arcCentreMeaning(tp.reading.arcCentre) +
                  " (machine profile " + tp.reading.machine + ")");
  }
  std::string offset = "no wire offset (G40): the path is the wire's centre";
  if (const OffsetSpan* span = offsetSpanOf(tp, i)) {
    offset = "wire offset " + sideName(span->side);
    if (span->value) offset += ", " + mm(*span->value) + " mm";
    if (!span->offsetRegister.empty()) offset += " (" + span->offsetRegister + ")";
    const bool applied = i < tp.offsetRole.size() && tp.offsetRole[i] != OffsetRole::None;
    offset += applied ? ": the path drawn is the wire's centre, beside the block's" : ": not applied (no value known)";
  }
  out.push_back(offset);
  if (!tp.isTaper())
    out.push_back("2-axis: the wire stands upright");
  else if (tp.dialect == Dialect::TaperAngle && i < tp.taperDegrees.size())
    out.push_back("taper angle " + formatFixed(tp.taperDegrees[i], 3) + " deg (dialect taper-angle)");
  else
    out.push_back(std::string("4-axis taper, dialect ") + dialectName(tp.dialect) +
                  ": the upper contour has its own words");
  out.push_back(tp.feedOf(i) > 0 ? "feed " + mm(tp.feedOf(i)) + " mm/min" : "no feed programmed");
  return out;
}

namespace {

std::string passOf(const Structure* structure, std::size_t i) {
  if (!structure || !structure->multiPass()) return {};
  for (std::size_t c = 0; c < structure->contours.size(); ++c) {
    const Contour& contour = structure->contours[c];
    for (std::size_t k = 0; k < contour.passes.size(); ++k) {
      const Pass& p = contour.passes[k];
      if (i < p.first || i >= p.end) continue;
      const char* part = i < p.alongFirst ? ", its lead-in" : i >= p.alongEnd ? ", its lead-out" : "";
      return passName(c, k) + ": " + passRole(p, k) + part;
    }
  }
  return {};
}

}  // namespace

Construction constructionOf(const SourceFile& source, const Toolpath& toolpath, const Structure* structure,
                            const geometry::Sampling& sampling, std::size_t move, const ParseOptions& parse) {
  Construction c;
  c.move = move;
  const Move& m = toolpath.moves[move];
  c.line = m.line;
  c.block = blockTextOf(source, m);
  c.marks = marksOf(toolpath, move, sampling, c.maxDeviation);
  c.words = blockWords(source, toolpath, move, parse);
  c.modes = blockModes(toolpath, move);
  c.pass = passOf(structure, move);
  if (!c.pass.empty())  // said beside the block's segment too
    c.marks.insert(c.marks.begin() + 1, ConstructionMark{ConstructionMark::Kind::Segment, ConstructionMark::Role::Path,
                                                         m.lower, false, c.pass});
  return c;
}

std::optional<std::size_t> moveOnLine(const Toolpath& toolpath, std::uint32_t line) {
  for (std::size_t i = 0; i < toolpath.moves.size(); ++i)
    if (toolpath.moves[i].line == line) return i;
  return std::nullopt;
}

}  // namespace kerf::converter
