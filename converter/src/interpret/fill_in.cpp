// Phase 2 (fill in): what the block does once what it leaves out is taken from the modal state.
// Nothing changes here; execute applies the plan in order.
#include "interpreter_impl.h"

namespace kerf::converter::interp {
namespace {

bool isValueUnknown(const Word* w) { return w && (w->kind == WordValue::Register || w->kind == WordValue::Macro); }

}  // namespace

BlockPlan Interpreter::fillIn(const Block& block, const BlockWords& bw, const BlockWords& ubw) const {
  BlockPlan p;
  if (const Word* mw = bw.group(ModalGroup::Motion)) {
    p.motion = motionOf(bw.code(ModalGroup::Motion));
    p.motionWord = mw;
  } else {
    p.motion = motion_;
    p.motionWord = motionWord_.get();
  }
  p.incremental = bw.group(ModalGroup::Distance) ? bw.code(ModalGroup::Distance) == GCode::Incremental : incremental_;
  if (bw.group(ModalGroup::Units)) {
    const GCode u = bw.code(ModalGroup::Units);
    p.inch = u == GCode::Inch || u == GCode::InchOld;
  } else {
    p.inch = inch_;
  }
  // G04, G28, G30, G53 and G92 are the non-modal group's codes: a block holds one at most, and most
  // blocks none.
  if (bw.group(ModalGroup::NonModal)) {
    const GCode c = bw.code(ModalGroup::NonModal);
    p.setPosition = c == GCode::SetPosition;
    p.dwell = c == GCode::Dwell;
    // G53 alone moves nothing (a machine-coordinate move needs its axis words).
    const bool axisWords = bw.hasAny(letterBits("XYUV")) || ubw.hasAny(letterBits("UV"));
    p.homing =
        c == GCode::ReferenceReturn || c == GCode::SecondReference || (c == GCode::MachineCoordinates && axisWords);
  }
  p.lowerWords = bw.hasAny(letterBits("XYIJR")) || (options_.millTurn && bw.has('C'));
  p.upperWords = bw.hasAny(letterBits("UV"));
  if (block.upperFrom < block.wordCount) p.upperWords |= ubw.hasAny(letterBits("UVXYIJRKL"));
  if (block.unusualValues)
    for (const BlockWords* side : {&bw, &ubw})
      for (char c : {'X', 'Y', 'U', 'V', 'I', 'J', 'R', 'K', 'L'})
        if (!p.unknownValue && isValueUnknown((*side)[c])) p.unknownValue = (*side)[c];
  for (std::size_t k = 0; k < bw.machineCount; ++k) {
    const KnownCode* code = bw.machine[k].code;
    if (code->effect == CodeEffect::Position && !p.positionCode) {
      p.positionCode = code;
      p.positionCodeWord = bw.machine[k].word;
    }
    if (code->effect == CodeEffect::NoMotion) p.noMotion = true;
  }
  return p;
}

}  // namespace kerf::converter::interp
