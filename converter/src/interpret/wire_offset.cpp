// G40/G41/G42 with a D or H register (Sodick's H000 = tables, --offset for a bare code or a
// register the file does not fill): recorded per move while reading, then applied at the end
// through geometry::wireOffset (arc corners, interference removed), so that checks, pictures and
// emitters see the wire-centre path (docs/interpreter.md, "Wire offset").
#include "interpreter_impl.h"

#include "kerf/geometry/offset.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

namespace kerf::converter::interp {

void Interpreter::executeWireOffset(const BlockWords& bw, const Word& o) {
  const GCode code = bw.code(ModalGroup::WireOffset);
  const WireOffset before = wireOffset_;
  wireOffset_ = code == GCode::OffsetCancel ? WireOffset::Off
                : code == GCode::OffsetLeft ? WireOffset::Left
                                            : WireOffset::Right;
  if (wireOffset_ != before) pendingOffset_.hold(&o);  // carried out by the next move
  if (code == GCode::OffsetCancel) return;
  const Word* reg = bw.has('D') ? bw['D'] : bw['H'];
  offsetValue_.reset();
  offsetRegister_.clear();
  if (reg && reg->isNumber()) {
    char name[16];
    std::snprintf(name, sizeof name, "%c%03ld", reg->letter, std::lround(reg->value));
    offsetRegister_ = name;
    const auto it = std::find_if(toolpath_.settings.begin(), toolpath_.settings.end(),
                                 [&](const Setting& s) { return s.name == name; });
    if (it != toolpath_.settings.end()) {
      char* endp = nullptr;
      const double v = std::strtod(it->value.c_str(), &endp);
      if (endp != it->value.c_str() && std::isfinite(v)) offsetValue_ = std::abs(v);
    }
    // Then --offsets FILE's table, then the profile's (InterpreterOptions::offsets holds both).
    if (const auto table = options_.offsets.find(name); !offsetValue_ && table != options_.offsets.end())
      offsetValue_ = table->second;
    if (!offsetValue_ && options_.wireOffset) offsetValue_ = *options_.wireOffset;
    if (!offsetValue_ && registersWithoutValue_.insert(name).second)
      diags_.warning(Code::WireOffsetNotApplied, src_, o.span(),
                     gName(code) + " " + std::string(name) + ": no table gives " + name +
                         " (the program's, --offsets or the machine profile's), so Kerf shows the moves under "
                         "it on their programmed contour",
                     "give it in an --offsets file (" + std::string(name) + " = 0.180) or with --offset MM");
  } else if (options_.wireOffset) {
    offsetValue_ = *options_.wireOffset;
  } else if (!warnedOffsetUnknown_) {
    warnedOffsetUnknown_ = true;
    diags_.warning(Code::WireOffsetUnknown, src_, o.span(),
                   gName(code) + " without D or H: the offset is set at the machine",
                   "give it with --offset MM to see and check the wire-centre path");
  }
}

/// Every offset run as an OffsetSpan of the moves read (applyWireOffsets renumbers them): the
/// cancelling G40 move, when it is a line, belongs to the run it ends.
void Interpreter::recordOffsetSpans() {
  const MoveList& moves = toolpath_.moves;
  for (const OffsetRun& r : offsetRuns_) {
    OffsetSpan s;
    s.first = static_cast<std::uint32_t>(r.first);
    const bool cancelled =
        r.end < moves.size() && moves[r.end].kind == MoveKind::Line && moves[r.end].wireOffset == WireOffset::Off;
    s.end = static_cast<std::uint32_t>(cancelled ? r.end + 1 : r.end);
    s.side = r.side;
    s.offsetRegister = r.offsetRegister;
    s.value = r.value;
    s.cancelled = cancelled;
    toolpath_.offsetSpans.push_back(std::move(s));
  }
}

namespace {

/// Where two wire paths' pieces are paired: the element (twice, plus one for the corner after it).
std::size_t pairKey(const geometry::WirePiece& p) { return 2 * p.element + (p.corner ? 1 : 0); }

}  // namespace

std::vector<Interpreter::PairedPiece> Interpreter::pairPieces(const std::vector<geometry::WirePiece>& lower,
                                                              const std::vector<geometry::WirePiece>* upper) {
  std::vector<PairedPiece> out;
  if (!upper) {
    for (const geometry::WirePiece& p : lower) out.push_back({p, p.segment});
    return out;
  }
  // Pieces of the same element (or corner) are paired in order; where one plane has a piece the
  // other has not (a corner convex on one plane only, an element lost on one), the other plane's
  // wire stands still where it is.
  std::size_t i = 0, j = 0;
  auto still = [](const std::vector<geometry::WirePiece>& side, std::size_t k) {
    const Vec2 at = k > 0 ? side[k - 1].segment.end : side.front().segment.start;
    return Segment::line(at, at);
  };
  while (i < lower.size() || j < upper->size()) {
    const std::size_t kl = i < lower.size() ? pairKey(lower[i]) : SIZE_MAX;
    const std::size_t ku = j < upper->size() ? pairKey((*upper)[j]) : SIZE_MAX;
    if (kl == ku) {
      out.push_back({lower[i++], (*upper)[j++].segment});
    } else if (kl < ku) {
      out.push_back({lower[i], still(*upper, j)});
      ++i;
    } else {
      const geometry::WirePiece& up = (*upper)[j++];
      geometry::WirePiece standing = up;  // the element's pairing, the lower wire where it stands
      standing.segment = still(lower, i);
      out.push_back({standing, up.segment});
    }
  }
  return out;
}

std::optional<std::vector<Interpreter::PairedPiece>> Interpreter::offsetRun(const OffsetRun& run) {
  const MoveList& moves = toolpath_.moves;
  const bool twoContours = toolpath_.isTaper() && dialect_ != Dialect::TaperAngle;
  const double d = run.side == WireOffset::Left ? *run.value : -*run.value;
  geometry::WireOffsetOptions wo;
  wo.closed = false;
  std::vector<Segment> chain, upperChain;
  for (std::size_t i = run.first + 1; i < run.end; ++i) {
    chain.push_back(moves[i].lower);
    if (twoContours) upperChain.push_back(toolpath_.upper[i]);
  }
  geometry::WireOffsetResult r = geometry::wireOffset(chain, d, wo);
  geometry::WireOffsetResult u;
  if (twoContours) u = geometry::wireOffset(upperChain, d, wo);
  const bool split = r.paths.size() != 1 || (twoContours && u.paths.size() != 1);
  if (r.refused || u.refused || split) {
    const geometry::WireOffsetResult& bad = r.refused || r.paths.size() != 1 ? r : u;
    const std::string plane = twoContours ? (&bad == &r ? " on the lower plane" : " on the upper plane") : "";
    diags_.error(Code::WirePathSplits, src_, moves[run.first].span,
                 bad.tooMuchWork
                     ? "the wire offset of this run of moves needs more than " + std::to_string(bad.tests - 1) +
                           " exact tests of pieces whose boxes overlap (long moves side by side, as in a "
                           "star of thin spikes): refused"
                 : bad.refused ? std::string("the wire offset of this run of moves needs more pieces than the budget")
                               : "at an offset of " + formatFixed(*run.value, 3) + " mm the wire path of these " +
                                     std::to_string(chain.size()) + " moves" + plane + " breaks into " +
                                     std::to_string(bad.paths.size()) + " pieces: the wire cannot follow them",
                 "the moves keep their programmed geometry");
    return std::nullopt;
  }
  reportLostRuns(run, r.lost);
  return pairPieces(r.paths.front(), twoContours ? &u.paths.front() : nullptr);
}

void Interpreter::reportLostRuns(const OffsetRun& run, const std::vector<geometry::LostRun>& lostRuns) {
  for (const geometry::LostRun& lost : lostRuns) {
    const Move& m = toolpath_.moves[run.first + 1 + lost.first];
    if (lost.fillet)
      diags_.note(Code::InsideCornerRadius, src_, m.span,
                  "this arc's radius " + formatFixed(m.lower.radius(), 3) + " mm is smaller than the wire offset " +
                      formatFixed(*run.value, 3) + " mm: the wire cuts the corner with radius " +
                      formatFixed(*run.value, 3) + " mm");
    else
      diags_.warning(Code::WireCannotReach, src_, m.span,
                     "the wire (offset " + formatFixed(*run.value, 3) + " mm) cannot reach " +
                         std::to_string(lost.count) + (lost.count == 1 ? " move" : " moves") +
                         " from here: a slot or recess narrower than the "
                         "wire; up to " +
                         formatFixed(lost.uncut, 3) + " mm of material stays",
                     "the wire path leaves it out");
  }
}

void Interpreter::resolveWireOffsets() {
  recordOffsetSpans();
  std::vector<OffsetRun> runs;
  for (const OffsetRun& r : offsetRuns_)
    if (r.value && *r.value > 0) runs.push_back(r);
  if (runs.empty()) return;
  OffsetBuild b;
  const MoveList& moves = toolpath_.moves;
  b.firstOut.assign(moves.size() + 1, UINT32_MAX);
  for (const OffsetRun& run : runs) {
    // The start-up move and the moves it compensates; a rapid or an arc start-up is reported elsewhere.
    if (run.end - run.first < 2 || moves[run.first].kind != MoveKind::Line) continue;
    const std::optional<std::vector<PairedPiece>> path = offsetRun(run);
    if (!path) continue;
    b.copyUpTo(run.first, toolpath_);
    b.addRun(run, *path, toolpath_);
    b.applied = true;
  }
  if (!b.applied) return;
  b.copyUpTo(moves.size(), toolpath_);
  // The moves are the wire-centre path now: an output written from them must not offset again.
  for (MoveRow& r : b.rows)
    if (r.offsetRole != OffsetRole::None) r.move.wireOffset = WireOffset::Off;
  renumberAfterOffset(b);
  const OffsetRun& first = runs.front();
  diags_.note(Code::WireOffsetApplied, src_, toolpath_.moves.empty() ? SourceSpan::wholeFile() : moves[0].span,
              std::string("wire offset applied (") + (first.side == WireOffset::Left ? "G41" : "G42") + ", " +
                  formatFixed(*first.value, 3) + " mm" + (runs.size() > 1 ? " first" : "") + ")" +
                  (toolpath_.isTaper() ? (dialect_ == Dialect::TaperAngle
                                              ? " on the program plane, the taper taken from the offset path"
                                              : " to both planes' contours, their pieces paired")
                                       : std::string()) +
                  ": checks, pictures and outputs use the wire-centre path",
              "kerf explain shows each move's programmed geometry beside it");
}

void Interpreter::OffsetBuild::push(const Toolpath& tp, std::size_t from, const Move& m, const Segment& upperSegment,
                                    OffsetRole r, const Segment& programmedSegment) {
  MoveRow row = tp.rowOf(from);
  row.move = m;
  row.upper = upperSegment;
  row.offsetRole = r;
  row.programmed = programmedSegment;
  rows.push_back(row);
  source.push_back(from);
}

void Interpreter::OffsetBuild::copyUpTo(std::size_t end, const Toolpath& tp) {
  for (; next < end; ++next) {
    firstOut[next] = static_cast<std::uint32_t>(rows.size());
    push(tp, next, tp.moves[next], tp.upperOf(next), OffsetRole::None, tp.moves[next].lower);
  }
}

void Interpreter::OffsetBuild::addRun(const OffsetRun& run, const std::vector<PairedPiece>& path, const Toolpath& tp) {
  const MoveList& moves = tp.moves;
  Move startUp = moves[run.first];
  startUp.lower = Segment::line(startUp.lower.start, path.front().lower.segment.start);
  firstOut[run.first] = static_cast<std::uint32_t>(rows.size());
  push(tp, run.first, startUp, Segment::line(tp.upperOf(run.first).start, path.front().upper.start),
       OffsetRole::StartUp, moves[run.first].lower);
  for (const PairedPiece& pp : path) {
    const geometry::WirePiece& piece = pp.lower;
    const std::size_t element = run.first + 1 + piece.element;
    const std::size_t from = piece.corner && element + 1 < run.end ? element + 1 : element;
    Move m = moves[from];
    m.lower = piece.segment;
    m.kind = piece.segment.isArc() || pp.upper.isArc() ? MoveKind::Arc : MoveKind::Line;
    if (!piece.corner && firstOut[element] == UINT32_MAX) firstOut[element] = static_cast<std::uint32_t>(rows.size());
    const Segment& programmedElement = moves[element].lower;
    push(tp, from, m, pp.upper, piece.corner ? OffsetRole::Corner : OffsetRole::Element,
         piece.corner ? Segment::line(programmedElement.end, programmedElement.end) : programmedElement);
  }
  next = run.end;
  // The cancel move (G40 on a line) leaves the offset path for its programmed end.
  if (run.end < moves.size() && moves[run.end].kind == MoveKind::Line) {
    Move cancel = moves[run.end];
    cancel.lower = Segment::line(path.back().lower.segment.end, cancel.lower.end);
    firstOut[run.end] = static_cast<std::uint32_t>(rows.size());
    push(tp, run.end, cancel, Segment::line(path.back().upper.end, tp.upperOf(run.end).end), OffsetRole::Cancel,
         moves[run.end].lower);
    next = run.end + 1;
  }
}

void Interpreter::renumberAfterOffset(OffsetBuild& b) {
  const std::size_t oldCount = toolpath_.moves.size();
  // A move the wire cannot reach takes the place of the next one that is cut.
  const std::size_t newCount = b.rows.size();
  b.firstOut[oldCount] = static_cast<std::uint32_t>(newCount);
  for (std::size_t k = oldCount; k-- > 0;)
    if (b.firstOut[k] == UINT32_MAX) b.firstOut[k] = b.firstOut[k + 1];
  // taper-angle: each applied move leans as the move it came from; the taper starts on the first
  // move made from its start move and ends on the last made from its end move.
  if (!taperRecords_.empty()) {
    std::vector<std::size_t> recordOf(oldCount, SIZE_MAX);
    for (std::size_t k = 0; k < taperRecords_.size(); ++k) recordOf[taperRecords_[k].index] = k;
    std::vector<TaperRecord> records;
    for (std::size_t o = 0; o < newCount; ++o) {
      const std::size_t s = b.source[o];
      if (recordOf[s] == SIZE_MAX) continue;
      TaperRecord r = taperRecords_[recordOf[s]];
      r.index = o;
      r.start = r.start && (o == 0 || b.source[o - 1] != s);
      r.end = r.end && (o + 1 == newCount || b.source[o + 1] != s);
      records.push_back(r);
    }
    taperRecords_ = std::move(records);
  }
  // A taper's rounded corner, offset with its neighbours, keeps its place; its radius on the wire's
  // path is the part's less (or more) the wire offset, on every plane alike.
  for (TaperCorner& c : taperCorners_) {
    c.move = b.firstOut[c.move];
    if (c.chamfer || c.move >= newCount || b.rows[c.move].offsetRole != OffsetRole::Element ||
        !b.rows[c.move].move.lower.isArc())
      continue;
    const double grown = b.rows[c.move].move.lower.radius() - c.size;
    c.size += grown;
    if (c.upperSize) *c.upperSize += grown;
  }
  toolpath_.replaceMoves(std::move(b.rows), b.firstOut, true);
}

}  // namespace kerf::converter::interp
