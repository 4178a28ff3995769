// Phase 3 (check): combinations that cannot mean anything are refused before anything runs.
#include "interpreter_impl.h"

namespace kerf::converter::interp {

bool Interpreter::checkDialectWords(const Block& block, const BlockWords& bw, const BlockWords& ubw, bool setPosition) {
  // Built only when a word is refused.
  const char* choose = "choose the dialect with --dialect";
  auto refuse = [&](const Word* w, const std::string& message, const std::string& help = {}) {
    diags_.error(Code::WordNotInDialect, src_, w ? w->span() : block.span(),
                 message + " (this program is read as " + dialectName(dialect_) + ")", help);
    return false;
  };
  const bool upperContourWords =
      dialect_ == Dialect::XyuvAbs || dialect_ == Dialect::XyuvRel || dialect_ == Dialect::XyuvLinuxCnc;
  for (const BlockWords* side : {&bw, &ubw}) {
    if (!upperContourWords && !setPosition && (side->has('U') || side->has('V')))
      return refuse(side->has('U') ? (*side)['U'] : (*side)['V'], "U/V give the upper contour of a 4-axis program",
                    dialect_ == Dialect::SodickColon
                        ? std::string("in sodick-colon the upper contour follows ':' as X Y")
                        : std::string(choose) + " xyuv-abs, xyuv-rel or xyuv-linuxcnc");
  }
  if (block.colon && dialect_ != Dialect::SodickColon)
    return refuse(nullptr, "':' separates the lower and upper contours of a Sodick 4-axis program",
                  std::string(choose) + " sodick-colon");
  if (const Word* t = bw.group(ModalGroup::Taper); t && dialect_ != Dialect::TaperAngle)
    return refuse(t, gName(bw.code(ModalGroup::Taper)) + " is a taper-angle command",
                  std::string(choose) + " taper-angle");
  if (const Word* c = bw.group(ModalGroup::ColonMode); c && dialect_ != Dialect::SodickColon)
    return refuse(c, gName(bw.code(ModalGroup::ColonMode)) + " is a Sodick 4-axis command",
                  std::string(choose) + " sodick-colon");
  if (dialect_ == Dialect::XyuvAbs) {
    for (char c : {'X', 'Y', 'K', 'L'})
      if (ubw.has(c))
        return refuse(ubw[c], std::string("'") + c + "' on the upper side: xyuv-abs gives the upper contour as U V",
                      "put X Y before the U V words");
  }
  if (dialect_ == Dialect::XyuvLinuxCnc) {
    for (char c : {'X', 'Y', 'I', 'J', 'R', 'K', 'L'})
      if (ubw.has(c))
        return refuse(ubw[c],
                      std::string("'") + c +
                          "' on the upper side: in xyuv-linuxcnc U V move in a straight line during the "
                          "block, so the upper side has no centre of its own",
                      "for an upper arc with its own centre, " + std::string(choose) + " xyuv-abs");
    if (const Word* g = ubw.group(ModalGroup::Motion))
      return refuse(g, "a second motion word: in xyuv-linuxcnc both sides share the block's motion",
                    std::string(choose) + " xyuv-abs");
  }
  if (dialect_ == Dialect::XyuvRel) {
    for (char c : {'X', 'Y', 'I', 'J', 'R'})
      if (ubw.has(c))
        return refuse(ubw[c], std::string("'") + c +
                                  "' after U V: xyuv-rel gives the upper arc by K L (lower centre to upper centre)");
    if (const Word* g = ubw.group(ModalGroup::Motion))
      return refuse(g, "a second motion word: in xyuv-rel both sides share the block's motion");
  }
  if (dialect_ == Dialect::SodickColon) {
    for (char c : {'K', 'L'})
      if (ubw.has(c)) return refuse(ubw[c], std::string("'") + c + "' has no meaning after ':'");
  }
  return true;
}

bool Interpreter::checkBlockWords(const Block& block, const BlockWords& bw, const BlockWords& ubw,
                                  const BlockPlan& plan) {
  if (!checkDialectWords(block, bw, ubw, plan.setPosition)) return false;
  // G04: a time, P in milliseconds or X in seconds, not below zero.
  if (plan.dwell) {
    const Word* time = bw.has('P') ? bw['P'] : bw['X'];
    if (!time) {
      diags_.error(Code::DwellWithoutTime, src_, bw.group(ModalGroup::NonModal)->span(),
                   "G04 needs a time: P (milliseconds) or X (seconds)");
      return false;
    }
    if (time->isNumber() && time->value < 0) {
      diags_.error(Code::NegativeDwell, src_, time->span(),
                   "dwell time " + std::string(src_->text().substr(time->offset, time->length)) +
                       " is negative: a control waits for no less than nothing",
                   "give the time as a positive number of milliseconds (P) or seconds (X)");
      return false;
    }
  }
  if (const Word* p = bw.group(ModalGroup::Plane); p && bw.code(ModalGroup::Plane) != GCode::PlaneXY) {
    diags_.error(
        Code::PlaneNotSupported, src_, p->span(),
        gName(bw.code(ModalGroup::Plane)) + " selects a plane a wire machine cannot cut in; only G17 (XY) is allowed");
    return false;
  }
  // A direction alone (`Y+`) belongs to an edge-sensing code of the machine.
  if (block.unusualValues)
    for (const BlockWords* side : {&bw, &ubw})
      for (char c : {'X', 'Y', 'U', 'V', 'Z'})
        if (const Word* w = (*side)[c]; w && w->kind == WordValue::Direction && !plan.positionCode) {
          diags_.error(Code::DirectionWord, src_, w->span(),
                       "'" + std::string(src_->text().substr(w->offset, w->length)) +
                           "' gives a direction, not a coordinate: that belongs to an edge-sensing code",
                       "Sodick writes G80 X+ (contact sensing); read such a program with --machine sodick");
          return false;
        }
  // The second plane named U Z: ask, do not guess. Said once; every such block is left unread,
  // so no contour half made of guesses follows.
  if (!programHasV_ && !machine_.upperAxesUZ && (bw.has('U') || ubw.has('U'))) {
    const Word* u = bw.has('U') ? bw['U'] : ubw['U'];
    const Word* z = bw['Z'];
    if (u && z) {
      if (!warnedUz_)
        diags_.error(Code::UpperAxesNamedUZ, src_, z->span(),
                     "Z beside U and no V anywhere in the program: the second plane's axes may be named U Z",
                     "if this machine names them so, read Z as V with --upper-axes uz (or a machine profile with "
                     "upper_axes = uz)");
      warnedUz_ = true;
      return false;
    }
  }
  return true;
}

}  // namespace kerf::converter::interp
