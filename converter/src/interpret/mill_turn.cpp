// Mill-turn face programs in the interpreter's phases (mill_turn.h, docs/polar.md): the words a
// face program reads (phase 1), and in phase 4 polar interpolation on and off, the table homed,
// and the face point each move reaches — X/C cutting moves as the machine's spirals
// (geometry/polar.h), moves inside G12.1 in the polar frame.
#include "kerf/converter/interpret/mill_turn.h"

#include "interpreter_impl.h"
#include "kerf/converter/nc/number_format.h"
#include "kerf/geometry/polar.h"

#include <cmath>
#include <cstring>

namespace kerf::converter {

namespace {

bool isG(const Word& w, int whole, int tenth = 0) {
  return w.letter == 'G' && w.isNumber() && roundHalfAway(w.value * 10) == whole * 10 + tenth;
}

/// A code as written: G12.1, M30, T707.
std::string codeText(const Word& w) {
  const long tenths = std::lround(w.value * 10);
  return std::string(1, w.letter) + std::to_string(tenths / 10) +
         (tenths % 10 != 0 ? "." + std::to_string(std::labs(tenths % 10)) : "");
}

/// G codes a face program carries out, read by the standard phases: motion, dwell, polar
/// interpolation, units, distance mode, the reference points.
bool faceG(const Word& w) {
  for (const auto& [whole, tenth] : {std::pair{0, 0},
                                     {1, 0},
                                     {2, 0},
                                     {3, 0},
                                     {12, 1},
                                     {13, 1},
                                     {112, 0},
                                     {113, 0},
                                     {20, 0},
                                     {21, 0},
                                     {90, 0},
                                     {91, 0},
                                     {28, 0},
                                     {30, 0},
                                     {53, 0},
                                     {92, 0},
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
      c |= w.letter == 'C' && !w.corner;  // `,C` is a chamfer, not the table
      y |= w.letter == 'Y';
      home |= isG(w, 28) || isG(w, 30);
    }
    if (c && ((x && !y) || home)) return true;  // X/C moves, or the table homed (G28 C0.)
  }
  return false;
}

}  // namespace kerf::converter

namespace kerf::converter::interp {

namespace {

Vec2 rotate(const Vec2& p, double degrees) {
  const double a = degrees / geometry::kDegreesPerRadian, c = std::cos(a), s = std::sin(a);
  return {c * p.x() - s * p.y(), s * p.x() + c * p.y()};
}

}  // namespace

bool Interpreter::readFaceWord(const Word& w) {
  auto noteOnce = [&](const char* what) {
    const std::string code = codeText(w);
    if (std::find(face_.noted.begin(), face_.noted.end(), code) != face_.noted.end()) return;
    face_.noted.push_back(code);
    diags_.note(Code::MachineCode, src_, w.span(), code + ": " + what);
  };
  if (!w.isNumber()) return false;  // the standard reading reports what is wrong with it
  switch (w.letter) {
    case 'G':
      if (faceG(w)) return false;
      if (isG(w, 41) || isG(w, 42))
        diags_.warning(Code::CodeNotModelled, src_, w.span(),
                       "cutter compensation in a mill-turn program is not applied: the path drawn is the "
                       "programmed one, not the tool centre's",
                       "the tool's offset is known only at the machine");
      else if (!harmlessG(w))
        diags_.warning(Code::CodeNotModelled, src_, w.span(),
                       codeText(w) + " is not read in a mill-turn face program: the path may differ",
                       "Kerf reads G0-G3, G4, G12.1/G13.1 (G112/G113), G20/G21, G90/G91, G92 and G28/G30/G53 here "
                       "(docs/polar.md)");
      return true;
    case 'M':
      if (w.value == 2 || w.value == 30 || w.value == 98 || w.value == 99) return false;
      noteOnce("a machine function (spindle, coolant, C-axis mode): no motion of the face point");
      return true;
    case 'T': noteOnce("tool selection"); return true;
    case 'S': noteOnce("spindle speed"); return true;
    default:
      // The face plane's words, the feed, and the dwell and call parameters; Z (depth), W, U and
      // the rest do not move the face point.
      return std::strchr("XYCIJRFPL", w.letter) == nullptr;
  }
}

void Interpreter::executeFaceBlock(const BlockWords& bw, const Block& block, const BlockPlan& plan) {
  if (plan.dwell) return;  // G4 X2.: X (or P) is the time, not a position
  if (plan.homing) {       // G28 C0.: the table at its reference; other axes where the machine knows
    if (bw.has('C')) {
      face_.c = 0.0;
      face_.cKnown = true;
      position_ = Vec2(face_.radius, face_.y);
    }
    return;
  }
  if (plan.setPosition) {  // G92 X C: the face point is there now (X a diameter, C degrees)
    if (face_.polar) {
      diags_.warning(Code::CodeNotModelled, src_, block.span(),
                     "G92 inside polar coordinate interpolation is not read: the path may differ");
      return;
    }
    if (const Word* X = bw['X']) face_.radius = length(*X) / 2;
    if (const Word* Y = bw['Y']) face_.y = length(*Y);
    if (const Word* C = bw['C']) {
      face_.c = C->value;
      face_.cKnown = true;
    }
    position_ = rotate(Vec2(face_.radius, face_.y), face_.c);
    return;
  }
  if (bw.group(ModalGroup::Polar)) {
    const bool on = bw.code(ModalGroup::Polar) == GCode::PolarOn;
    if (on && !face_.polar) startPolar(block);
    if (!on && face_.polar) endPolar();
  }
  if (!bw.has('X') && !bw.has('Y') && !bw.has('C')) return;
  if (motion_ == Motion::None) {
    diags_.error(Code::NoMotionMode, src_, block.span(), "a move with no motion mode (G00, G01, G02 or G03) in force",
                 "start the block (or an earlier one) with G00, G01, G02 or G03");
    return;
  }
  faceMove(bw, block);
}

void Interpreter::startPolar(const Block& block) {
  const MillTurnOptions& o = *options_.millTurn;
  face_.polar = true;
  const double at = face_.cKnown ? face_.c : 0.0;
  face_.frame = o.polarFrameTable ? 0.0 : at;
  face_.inPolar = rotate(position_, -face_.frame);
  if (std::abs(std::remainder(at, 360.0)) <= 1e-9) return;
  if (o.polarFrameTable)
    diags_.note(Code::PolarAxisValue, src_, block.span(),
                "polar interpolation starts with the table at C " + formatFixed(at, 3) +
                    ": read in the table's frame at C 0 (--polar-frame table), as seed 002's post means",
                "on a control that turns the frame with C (Fanuc 15i-MA), --polar-frame tool");
  else
    diags_.note(Code::PolarAxisValue, src_, block.span(),
                "polar interpolation starts with the table at C " + formatFixed(at, 3) +
                    ": its frame's x axis passes through the tool there, so the section is drawn turned by that angle",
                "FORMATS §5 and the Fanuc 15i-MA manual: the tool's position at G12.1 is angle 0; for a post that "
                "means the table's frame at C 0 (seed 002's O66), --polar-frame table");
}

void Interpreter::endPolar() {
  face_.polar = false;
  face_.radius = position_.norm();
  if (face_.radius > 0)
    face_.c = geometry::unwrapDegrees(std::atan2(position_.y(), position_.x()) * geometry::kDegreesPerRadian, face_.c);
  face_.y = 0.0;
  face_.cKnown = true;
}

Vec2 Interpreter::faceTarget(const BlockWords& bw, double& newC, double& startRadius) {
  const MillTurnOptions& o = *options_.millTurn;
  const Word *X = bw['X'], *Y = bw['Y'], *C = bw['C'];
  newC = face_.c;
  startRadius = face_.radius;
  if (face_.polar) {
    Vec2 p = face_.inPolar;
    const double x = X ? length(*X) * (o.polarXDiameter ? 0.5 : 1.0) : 0.0;
    const double v = C ? length(*C) * (o.polarCDiameter ? 2.0 : 1.0) : 0.0;
    if (incremental_) {
      p += Vec2(x, v);
    } else {
      if (X) p.x() = x;
      if (C) p.y() = v;
    }
    if (Y)
      diags_.warning(Code::WordIgnored, src_, Y->span(),
                     "Y inside polar coordinate interpolation: the plane is X and C; Y is not read");
    face_.inPolar = p;
    return rotate(p, face_.frame);
  }
  double r = face_.radius, y = face_.y;
  if (X) r = incremental_ ? face_.radius + length(*X) / 2 : length(*X) / 2;
  if (Y) y = incremental_ ? face_.y + length(*Y) : length(*Y);
  if (C) {
    newC = incremental_ ? face_.c + C->value : C->value;  // degrees, not a length
    // Cutting, the part turns under the tool: an error. A rapid only takes the long way round.
    if (face_.cKnown && std::abs(newC - face_.c) > 180.0)
      diags_.report({motion_ == Motion::Rapid ? Severity::Warning : Severity::Error, Code::RotaryJump, src_, C->span(),
                     "C" + formatFixed(C->value, 3) + " turns the table " + formatFixed(std::abs(newC - face_.c), 3) +
                         " degrees from C" + formatFixed(face_.c, 3) + ", more than the shortest way (" +
                         formatFixed(std::abs(std::remainder(newC - face_.c, 360.0)), 3) +
                         " degrees): the part turns under the tool",
                     "write C continuous: the value congruent mod 360 nearest the previous C (seed 002: N850 "
                     "X28.006 C-358.834 damaged the part)",
                     std::nullopt, std::nullopt});
    face_.cKnown = true;
  }
  face_.radius = r;
  face_.y = y;
  return rotate(Vec2(r, y), newC);
}

void Interpreter::faceMove(const BlockWords& bw, const Block& block) {
  double newC = 0.0, startRadius = 0.0;
  const Vec2 start = position_;
  const Vec2 target = faceTarget(bw, newC, startRadius);
  const bool rotary = !face_.polar && bw.has('C') && std::abs(newC - face_.c) > 1e-12;
  const double startC = face_.c;
  face_.c = newC;
  Move move;
  move.line = lineOf(block);
  move.span = block.span();
  move.setCallDepth(stack_.size());
  moveCentreWords_ = Vec2::Zero();
  const bool arc = motion_ == Motion::Clockwise || motion_ == Motion::CounterClockwise;
  if (arc && rotary) {
    diags_.error(Code::WordNotInDialect, src_, bw['C']->span(), "an arc that also turns the table (C) is not read");
    position_ = target;
    return;
  }
  Segment lower;
  const double centreTurn = face_.polar ? face_.frame : 0.0;  // I J are in the polar frame inside G12.1
  if (!buildSegment(bw, motion_, start, target, Vec2::Zero(), centreTurn, "", block, motionWord_.get(), lower, &move)) {
    position_ = target;
    return;
  }
  move.kind = motion_ == Motion::Rapid ? MoveKind::Rapid : arc ? MoveKind::Arc : MoveKind::Line;
  move.lower = lower;
  if (rotary && move.kind == MoveKind::Line && std::abs(face_.y) < 1e-12 &&
      pushSpiral(move, {startRadius, startC}, {face_.radius, newC}, bw, target))
    return;
  // A table turn at the centre, or a Z move, leaves the face point where it is: no move.
  if (!arc && lower.length() < 1e-12) {
    position_ = target;
    return;
  }
  push(std::move(move), lower);
  position_ = target;
}

bool Interpreter::pushSpiral(const Move& move, const geometry::PolarPoint& from, const geometry::PolarPoint& to,
                             const BlockWords& bw, const Vec2& target) {
  // The machine moves X and C together: a spiral in the face plane, drawn as arcs within the
  // spiral tolerance (geometry/polar.h).
  const MillTurnOptions& o = *options_.millTurn;
  geometry::SpiralPieces spiral = geometry::spiralAsArcs(from, to, o.spiralTolerance, o.spiralBudget);
  if (spiral.overBudget) {
    diags_.error(Code::RotaryJump, src_, bw['C']->span(),
                 "this X/C move turns the table " + formatFixed(std::abs(to.c - from.c), 3) +
                     " degrees: drawing its spiral would take more than " + std::to_string(o.spiralBudget) +
                     " pieces; drawn as its chord",
                 "write C continuous: the value congruent mod 360 nearest the previous C");
    return false;
  }
  if (spiral.pieces.empty()) return false;
  face_.worstSpiral = std::max(face_.worstSpiral, spiral.maxDeviation);
  spiral.pieces.back().end = target;
  for (const Segment& piece : spiral.pieces) {
    Move part = move;
    part.kind = piece.isArc() ? MoveKind::Arc : MoveKind::Line;
    part.lower = piece;
    moveCentreWords_ = Vec2::Zero();
    push(std::move(part), piece);
    position_ = piece.end;
  }
  face_.spiralPieces += spiral.pieces.size();
  position_ = target;
  return true;
}

void Interpreter::finishFace() {
  if (face_.polar)
    diags_.warning(Code::PolarNotSupported, src_, SourceSpan::wholeFile(),
                   "the program ends inside polar coordinate interpolation (no G13.1 or G113)");
  if (face_.spiralPieces > 0)
    diags_.note(Code::PolarAxisValue, src_, SourceSpan::wholeFile(),
                "X/C cutting moves are drawn as the machine moves them, spirals (X and C linear together), in " +
                    std::to_string(face_.spiralPieces) + (face_.spiralPieces == 1 ? " piece" : " pieces") +
                    " (arcs, or lines where straight) within " + formatFixed(face_.worstSpiral, 6) + " mm");
}

}  // namespace kerf::converter::interp
