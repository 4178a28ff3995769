// G40/G41/G42 with a D or H register: recorded per move (the geometry stays the programmed
// contour until the wire offset is applied; docs/interpreter.md).
#include "interpreter_impl.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace kerf::converter::interp {

void Interpreter::executeWireOffset(const BlockWords& bw, const Word& o) {
  const GCode code = bw.code(ModalGroup::WireOffset);
  const WireOffset before = wireOffset_;
  wireOffset_ = code == GCode::OffsetCancel ? WireOffset::Off
                : code == GCode::OffsetLeft ? WireOffset::Left
                                            : WireOffset::Right;
  if (wireOffset_ != before) pendingOffset_ = &o;  // carried out by the next move
  if (code == GCode::OffsetCancel) return;
  const Word* reg = bw.has('D') ? bw['D'] : bw['H'];
  std::string what;
  if (reg && reg->isNumber()) {
    char name[16];
    std::snprintf(name, sizeof name, "%c%03ld", reg->letter, std::lround(reg->value));
    what = std::string(name);
    const auto it = std::find_if(toolpath_.settings.begin(), toolpath_.settings.end(),
                                 [&](const Setting& s) { return s.name == name; });
    if (it != toolpath_.settings.end()) what += " = " + it->value;
  } else if (options_.wireOffset) {
    what = "--offset " + fmt3(*options_.wireOffset) + " mm";
  } else {
    if (!warnedOffsetUnknown_) {
      warnedOffsetUnknown_ = true;
      diags_.warning(Code::WireOffsetUnknown, src_, o.span(),
                     gName(code) + " without D or H: the offset is set at the machine",
                     "give it with --offset MM to record it");
    }
    return;
  }
  if (!warnedOffset_) {
    warnedOffset_ = true;
    diags_.warning(Code::WireOffsetNotApplied, src_, o.span(),
                   "wire offset " + gName(code) + " (" + what +
                       ") is read but not applied yet: geometry and pictures show the programmed contour");
  }
}

}  // namespace kerf::converter::interp
