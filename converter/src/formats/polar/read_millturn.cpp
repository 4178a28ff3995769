// Mill-turn face programs (docs/polar.md, seed 002, FORMATS §5): polar coordinate interpolation
// (G12.1/G13.1 = G112/G113) and explicit X/C moves, read into the Cartesian face plane.
//
// The face plane is the table's frame at C = 0: the tool at radius r and table angle C is
// r (cos C, sin C) [sourced: seed 002, O31's X64.404 C-115.769 is O30's X-28. Y-29.]. Outside polar
// mode X is a diameter, Y a linear axis, C the table angle in degrees. Inside, the program is
// Cartesian in a frame whose x axis passes through the tool when G12.1 is commanded (FORMATS §5:
// C is 0 there): X is a radius or a diameter (--polar-x, the profile's polar_x), C the virtual
// linear axis in mm (a diameter on Star machines: the profile's polar_c).

#include "kerf/converter/formats/polar/read_millturn.h"
#include "kerf/converter/nc/number_format.h"
#include "kerf/geometry/arc.h"
#include "kerf/geometry/polar.h"

#include <algorithm>
#include <cmath>

namespace kerf::converter {

namespace {

using geometry::Segment;
using geometry::Vec2;

Vec2 rotate(const Vec2& p, double degrees) {
  const double a = degrees / geometry::kDegreesPerRadian, c = std::cos(a), s = std::sin(a);
  return {c * p.x() - s * p.y(), s * p.x() + c * p.y()};
}

bool isG(const Word& w, int whole, int tenth = 0) {
  return w.letter == 'G' && w.isNumber() && roundHalfAway(w.value * 10) == whole * 10 + tenth;
}

/// A code as written: G12.1, M30, T707.
std::string codeText(const Word& w) {
  const long tenths = std::lround(w.value * 10);
  return std::string(1, w.letter) + std::to_string(tenths / 10) +
         (tenths % 10 != 0 ? "." + std::to_string(std::labs(tenths % 10)) : "");
}

bool knownG(const Word& w) {
  for (const auto& [whole, tenth] : {std::pair{0, 0},
                                     {1, 0},
                                     {2, 0},
                                     {3, 0},
                                     {12, 1},
                                     {13, 1},
                                     {112, 0},
                                     {113, 0},
                                     {90, 0},
                                     {91, 0},
                                     {28, 0},
                                     {30, 0},
                                     {53, 0},
                                     {4, 0}})
    if (isG(w, whole, tenth)) return true;
  return false;
}

/// G codes that do not move the face point: planes, units (mm assumed), work offsets, feed and
/// spindle modes, cancels.
bool harmlessG(const Word& w) {
  for (const auto& [whole, tenth] : {std::pair{17, 0},
                                     {18, 0},
                                     {19, 0},
                                     {21, 0},
                                     {40, 0},
                                     {54, 0},
                                     {55, 0},
                                     {56, 0},
                                     {57, 0},
                                     {58, 0},
                                     {59, 0},
                                     {80, 0},
                                     {94, 0},
                                     {95, 0},
                                     {96, 0},
                                     {97, 0},
                                     {98, 0},
                                     {99, 0},
                                     {9, 0}})
    if (isG(w, whole, tenth)) return true;
  return false;
}

}  // namespace

bool isMillTurnProgram(const Program& program) {
  // The ranges hold G12.1 and G112 with room to spare: most G words are out after two comparisons.
  for (const std::uint32_t k : program.notPlain) {  // a plain block's G words are G00-G03
    const Block& b = program.blocks[k];
    for (const Word& w : program.wordsOf(b))
      if (w.letter == 'G' && ((w.value >= 12 && w.value < 12.2) || (w.value >= 111.9 && w.value < 112.1)) &&
          (isG(w, 12, 1) || isG(w, 112)))
        return true;
  }
  return false;
}

bool hasRotaryMoves(const Program& program) {
  for (const std::uint32_t k : program.notPlain) {  // a plain block has no C word
    const Block& b = program.blocks[k];
    bool x = false, c = false, y = false, home = false;
    for (const Word& w : program.wordsOf(b)) {
      x |= w.letter == 'X';
      c |= w.letter == 'C';
      y |= w.letter == 'Y';
      home |= isG(w, 28) || isG(w, 30);
    }
    if (c && ((x && !y) || home)) return true;  // X/C moves, or the table homed (G28 C0.)
  }
  return false;
}

Toolpath readMillTurn(const Program& program, const MillTurnOptions& options, Diagnostics& diags) {
  const SourceFile* src = program.source;
  Toolpath path;
  path.blocks = program.blocks.size();
  path.reading.machine = options.machine;
  bool polar = false;
  bool incremental = false;
  int motion = -1;  // 0 1 2 3
  double feed = 0.0;
  // Outside polar mode: the axes as the machine holds them.
  double radius = 0.0, y = 0.0, c = 0.0;  // mm, mm, degrees
  double startRadius = 0.0;               // the move's start radius (a signed X / 2)
  std::size_t spirals = 0;                // X/C moves' pieces
  bool cKnown = false;
  // Inside: the polar frame's turn and the tool in it.
  double frame = 0.0;
  Vec2 inPolar(0, 0);
  Vec2 position(0, 0);
  bool first = true;
  double worstSpiral = 0.0;
  const double polarXScale = options.polarXDiameter ? 0.5 : 1.0;
  const double polarCScale = options.polarCDiameter ? 2.0 : 1.0;

  // T, S and M words do not move the face point: said once per code, with the first line.
  std::vector<std::string> unreadSeen;
  auto unread = [&](const Word& w, const char* what) {
    const std::string code = codeText(w);
    if (std::find(unreadSeen.begin(), unreadSeen.end(), code) != unreadSeen.end()) return;
    unreadSeen.push_back(code);
    diags.note(Code::MachineCode, src, w.span(), code + ": " + what);
  };
  bool ends = false;
  for (std::size_t bi = 0; bi < program.blocks.size() && !ends; ++bi) {  // M02/M30/M99 end it
    const Block& b = program.blocks[bi];
    if (b.hasError || b.kind != BlockKind::Words) continue;
    const Word *X = nullptr, *Y = nullptr, *C = nullptr, *I = nullptr, *J = nullptr, *R = nullptr;
    bool homing = false, polarOn = false, polarOff = false, dwell = false;
    for (const Word& w : program.wordsOf(b)) {
      if (!w.isNumber()) continue;
      switch (w.letter) {
        case 'G':
          if (isG(w, 0) || isG(w, 1) || isG(w, 2) || isG(w, 3)) motion = static_cast<int>(std::lround(w.value));
          if (isG(w, 12, 1) || isG(w, 112)) polarOn = true;
          if (isG(w, 13, 1) || isG(w, 113)) polarOff = true;
          if (isG(w, 90)) incremental = false;
          if (isG(w, 91)) incremental = true;
          if (isG(w, 28) || isG(w, 30) || isG(w, 53)) homing = true;
          if (isG(w, 4)) dwell = true;
          break;
        case 'X': X = &w; break;
        case 'Y': Y = &w; break;
        case 'C': C = &w; break;
        case 'I': I = &w; break;
        case 'J': J = &w; break;
        case 'R': R = &w; break;
        case 'F': feed = w.value; break;
        case 'M':
          if (w.value == 2 || w.value == 30 || w.value == 99)
            ends = true;
          else
            unread(w, "a machine function (spindle, coolant, C-axis mode): no motion of the face point");
          break;
        case 'T': unread(w, "tool selection"); break;
        case 'S': unread(w, "spindle speed"); break;
        default: break;  // N Z W ...: not the face plane
      }
      if (w.letter == 'G' && !knownG(w)) {
        if (isG(w, 41) || isG(w, 42))
          diags.warning(Code::CodeNotModelled, src, w.span(),
                        "cutter compensation in a mill-turn program is not applied: the path drawn is the "
                        "programmed one, not the tool centre's",
                        "the tool's offset is known only at the machine");
        else if (!harmlessG(w))
          diags.warning(Code::CodeNotModelled, src, w.span(),
                        codeText(w) + " is not read in a mill-turn face program: the path may differ",
                        "Kerf reads G0-G3, G12.1/G13.1 (G112/G113), G90/G91 and G28/G30 here (docs/polar.md)");
      }
    }
    if (dwell) continue;  // G4 X2.: X (or P, U) is the dwell time, not a position
    if (homing) {         // G28 C0.: the table at its reference; other axes to where the machine knows
      if (C) {
        c = 0.0;
        cKnown = true;
        position = rotate(Vec2(radius, y), c);
      }
      continue;
    }
    if (polarOn && !polar) {
      polar = true;
      const double at = cKnown ? c : 0.0;
      frame = options.polarFrameTable ? 0.0 : at;
      inPolar = rotate(position, -frame);
      if (std::abs(std::remainder(at, 360.0)) > 1e-9) {
        if (options.polarFrameTable)
          diags.note(Code::PolarAxisValue, src, b.span(),
                     "polar interpolation starts with the table at C " + formatFixed(at, 3) +
                         ": read in the table's frame at C 0 (--polar-frame table), as seed 002's post means",
                     "on a control that turns the frame with C (Fanuc 15i-MA), --polar-frame tool");
        else
          diags.note(Code::PolarAxisValue, src, b.span(),
                     "polar interpolation starts with the table at C " + formatFixed(at, 3) +
                         ": its frame's x axis passes through the tool there, so the section is drawn turned by "
                         "that angle",
                     "FORMATS §5 and the Fanuc 15i-MA manual: the tool's position at G12.1 is angle 0; for a post "
                     "that means the table's frame at C 0 (seed 002's O66), --polar-frame table");
      }
    }
    if (polarOff && polar) {
      polar = false;
      radius = position.norm();
      if (radius > 0)
        c = geometry::unwrapDegrees(std::atan2(position.y(), position.x()) * geometry::kDegreesPerRadian, c);
      y = 0.0;
      cKnown = true;
    }
    if (!X && !Y && !C) continue;
    if (motion < 0) {
      diags.error(Code::NoMotionMode, src, b.span(), "a move with no motion mode (G00, G01, G02 or G03) in force");
      continue;
    }
    Vec2 target;
    double newC = c;
    if (polar) {
      Vec2 p = inPolar;
      const double x = X ? X->value * polarXScale : 0.0, v = C ? C->value * polarCScale : 0.0;
      if (incremental) {
        p += Vec2(x, v);
      } else {
        if (X) p.x() = x;
        if (C) p.y() = v;
      }
      if (Y)
        diags.warning(Code::WordIgnored, src, Y->span(),
                      "Y inside polar coordinate interpolation: the plane is X and C; Y is not read");
      inPolar = p;
      target = rotate(p, frame);
    } else {
      double r = radius, yy = y;
      if (X) r = incremental ? radius + X->value / 2 : X->value / 2;
      if (Y) yy = incremental ? y + Y->value : Y->value;
      if (C) {
        newC = incremental ? c + C->value : C->value;
        // Cutting, the part turns under the tool: an error. A rapid only takes the long way round.
        if (cKnown && std::abs(newC - c) > 180.0)
          diags.report({motion == 0 ? Severity::Warning : Severity::Error, Code::RotaryJump, src, C->span(),
                        "C" + formatFixed(C->value, 3) + " turns the table " + formatFixed(std::abs(newC - c), 3) +
                            " degrees from C" + formatFixed(c, 3) + ", more than the shortest way (" +
                            formatFixed(std::abs(std::remainder(newC - c, 360.0)), 3) +
                            " degrees): the part turns under the tool",
                        "write C continuous: the value congruent mod 360 nearest the previous C (seed 002: N850 "
                        "X28.006 C-358.834 damaged the part)",
                        std::nullopt, std::nullopt});
        cKnown = true;
      }
      target = rotate(Vec2(r, yy), newC);
      startRadius = radius;
      radius = r;
      y = yy;
    }
    Move m;
    m.line = b.line;
    m.span = b.span();
    m.feedIndex = path.feedIndexFor(feed);
    Vec2 centreWords(0, 0);  // R as written, for an arc
    const bool rotary = !polar && C && std::abs(newC - c) > 1e-12;
    if (motion == 2 || motion == 3) {
      const auto dir = motion == 2 ? geometry::ArcDirection::Clockwise : geometry::ArcDirection::CounterClockwise;
      if (rotary) {
        diags.error(Code::WordNotInDialect, src, C->span(), "an arc that also turns the table (C) is not read");
        c = newC;
        position = target;
        continue;
      }
      geometry::ArcBuild build;
      if (R) {
        build = geometry::arcFromRadius(position, target, R->value, dir);
      } else if (I || J) {
        const Vec2 ij(I ? I->value : 0.0, J ? J->value : 0.0);
        build = geometry::arcFromCentre(position, target, position + rotate(ij, polar ? frame : 0.0), dir);
      } else {
        diags.error(Code::ArcWithoutCentre, src, b.span(), "an arc with neither R nor I J");
        position = target;
        continue;
      }
      if (build.status != geometry::ArcStatus::Ok) {
        using geometry::ArcStatus;
        const Code code = build.status == ArcStatus::ZeroRadius             ? Code::ZeroRadius
                          : build.status == ArcStatus::RadiusTooSmall       ? Code::RadiusTooSmall
                          : build.status == ArcStatus::FullCircleWithRadius ? Code::FullCircleWithRadius
                                                                            : Code::ArcEndOffCircle;
        const char* why = build.status == ArcStatus::ZeroRadius       ? "the arc's radius is 0"
                          : build.status == ArcStatus::RadiusTooSmall ? "R is shorter than half the chord"
                          : build.status == ArcStatus::FullCircleWithRadius
                              ? "a full circle cannot be given by R (its centre is not determined): use I J"
                              : "the end is not on the circle through the start about the centre I J gives";
        diags.error(code, src, R ? R->span() : b.span(), std::string("this arc cannot be built: ") + why);
        position = target;
        continue;
      }
      m.kind = MoveKind::Arc;
      m.lower = build.arc;
      m.centreForm = R ? CentreForm::Radius : CentreForm::Incremental;
      centreWords = Vec2(R ? R->value : 0.0, 0.0);
    } else {
      m.kind = motion == 0 ? MoveKind::Rapid : MoveKind::Line;
      m.lower = Segment::line(position, target);
      if (rotary && m.kind == MoveKind::Line && std::abs(y) < 1e-12) {
        // The machine moves X and C together: a spiral in the face plane, drawn as arcs within
        // options.spiralTolerance (geometry/polar.h).
        const geometry::PolarPoint a{startRadius, c}, e{radius, newC};
        geometry::SpiralPieces spiral = geometry::spiralAsArcs(a, e, options.spiralTolerance, options.spiralBudget);
        if (spiral.overBudget) {
          diags.error(Code::RotaryJump, src, C->span(),
                      "this X/C move turns the table " + formatFixed(std::abs(newC - c), 3) +
                          " degrees: drawing its spiral would take more than " + std::to_string(options.spiralBudget) +
                          " pieces; drawn as its chord",
                      "write C continuous: the value congruent mod 360 nearest the previous C");
        } else if (!spiral.pieces.empty()) {
          worstSpiral = std::max(worstSpiral, spiral.maxDeviation);
          spiral.pieces.back().end = target;
          if (first) {
            path.start = position;
            first = false;
          }
          for (const Segment& piece : spiral.pieces) {
            Move part = m;
            part.kind = piece.isArc() ? MoveKind::Arc : MoveKind::Line;
            part.lower = piece;
            path.moves.push_back(std::move(part));
            path.centreWords.push_back(Vec2::Zero());
          }
          spirals += spiral.pieces.size();
          c = newC;
          position = target;
          continue;
        }
      }
    }
    c = newC;
    if (first) {
      path.start = position;
      first = false;
    }
    position = target;
    if ((m.lower.end - m.lower.start).norm() < 1e-12 && m.kind != MoveKind::Arc) continue;
    path.moves.push_back(std::move(m));
    path.centreWords.push_back(centreWords);
  }
  path.endedProperly = ends;
  if (!ends && !diags.hasErrors() && !path.moves.empty())
    diags.warning(Code::MissingProgramEnd, src, program.blocks.back().span(), "program ends without M02 or M30");
  if (polar)
    diags.warning(Code::PolarNotSupported, src, SourceSpan::wholeFile(),
                  "the program ends inside polar coordinate interpolation (no G13.1 or G113)");
  if (spirals > 0)
    diags.note(Code::PolarAxisValue, src, SourceSpan::wholeFile(),
               "X/C cutting moves are drawn as the machine moves them, spirals (X and C linear together), in " +
                   std::to_string(spirals) + (spirals == 1 ? " piece" : " pieces") +
                   " (arcs, or lines where straight) within " + formatFixed(worstSpiral, 6) + " mm");
  return path;
}

}  // namespace kerf::converter
