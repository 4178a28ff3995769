// The upper side of a 4-axis move, by dialect (docs/taper.md).
#include "interpreter_impl.h"

#include <cmath>

namespace kerf::converter::interp {
namespace {

Segment translated(Segment s, const Vec2& d) {
  s.start += d;
  s.end += d;
  s.centre += d;
  return s;
}

}  // namespace

bool Interpreter::buildUpper(const BlockWords& bw, const BlockWords& ubw, const Block& block, Move& move,
                             Segment& upper) {
  switch (dialect_) {
    case Dialect::Plain:
    case Dialect::TwoFile: return true;
    case Dialect::XyuvAbs: return buildUpperAbsolute(bw, ubw, block, upper);
    case Dialect::XyuvLinuxCnc: return buildUpperLinuxCnc(ubw, upper);
    case Dialect::SodickColon: return buildUpperColon(ubw, block, move, upper);
    case Dialect::XyuvRel: return recordUpperRelative(ubw, move, upper);
    case Dialect::TaperAngle: return recordTaper(block, move);
  }
  return true;
}

/// xyuv-abs: U V (with the upper side's own motion word and I J or R) the upper contour itself.
bool Interpreter::buildUpperAbsolute(const BlockWords& bw, const BlockWords& ubw, const Block& block, Segment& upper) {
  if (const Word* g = ubw.group(ModalGroup::Motion)) {
    upperMotion_ = motionOf(ubw.code(ModalGroup::Motion));
    upperMotionWord_.hold(g);
  } else if (bw.group(ModalGroup::Motion) || upperMotion_ == Motion::None) {
    upperMotion_ = motion_;
    upperMotionWord_.hold(motionWord_.get());
  }
  const bool moves = ubw.has('U') || ubw.has('V') || ubw.has('I') || ubw.has('J') || ubw.has('R');
  if (!moves) {  // the upper guide stays where it is
    upper = Segment::line(upperPosition_, upperPosition_);
    return true;
  }
  // An arc the upper side only inherits, with no centre of its own: U V move in a straight
  // line, as LinuxCNC moves them and as cnc3 draws it (its missing upper centre is the start
  // point, and an arc centred on its start is drawn as a line: gcode.cpp, GCode::addArc).
  const bool inheritedArc = !ubw.group(ModalGroup::Motion) && !ubw.has('I') && !ubw.has('J') && !ubw.has('R') &&
                            (upperMotion_ == Motion::Clockwise || upperMotion_ == Motion::CounterClockwise);
  Vec2 end;
  const bool ok = buildSide(ubw, 'U', 'V', inheritedArc ? Motion::Line : upperMotion_, upperPosition_, upperShift_,
                            "upper ", block, upperMotionWord_.get(), upper, end, nullptr);
  upperPosition_ = end;
  return ok;
}

/// xyuv-linuxcnc: U V move linearly during any motion (LinuxCNC moves Z so during a helix).
bool Interpreter::buildUpperLinuxCnc(const BlockWords& ubw, Segment& upper) {
  // LinuxCNC moves U V linearly during any motion, as it moves Z during a helix: the upper
  // side of an XY arc is a straight line.
  Vec2 end = upperPosition_ + upperShift_;
  if (const Word* u = ubw['U']) end.x() = incremental_ ? end.x() + length(*u) : length(*u);
  if (const Word* v = ubw['V']) end.y() = incremental_ ? end.y() + length(*v) : length(*v);
  end -= upperShift_;
  upper = Segment::line(upperPosition_, end);
  upperPosition_ = end;
  return true;
}

/// sodick-colon: the words after ':' are the upper contour; without them the wire keeps its lean.
bool Interpreter::buildUpperColon(const BlockWords& ubw, const Block& block, const Move& move, Segment& upper) {
  if (!block.colon) {
    if (colonMode_) {
      diags_.error(Code::UpperSideMissing, src_, block.span(),
                   "this move has no upper contour: inside G141/G142 every move gives it after ':'");
      return false;
    }
    upper = translated(move.lower, upperPosition_ - move.lower.start);  // the wire keeps its lean
    upperPosition_ = upper.end;
    return true;
  }
  if (const Word* g = ubw.group(ModalGroup::Motion)) {
    upperMotion_ = motionOf(ubw.code(ModalGroup::Motion));
    upperMotionWord_.hold(g);
  } else if (upperMotion_ == Motion::None) {
    upperMotion_ = motion_;
    upperMotionWord_.hold(motionWord_.get());
  }
  Vec2 end;
  const bool ok = buildSide(ubw, 'X', 'Y', upperMotion_, upperPosition_, shift_, "upper ", block,
                            upperMotionWord_.get(), upper, end, nullptr);
  upperPosition_ = end;
  return ok;
}

/// xyuv-rel: U V (upper minus lower) and K L recorded; the contours are made once the heights are
/// known (resolveRel). upper is a placeholder until then.
bool Interpreter::recordUpperRelative(const BlockWords& ubw, const Move& move, Segment& upper) {
  RelRecord r;
  r.index = toolpath_.moves.size();
  r.offsetStart = uvOffset_;
  if (const Word* u = ubw['U']) uvOffset_.x() = incremental_ ? uvOffset_.x() + length(*u) : length(*u);
  if (const Word* v = ubw['V']) uvOffset_.y() = incremental_ ? uvOffset_.y() + length(*v) : length(*v);
  r.offsetEnd = uvOffset_;
  if (const Word* k = ubw['K']) r.centreShift.x() = length(*k);
  if (const Word* l = ubw['L']) r.centreShift.y() = length(*l);
  if (!move.lower.isArc() && (ubw.has('K') || ubw.has('L'))) {
    const Word* w = ubw.has('K') ? ubw['K'] : ubw['L'];
    diags_.warning(Code::CentreOnStraightMove, src_, w->span(),
                   std::string("'") + w->letter + "' gives the upper arc's centre and means nothing on a line");
  }
  r.tolerance = tolerance_;
  relRecords_.push_back(r);
  upper = translated(move.lower, r.offsetStart);  // placeholder until the heights are known
  return true;
}

/// taper-angle: the move's lean recorded; the contours are its offsets once the heights are known
/// (resolveTaperAngle). False on a start or end on an arc (K0219).
bool Interpreter::recordTaper(const Block& block, const Move& move) {
  TaperRecord t;
  t.index = toolpath_.moves.size();
  t.tanLeft = taperSide_ * std::tan(taperDegrees_ * geometry::kPi / 180.0);
  t.cylindricalArcs = programCorners_ == CodeEffect::CornerCylindrical;
  // The wire starts and ends its lean on a straight move (K0219, NCVC's rule).
  auto onArc = [&](const char* what, const char* help) {
    if (!move.lower.isArc()) return false;
    diags_.error(Code::TaperOnArc, src_, block.span(), what, help);
    return true;
  };
  switch (taperPhase_) {
    case TaperPhase::Off: return true;
    case TaperPhase::Starting:
      t.start = true;
      taperPhase_ = TaperPhase::On;
      if (onArc("the taper starts on an arc: the wire cannot lean while it follows a circle",
                "start the taper (G51/G52) on a straight move, as NC controls require"))
        return false;
      break;
    case TaperPhase::On: break;
    case TaperPhase::Ending:
      t.end = true;
      taperPhase_ = TaperPhase::Off;
      if (onArc("the taper ends (G50) on an arc: the wire cannot straighten while it follows a circle",
                "cancel the taper before a straight move"))
        return false;
      break;
  }
  moveTaper_ = static_cast<float>(taperSide_ * taperDegrees_);
  taperRecords_.push_back(t);
  return true;
}

}  // namespace kerf::converter::interp
