// Phase 4, the corner at a block's end: Fanuc's `,R r` and `,C c`, and NCVC's bare R on a cut
// block (profile `corner_r = bare`). The corner is held until the next move is pushed; then both
// elements are trimmed and the fillet or chamfer is pushed between them (geometry/corner.h), as a
// move of the block that asked for it. docs/formats.md, "Corner rounding and chamfers".
#include "interpreter_impl.h"

#include "kerf/geometry/corner.h"

namespace kerf::converter::interp {

const BlockWords& Interpreter::cornerWords(const BlockWords& bw, BlockWords& bare) const {
  if (!machine_.bareCornerRadius || !bw.has('R') || bw.cornerRound || bw.cornerChamfer) return bw;
  const bool arcWithCentre =
      (motion_ == Motion::Clockwise || motion_ == Motion::CounterClockwise) && (bw.has('I') || bw.has('J'));
  if (motion_ != Motion::Line && !arcWithCentre) return bw;  // an R arc's R is its radius
  bare = bw;
  bare.cornerRound = bw['R'];
  bare.clearLetter('R');
  return bare;
}

const Word* Interpreter::cornerUpperRadius(const BlockWords& bw) const {
  if (dialect_ != Dialect::TaperAngle || !machine_.bareCornerRadius || !bw.has('K')) return nullptr;
  return bw.has('R') || (bw.cornerRound && !bw.cornerRound->corner) ? bw['K'] : nullptr;
}

void Interpreter::holdCorner(const Word& w, const Block& block, bool moved, const Word* upper) {
  const std::string written(src_->text().substr(w.offset, w.length));
  auto refuse = [&](const std::string& why, const std::string& help = {}) {
    diags_.error(Code::CornerNotMade, src_, w.span(), "'" + written + "': " + why, help);
  };
  if (!moved) return refuse("the block makes no cut move whose corner it could round");
  if (toolpath_.moves.back().kind == MoveKind::Rapid) return refuse("a rapid has no corner to round or chamfer");
  if (dialect_ != Dialect::Plain && dialect_ != Dialect::TaperAngle)
    return refuse(std::string("Kerf rounds corners in 2-axis and taper-angle programs; a ") + dialectName(dialect_) +
                      " program gives each plane's contour itself",
                  "write the fillet as an arc on both planes");
  const double size = length(w);
  if (!(size > 0) || size > 1e5)
    return refuse("the corner's size must be more than 0 and at most 100 m, not " + formatFixed(size, 3) + " mm");
  std::optional<double> upperSize;
  if (upper) {
    upperSize = length(*upper);
    if (!(*upperSize >= 0) || *upperSize > 1e5)
      return refuse("the upper plane's corner radius K must be 0 to 100 m, not " + formatFixed(*upperSize, 3) + " mm");
  }
  pendingCorner_ = PendingCorner{size, upperSize, w.letter == 'C', w.span(), lineOf(block)};
}

void Interpreter::refusePendingCorner(const std::string& why) {
  if (!pendingCorner_) return;
  const PendingCorner pc = *pendingCorner_;
  pendingCorner_.reset();
  diags_.error(Code::CornerNotMade, src_, pc.span,
               "'" + std::string(src_->text().substr(pc.span.offset, pc.span.length)) + "': " + why,
               "a corner word rounds the corner between its block's move and the next cut move");
}

void Interpreter::makeCorner(Move& next, Segment& nextUpper) {
  if (!next.isCut()) return refusePendingCorner("a rapid follows, not a cut move: there is no corner to round");
  const PendingCorner pc = *pendingCorner_;
  Move& prev = toolpath_.moves.back();
  const bool apex = pc.size == 0;  // corner-rounded: a point here, rounded on the other planes
  geometry::Corner c;
  if (apex) {
    c.status = geometry::CornerStatus::Ok;
    c.first = prev.lower;
    c.second = next.lower;
    c.sharp = prev.lower.end;
    c.corner = Segment::line(c.sharp, c.sharp);
  } else {
    c = pc.chamfer ? geometry::chamferCorner(prev.lower, next.lower, pc.size)
                   : geometry::roundCorner(prev.lower, next.lower, pc.size);
  }
  if (c.status != geometry::CornerStatus::Ok) {
    const std::string what = pc.chamfer ? "chamfer " : "radius ";
    const std::string why =
        c.status == geometry::CornerStatus::NotJoined ? "the next cut move does not start where this block ends"
        : c.status == geometry::CornerStatus::Tangent ? "this block's element and the next meet tangent: no corner"
        : c.status == geometry::CornerStatus::Reversal
            ? "the next move turns straight back along this one"
            : "a " + what + formatFixed(pc.size, 3) + " mm corner needs more than this block's element or the " +
                  "next one (line " + std::to_string(next.line) + ") has";
    return refusePendingCorner(why);
  }
  pendingCorner_.reset();
  prev.lower = c.first;
  if (dialect_ != Dialect::Plain) toolpath_.upper.back() = c.first;  // taper-angle: the programmed contour
  next.lower = c.second;
  if (dialect_ != Dialect::Plain) nextUpper = c.second;
  Move corner = prev;
  corner.lower = c.corner;
  corner.kind = c.corner.isArc() ? MoveKind::Arc : MoveKind::Line;
  corner.centreForm = CentreForm::None;
  corner.span = pc.span;
  corner.line = pc.line;
  const std::size_t at = toolpath_.moves.size();
  // taper-angle: the corner leans as the element before it; the next move's record moves one on.
  if (!taperRecords_.empty() && taperRecords_.back().index == at) {
    TaperRecord nextRecord = taperRecords_.back();
    taperRecords_.pop_back();
    if (!nextRecord.start && !taperRecords_.empty() && taperRecords_.back().index + 1 == at &&
        !taperRecords_.back().end) {
      TaperRecord cornerRecord = taperRecords_.back();
      cornerRecord.index = at;
      cornerRecord.start = false;
      taperRecords_.push_back(cornerRecord);
    }
    nextRecord.index = at + 1;
    taperRecords_.push_back(nextRecord);
    if (taperRecords_.size() >= 2 && taperRecords_[taperRecords_.size() - 2].index == at)
      taperCorners_.push_back({at, apex ? CodeEffect::CornerConicalMean : taperCorner_, pc.size, pc.upperSize,
                               pc.chamfer, geometry::cross(c.first.tangentAt(1.0), c.second.tangentAt(0.0)) > 0});
  }
  noteOffsetRun(corner, at);
  toolpath_.moves.push_back(corner);
  if (dialect_ != Dialect::Plain) toolpath_.upper.push_back(c.corner);
  if (dialect_ == Dialect::TaperAngle) toolpath_.taperDegrees.push_back(toolpath_.taperDegrees.back());
  if (options_.recordCentreWords) toolpath_.centreWords.push_back(Vec2::Zero());
  if (!apex) toolpath_.corners.push_back({static_cast<std::uint32_t>(at), pc.size, pc.chamfer, c.sharp});
}

bool Interpreter::turnsTaperCorner(const Move& next) const {
  if (dialect_ != Dialect::TaperAngle || !next.isCut() || toolpath_.moves.empty() || !toolpath_.moves.back().isCut() ||
      taperRecords_.size() < 2)
    return false;
  // Both moves lean and neither starts or ends the taper (the next one's record is the last; the
  // one before belongs to the move before): the start-up and the cancel keep their sharp joints.
  const std::size_t at = toolpath_.moves.size();
  const TaperRecord& mine = taperRecords_.back();
  const TaperRecord& before = taperRecords_[taperRecords_.size() - 2];
  if (mine.index != at || mine.start || mine.end || before.index + 1 != at || before.start || before.end) return false;
  const Segment& a = toolpath_.moves.back().lower;
  if ((a.end - next.lower.start).norm() > 1e-6) return false;
  return std::abs(geometry::cross(a.tangentAt(1.0), next.lower.tangentAt(0.0))) > 1e-9;  // a corner, not tangent
}

}  // namespace kerf::converter::interp
