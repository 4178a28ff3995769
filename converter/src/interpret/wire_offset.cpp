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

void Interpreter::resolveWireOffsets() {
  recordOffsetSpans();
  std::vector<OffsetRun> runs;
  for (const OffsetRun& r : offsetRuns_)
    if (r.value && *r.value > 0) runs.push_back(r);
  if (runs.empty()) return;
  MoveList& moves = toolpath_.moves;
  if (toolpath_.isTaper()) {
    diags_.warning(Code::WireOffsetNotApplied, src_, moves[runs.front().first].span,
                   "the wire offset is read but not applied to a 4-axis program: geometry and pictures show the "
                   "programmed contours");
    return;
  }
  MoveList out;
  std::vector<OffsetRole> role;
  std::vector<Segment> programmed;
  // The centres as written stay with the moves they came from (when they are kept).
  const std::vector<Vec2>& centres = toolpath_.centreWords;
  std::vector<Vec2> outCentres;
  auto keepCentre = [&](std::size_t from) {
    if (!centres.empty()) outCentres.push_back(centres[from]);
  };
  out.reserve(moves.size() + moves.size() / 2);
  std::size_t next = 0;  // first move not yet copied
  bool applied = false;
  // Per programmed move, the first applied move made from it (for Toolpath::stops).
  std::vector<std::uint32_t> firstOut(moves.size() + 1, UINT32_MAX);
  auto copyUpTo = [&](std::size_t end) {
    for (; next < end; ++next) {
      firstOut[next] = static_cast<std::uint32_t>(out.size());
      out.push_back(moves[next]);
      keepCentre(next);
      role.push_back(OffsetRole::None);
      programmed.push_back(moves[next].lower);
    }
  };
  for (const OffsetRun& run : runs) {
    // The start-up move and the moves it compensates; a rapid or an arc start-up is reported elsewhere.
    if (run.end - run.first < 2 || moves[run.first].kind != MoveKind::Line) continue;
    std::vector<Segment> chain;
    for (std::size_t i = run.first + 1; i < run.end; ++i) chain.push_back(moves[i].lower);
    const double d = run.side == WireOffset::Left ? *run.value : -*run.value;
    geometry::WireOffsetOptions wo;
    wo.closed = false;
    const geometry::WireOffsetResult r = geometry::wireOffset(chain, d, wo);
    if (r.refused || r.paths.size() != 1) {
      diags_.error(Code::WirePathSplits, src_, moves[run.first].span,
                   r.tooMuchWork
                       ? "the wire offset of this run of moves needs more than " + std::to_string(r.tests - 1) +
                             " exact tests of pieces whose boxes overlap (long moves side by side, as in a "
                             "star of thin spikes): refused"
                   : r.refused ? std::string("the wire offset of this run of moves needs more pieces than the budget")
                               : "at an offset of " + formatFixed(*run.value, 3) + " mm the wire path of these " +
                                     std::to_string(chain.size()) + " moves breaks into " +
                                     std::to_string(r.paths.size()) + " pieces: the wire cannot follow them",
                   "the moves keep their programmed geometry");
      continue;
    }
    copyUpTo(run.first);
    const std::vector<geometry::WirePiece>& path = r.paths.front();
    Move startUp = moves[run.first];
    startUp.lower = Segment::line(startUp.lower.start, path.front().segment.start);
    firstOut[run.first] = static_cast<std::uint32_t>(out.size());
    out.push_back(startUp);
    keepCentre(run.first);
    role.push_back(OffsetRole::StartUp);
    programmed.push_back(moves[run.first].lower);
    for (const geometry::WirePiece& piece : path) {
      const std::size_t source = run.first + 1 + piece.element;
      const std::size_t from = piece.corner && source + 1 < run.end ? source + 1 : source;
      Move m = moves[from];
      m.lower = piece.segment;
      m.kind = piece.segment.isArc() ? MoveKind::Arc : MoveKind::Line;
      if (!piece.corner && firstOut[source] == UINT32_MAX) firstOut[source] = static_cast<std::uint32_t>(out.size());
      out.push_back(m);
      keepCentre(from);
      role.push_back(piece.corner ? OffsetRole::Corner : OffsetRole::Element);
      programmed.push_back(piece.corner ? Segment::line(chain[piece.element].end, chain[piece.element].end)
                                        : chain[piece.element]);
    }
    next = run.end;
    // The cancel move (G40 on a line) leaves the offset path for its programmed end.
    if (run.end < moves.size() && moves[run.end].kind == MoveKind::Line) {
      Move cancel = moves[run.end];
      cancel.lower = Segment::line(path.back().segment.end, cancel.lower.end);
      firstOut[run.end] = static_cast<std::uint32_t>(out.size());
      out.push_back(cancel);
      keepCentre(run.end);
      role.push_back(OffsetRole::Cancel);
      programmed.push_back(moves[run.end].lower);
      next = run.end + 1;
    }
    for (const geometry::LostRun& lost : r.lost) {
      const Move& m = moves[run.first + 1 + lost.first];
      if (lost.fillet)
        diags_.note(Code::InsideCornerRadius, src_, m.span,
                    "this arc's radius " + formatFixed(m.lower.radius, 3) + " mm is smaller than the wire offset " +
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
    applied = true;
  }
  if (!applied) return;
  copyUpTo(moves.size());
  // The moves are the wire-centre path now: an output written from them must not offset again.
  for (std::size_t i = 0; i < out.size(); ++i)
    if (role[i] != OffsetRole::None) out[i].wireOffset = WireOffset::Off;
  // Stops, conditions and offset runs keep their place: before the first applied move of the
  // programmed move they preceded (a move the wire cannot reach takes the place of the next one that
  // is cut).
  firstOut[moves.size()] = static_cast<std::uint32_t>(out.size());
  for (std::size_t k = moves.size(); k-- > 0;)
    if (firstOut[k] == UINT32_MAX) firstOut[k] = firstOut[k + 1];
  toolpath_.renumberMoveLists(firstOut);
  moves = std::move(out);
  if (!centres.empty()) toolpath_.centreWords = std::move(outCentres);
  toolpath_.offsetRole = std::move(role);
  toolpath_.programmed = std::move(programmed);
  const OffsetRun& first = runs.front();
  diags_.note(Code::WireOffsetNotApplied, src_, toolpath_.moves.empty() ? SourceSpan::wholeFile() : moves[0].span,
              std::string("wire offset applied (") + (first.side == WireOffset::Left ? "G41" : "G42") + ", " +
                  formatFixed(*first.value, 3) + " mm" + (runs.size() > 1 ? " first" : "") +
                  "): checks, pictures and outputs use the wire-centre path",
              "kerf explain shows each move's programmed geometry beside it");
}

}  // namespace kerf::converter::interp
