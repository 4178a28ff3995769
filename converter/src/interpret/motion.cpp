// Phase 4 (execute), the motion: a block's end point, its arc from R or I J, the move.
#include "interpreter_impl.h"

#include <cmath>

namespace kerf::converter::interp {

void Interpreter::reportArc(const geometry::ArcBuild& build, const BlockWords& bw, const Block& block,
                            std::string_view side) {
  const double unit = inch_ ? 25.4 : 1.0;
  const char* u = inch_ ? " in" : " mm";
  switch (build.status) {
    case geometry::ArcStatus::RadiusTooSmall:
      if (const Word* r = bw['R'])  // an arc given by R: always here
        diags_.error(Code::RadiusTooSmall, src_, r->span(),
                     std::string(side) + "arc radius " + formatFixed(std::abs(length(*r)) / unit, 3) +
                         " is shorter than half the chord " + formatFixed(build.halfChord / unit, 3) + u);
      break;
    case geometry::ArcStatus::FullCircleWithRadius:
      diags_.error(Code::FullCircleWithRadius, src_, bw['R']->span(),
                   std::string(side) + "arc ends where it starts, and R cannot describe a full circle",
                   "give the centre with I J");
      break;
    case geometry::ArcStatus::ZeroRadius:
      diags_.error(Code::ZeroRadius, src_,
                   spanOf(bw.has('R')   ? bw['R']
                          : bw.has('I') ? bw['I']
                                        : bw['J'],
                          block),
                   std::string(side) + "arc radius is zero",
                   bw.has('R') || options_.arcCentre == ArcCentreMode::Absolute
                       ? std::string{}
                       : "if the post writes I J as absolute centres (Charmilles Robofil does), use --arc-centre "
                         "absolute or --machine robofil");
      break;
    case geometry::ArcStatus::EndOffCircle:
      diags_.error(Code::ArcEndOffCircle, src_, spanOf(bw.has('I') ? bw['I'] : bw['J'], block),
                   std::string(side) + "arc end point is " + formatFixed(std::abs(build.radiusError) / unit, 3) + u +
                       " off the circle through the start (limit " + formatFixed(tolerance_.centreAbsolute / unit, 3) +
                       u + ")",
                   options_.arcCentre == ArcCentreMode::Incremental
                       ? "if the post writes I J as start minus centre or as absolute centres, use --arc-centre "
                         "reversed|absolute"
                       : std::string{});
      break;
    case geometry::ArcStatus::Ok: break;
  }
}

/// Which conventions would close this I J arc: evidence for detecting the convention.
void Interpreter::tallyArcCentre(const Vec2& start, const Vec2& end, const Vec2& ij, const Vec2& shift,
                                 bool closedAsUsed, std::uint32_t line) {
  ++tally_.arcs;
  // In ArcCentreMode's order; the convention in use was judged as the arc was built (closedAsUsed:
  // the same centre, the same verdict).
  const Vec2 centres[3] = {start + ij, start - ij, ij - shift};
  const int used = static_cast<int>(options_.arcCentre);
  int closing = 0, way = 0;
  for (int k = 0; k < 3; ++k)
    if (k == used ? closedAsUsed
                  : geometry::centreVerdict(start, end, centres[k], tolerance_) == geometry::ArcStatus::Ok) {
      ++tally_.closes[k];
      ++closing;
      way = k;
    }
  if (closing == 1) ++tally_.only[way];
  if (closing == 0) ++tally_.closeNoWay;
  if (!closedAsUsed && tally_.firstFailLine == 0) tally_.firstFailLine = line;
}

bool Interpreter::buildArcSegment(const BlockWords& w, Motion motion, const Vec2& start, const Vec2& end,
                                  const Vec2& shift, double centreTurn, std::string_view side, const Block& block,
                                  const Word* motionWord, Segment& out, Move* record) {
  const bool hasCentre = w.has('I') || w.has('J');
  const bool hasRadius = w.has('R');
  if (motion == Motion::Rapid || motion == Motion::Line) {
    if (hasCentre || hasRadius) {
      const Word* c = hasRadius ? w['R'] : w.has('I') ? w['I'] : w['J'];
      diags_.warning(Code::CentreOnStraightMove, src_, c->span(),
                     std::string("'") + c->letter + "' has no meaning on a straight move and is ignored");
    }
    out = Segment::line(start, end);
    return true;
  }
  const geometry::ArcDirection dir =
      motion == Motion::Clockwise ? geometry::ArcDirection::Clockwise : geometry::ArcDirection::CounterClockwise;
  if (hasRadius && hasCentre) {
    diags_.error(Code::RadiusAndCentre, src_, w['R']->span(),
                 std::string(side) + "arc has both R and I/J: give one of them");
    return false;
  }
  if (!hasRadius && !hasCentre) {
    diags_.error(Code::ArcWithoutCentre, src_,
                 motionWord && motionWord->offset >= block.offset ? motionWord->span() : block.span(),
                 std::string(side) + "arc needs its centre (I J) or its radius (R)",
                 side.empty() ? std::string{} : "in xyuv-abs and sodick-colon the upper arc has its own I J or R");
    return false;
  }
  geometry::ArcBuild build;
  if (hasRadius) {
    const double r = length(*w['R']);
    if (record) {
      record->centreForm = CentreForm::Radius;
      moveCentreWords_ = Vec2(r, 0);
    }
    build = geometry::arcFromRadius(start, end, r, dir, tolerance_);
  } else {
    Vec2 ij(0, 0);
    if (const Word* i = w['I']) ij.x() = length(*i);
    if (const Word* j = w['J']) ij.y() = length(*j);
    if (centreTurn != 0.0) {
      const double a = centreTurn / geometry::kDegreesPerRadian, c = std::cos(a), s = std::sin(a);
      ij = Vec2(c * ij.x() - s * ij.y(), s * ij.x() + c * ij.y());
    }
    Vec2 centre;
    CentreForm form = CentreForm::Incremental;
    switch (options_.arcCentre) {
      case ArcCentreMode::Incremental: centre = start + ij; break;
      case ArcCentreMode::Reversed:
        centre = start - ij;
        form = CentreForm::Reversed;
        break;
      case ArcCentreMode::Absolute:
        centre = ij - shift;
        form = CentreForm::Absolute;
        break;
    }
    if (record) {
      moveCentreWords_ = ij;
      record->centreForm = form;
    }
    build = geometry::arcFromCentre(start, end, centre, dir, tolerance_);
    if (record) tallyArcCentre(start, end, ij, shift, build.status == geometry::ArcStatus::Ok, lineOf(block));
  }
  if (build.status != geometry::ArcStatus::Ok) {
    reportArc(build, w, block, side);
    return false;
  }
  out = build.arc;
  return true;
}

bool Interpreter::executeMotionWithCorner(const BlockWords& blockWords, const BlockWords& ubw, const Block& block,
                                          const BlockPlan& plan) {
  BlockWords bare;
  const BlockWords& bw = cornerWords(blockWords, bare);
  const Word* corner = bw.cornerRound ? bw.cornerRound : bw.cornerChamfer;
  const std::size_t before = toolpath_.moves.size();
  const bool ok = executeMove(bw, ubw, block, plan);
  if (corner && ok) holdCorner(*corner, block, toolpath_.moves.size() > before, cornerUpperRadius(bw));
  return ok;
}

bool Interpreter::executeMove(const BlockWords& bw, const BlockWords& ubw, const Block& block, const BlockPlan& plan) {
  const bool hasEnd = bw.has('X') || bw.has('Y');
  if (!plan.lowerWords && !plan.upperWords) return true;  // modal words only
  if (motion_ == Motion::None) {
    const Word* w = bw.has('X')   ? bw['X']
                    : bw.has('Y') ? bw['Y']
                    : bw.has('I') ? bw['I']
                    : bw.has('J') ? bw['J']
                    : bw.has('R') ? bw['R']
                                  : nullptr;
    diags_.error(Code::NoMotionMode, src_, w ? w->span() : block.span(), "coordinates without a motion command",
                 "start the block (or an earlier one) with G00, G01, G02 or G03");
    return false;
  }
  if (unknown_.active) {
    // Only a destination given in full, absolutely, tells where the wire is again; the move that
    // reaches it has an unknown start and is not drawn.
    if (!incremental_ && bw.has('X') && bw.has('Y')) {
      position_ = Vec2(length(*bw['X']), length(*bw['Y']));
      shift_ = Vec2::Zero();
      const Word* u = ubw.has('U') ? ubw['U'] : bw['U'];
      const Word* v = ubw.has('V') ? ubw['V'] : bw['V'];
      upperPosition_ = position_;
      upperShift_ = Vec2::Zero();
      if (u && v && (dialect_ == Dialect::XyuvAbs || dialect_ == Dialect::XyuvLinuxCnc))
        upperPosition_ = Vec2(length(*u), length(*v));
      skipMove(block, motion_ != Motion::Rapid);
      positionKnownAgain(block);
    } else {
      skipMove(block, motion_ != Motion::Rapid);
    }
    return true;
  }
  Move move;
  move.line = lineOf(block);
  move.span = block.span();
  moveCentreWords_ = Vec2::Zero();
  moveTaper_ = 0.0f;
  move.wireOffset = wireOffset_;
  move.setCallDepth(stack_.size());

  const Vec2 start = position_;
  Vec2 end = start;
  if (!buildSide(bw, 'X', 'Y', motion_, start, shift_, "", block, motionWord_.get(), move.lower, end, &move)) {
    position_ = end;
    return false;
  }
  const Segment& lower = move.lower;
  const bool straight = motion_ == Motion::Rapid || motion_ == Motion::Line;
  if (straight && !hasEnd && !plan.upperWords) return true;  // I J R alone on a line: warned, no move
  move.kind = motion_ == Motion::Rapid ? MoveKind::Rapid : straight ? MoveKind::Line : MoveKind::Arc;

  Segment upper = lower;  // a plain program's: the wire is vertical
  if (dialect_ != Dialect::Plain && !buildUpper(bw, ubw, block, move, upper)) {
    position_ = end;
    return false;
  }
  if (move.kind == MoveKind::Line && lower.length() <= 1e-9 && upper.length() <= 1e-9)
    diags_.warning(Code::ZeroLengthMove, src_, block.span(), "move has zero length");
  // The wire offset starts and ends on a straight move: the control cannot ramp it along an arc.
  if (const Word* pendingOffset = pendingOffset_.get()) {
    if (move.kind == MoveKind::Arc) {
      const bool cancel = wireOffset_ == WireOffset::Off;
      diags_.error(Code::OffsetOnArc, src_, block.span(),
                   std::string("the wire offset is ") + (cancel ? "cancelled" : "started") + " (" +
                       std::string(src_->text().substr(pendingOffset->offset, pendingOffset->length)) + " on line " +
                       std::to_string(src_->locate(pendingOffset->offset).line) + ") on this arc: a control " +
                       (cancel ? "cancels" : "starts") + " it on a straight move",
                   std::string("put a straight ") + (cancel ? "lead-out" : "lead-in") + " move after " +
                       std::string(src_->text().substr(pendingOffset->offset, pendingOffset->length)));
    }
    pendingOffset_.hold(nullptr);
  }
  push(std::move(move), upper);
  position_ = end;
  return true;
}

void Interpreter::push(Move&& m, Segment upper) {
  if (toolpath_.moves.empty()) toolpath_.start = position_;  // the move starts here (in the toolpath frame)
  if (pendingCorner_) {
    makeCorner(m, upper);
  } else if (roundsProgramCorner(m)) {  // corner-rounded (Charmilles G28): every sharp corner of a taper
    const Move& before = toolpath_.moves.back();
    pendingCorner_ = PendingCorner{0.0, std::nullopt, false, before.span, before.line};
    makeCorner(m, upper);
  }
  // Masked with the two bits Move::modes has, so that the compiler sees the value fit them.
  m.modes = ((incremental_ ? kModeIncremental : 0) | (inch_ ? kModeInch : 0)) & 3u;
  noteOffsetRun(m, toolpath_.moves.size());
  toolpath_.setFeedFrom(toolpath_.moves.size(), feed_);
  toolpath_.moves.push_back(std::move(m));
  if (dialect_ != Dialect::Plain) toolpath_.upper.push_back(upper);
  if (dialect_ == Dialect::TaperAngle) toolpath_.taperDegrees.push_back(moveTaper_);
  if (options_.recordCentreWords) toolpath_.centreWords.push_back(moveCentreWords_);
}

void Interpreter::extendOffsetRun(const Move& m, std::size_t index) {
  // Runs of moves under one G41/G42 (wire_offset.cpp applies them at the end).
  const bool extends = !offsetRuns_.empty() && offsetRuns_.back().end == index &&
                       offsetRuns_.back().side == m.wireOffset && offsetRuns_.back().value == offsetValue_ &&
                       offsetRuns_.back().offsetRegister == offsetRegister_ && m.kind != MoveKind::Rapid;
  if (extends)
    ++offsetRuns_.back().end;
  else
    offsetRuns_.push_back({index, index + 1, m.wireOffset, offsetValue_, offsetRegister_});
}

}  // namespace kerf::converter::interp
