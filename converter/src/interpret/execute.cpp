// Phase 4 (execute), the modal parts: words that mean nothing here, G92, the taper angle,
// lengths in the program's units.
#include "interpreter_impl.h"

#include <cmath>

namespace kerf::converter::interp {

void Interpreter::warnEachIgnoredWord(const BlockWords& bw, const BlockPlan& plan) {
  // Q is the second parameter of an M code (M100 P Q); Z may set the position with G92.
  const bool mCode = bw.mCount > 0 || bw.machineCount > 0;
  for (char c : {'A', 'K', 'Q', 'Z', 'T', 'W'}) {
    if (!bw.has(c) || (c == 'Z' && plan.setPosition) || (c == 'Q' && mCode)) continue;
    if ((c == 'A' || c == 'T') && dialect_ == Dialect::TaperAngle) continue;
    if (c == 'K' && cornerUpperRadius(bw)) continue;  // the upper plane's corner radius (corner.cpp)
    if (warnedLetters_.insert(c).second)
      diags_.warning(Code::WordIgnored, src_, bw[c]->span(),
                     std::string("word '") + c + "' has no meaning in a " + dialectName(dialect_) +
                         " wire program and is ignored");
  }
  if (const Word* b = bw['B']; b && warnedLetters_.insert('B').second)  // the parser lets B stand only after G28/G30
    diags_.note(Code::RotaryAxisNotModelled, src_, b->span(),
                "'" + std::string(src_->text().substr(b->offset, b->length)) +
                    "': the rotary axis B is homed here; Kerf does not model it (the wire's path is read without it)");
  if (plan.dwell && !plan.setPosition && (bw.has('Y') || bw.has('I') || bw.has('J') || bw.has('R'))) {
    const Word* w = bw.has('Y') ? bw['Y'] : bw.has('I') ? bw['I'] : bw.has('J') ? bw['J'] : bw['R'];
    diags_.warning(Code::DwellWordsIgnored, src_, w->span(), "coordinates in a G04 block are ignored");
  }
}

void Interpreter::setHeight(std::optional<Height>& slot, double value, const char* what, std::uint32_t line) {
  slot = Height{value, std::string(what) + " on line " + std::to_string(line)};
}

/// G92: the current position in program coordinates; in 4-axis dialects U V too, and NCVC's
/// plane heights (I thickness, J program plane). A bare G92 makes the current position the origin
/// where the machine's profile says so (Robofil).
bool Interpreter::executeSetPosition(const BlockWords& bw, const BlockWords& ubw, const Block& block) {
  const bool upperWords = ubw.has('U') || ubw.has('V') || bw.has('U') || bw.has('V');
  const bool heights = bw.has('I') || bw.has('J');
  const bool bare = !bw.has('X') && !bw.has('Y') && !upperWords && !bw.has('Z') && !heights;
  if (bare && !machine_.bareSetPositionIsOrigin) {
    diags_.error(Code::SetPositionWithoutAxis, src_, bw.group(ModalGroup::NonModal)->span(),
                 "G92 needs the coordinates of the current position (X, Y)",
                 "on Charmilles Robofil controls a bare G92 makes the current position the origin: read such a "
                 "program with --machine robofil");
    return false;
  }
  if (const Word* i = bw['I']) setHeight(fileThickness_, length(*i), "G92 I", lineOf(block));
  if (const Word* j = bw['J']) setHeight(fileProgramZ_, length(*j), "G92 J", lineOf(block));
  const bool wasUnknown = unknown_.active;
  if (wasUnknown && (bare || (bw.has('X') && bw.has('Y')))) {
    positionKnownAgain(block);
    shift_ = Vec2::Zero();
    upperShift_ = Vec2::Zero();
  }
  Vec2 programmed = bare ? Vec2(0, 0) : position_ + shift_;
  if (const Word* x = bw['X']) programmed.x() = length(*x);
  if (const Word* y = bw['Y']) programmed.y() = length(*y);
  const bool first = toolpath_.moves.empty() || (wasUnknown && !unknown_.active);
  if (first) {
    position_ = programmed;  // before any motion G92 places the start: no shift needed
    shift_ = Vec2::Zero();
    if (toolpath_.moves.empty()) toolpath_.start = position_;
  } else {
    shift_ = programmed - position_;
  }
  const Word* u = ubw.has('U') ? ubw['U'] : bw['U'];
  const Word* v = ubw.has('V') ? ubw['V'] : bw['V'];
  if (dialect_ == Dialect::XyuvAbs || dialect_ == Dialect::XyuvLinuxCnc) {
    Vec2 upperProgrammed = bare ? Vec2(0, 0) : upperPosition_ + upperShift_;
    if (u) upperProgrammed.x() = length(*u);
    if (v) upperProgrammed.y() = length(*v);
    if (first) {
      upperPosition_ = (u || v || bare) ? upperProgrammed : position_;
      upperShift_ = Vec2::Zero();
    } else {
      upperShift_ = upperProgrammed - upperPosition_;
    }
  } else if (dialect_ == Dialect::XyuvRel) {
    if (u) uvOffset_.x() = length(*u);
    if (v) uvOffset_.y() = length(*v);
  } else if (first) {
    upperPosition_ = position_;
  }
  return true;
}

/// G50/G51/G52 and the angle words. False (reported) for an angle NCVC refuses.
bool Interpreter::executeTaperAngle(const BlockWords& bw) {
  const Word* angle = bw.has('A') ? bw['A'] : bw['T'];
  if (bw.has('A') && bw.has('T')) {
    diags_.error(Code::TaperAngleTwice, src_, bw['T']->span(), "give the taper angle once, as A or as T");
    return false;
  }
  if (angle && angle->isNumber()) {
    if (std::abs(angle->value) > 45.0) {
      diags_.error(Code::TaperAngleTooLarge, src_, angle->span(),
                   "taper angle " + formatFixed(angle->value, 3) +
                       " degrees is beyond 45 degrees, the limit NC controls accept");
      return false;
    }
    taperDegrees_ = angle->value;
  }
  if (bw.group(ModalGroup::Taper)) {
    const GCode code = bw.code(ModalGroup::Taper);
    if (code == GCode::TaperCancel) {
      taperPhase_ = taperPhase_ == TaperPhase::Starting ? TaperPhase::Off
                    : taperPhase_ == TaperPhase::On     ? TaperPhase::Ending
                                                        : taperPhase_;
    } else {
      taperSide_ = code == GCode::TaperLeft ? 1 : -1;
      if (taperPhase_ == TaperPhase::Off || taperPhase_ == TaperPhase::Ending) taperPhase_ = TaperPhase::Starting;
    }
  }
  return true;
}

}  // namespace kerf::converter::interp
