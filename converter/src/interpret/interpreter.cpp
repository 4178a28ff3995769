// The block loop: phases in order for each block, program flow between blocks, the limits of one
// run, and what is settled after the last block (heights, taper contours).
#include "interpreter_impl.h"

#include "kerf/converter/interpret/dialect.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace kerf::converter::interp {

Motion motionOf(GCode code) {
  switch (code) {
    case GCode::Rapid: return Motion::Rapid;
    case GCode::Line: return Motion::Line;
    case GCode::ArcClockwise: return Motion::Clockwise;
    default: return Motion::CounterClockwise;
  }
}

namespace {
const MachineProfile& profileOf(const InterpreterOptions& o) {
  return o.machine ? *o.machine : *findBuiltinMachine("generic");
}
}  // namespace

Interpreter::Interpreter(const Program& program, const InterpreterOptions& options, Diagnostics& diags)
    : program_(program),
      words_(program),
      src_(program.source),
      options_(options),
      machine_(profileOf(options)),
      diags_(diags) {}

Interpretation Interpreter::run() {
  toolpath_.reading.machine = machine_.name;
  toolpath_.reading.integerUnit = options_.integerUnit;
  toolpath_.reading.arcCentre = options_.arcCentre;
  if (!options_.millTurn) chooseDialect();  // a face program is read in the plane: Plain
  indexLabels();
  for (const std::uint32_t k : program_.notPlain)  // a plain block has no V
    for (const Word& w : program_.wordsOf(program_.blocks[k])) programHasV_ |= w.letter == 'V';
  if (machine_.legacyTaperCodes) findLegacyTaperCodes();
  // Most blocks of a wire program are moves: reserving avoids copying them while growing.
  toolpath_.moves.reserve(std::min(program_.blocks.size(), options_.maxMoves));
  for (const Setting& s : program_.settings) toolpath_.settings.push_back(s);
  toolpath_.blocks = program_.blocks.size();
  warnIntegerUnit();
  std::size_t pc = 0;
  const std::size_t n = program_.blocks.size();
  while (pc < n) {
    if (++executed_ > options_.maxExecutedBlocks) {
      diags_.error(Code::ExecutionLimit, src_, program_.blocks[pc].span(),
                   "stopped after " + std::to_string(options_.maxExecutedBlocks) +
                       " executed blocks: the subprogram calls repeat without end or far too often");
      break;
    }
    const Block& block = program_.blocks[pc];
    std::size_t next = pc + 1;
    if (!(block.blockDelete && options_.blockDelete) && !block.hasError) {
      const Flow flow = executeBlock(pc, next);
      if (flow == Flow::Stop) break;
    }
    // The kept words behind this block are given back, in the main program: the moves made from
    // here on take their place. Not inside a subprogram, which may lie past the rest of the main
    // program (after its M30); a block run again all the same is parsed again (WordReader).
    if (block.plain && stack_.empty()) program_.plainWords.giveBackBefore(block.firstWord);
    if (toolpath_.moves.size() > options_.maxMoves) {
      diags_.error(Code::ExecutionLimit, src_, block.span(),
                   "stopped after " + std::to_string(options_.maxMoves) + " moves (the limit of one run)");
      break;
    }
    if (next >= n && !stack_.empty()) {
      diags_.warning(Code::MissingProgramEnd, src_, program_.blocks[stack_.back().callBlock].span(),
                     "subprogram called here runs to the end of the file without M99");
      next = stack_.back().returnTo;
      stack_.pop_back();
    }
    pc = next;
  }
  flushUnknown(nullptr);
  refusePendingCorner("no cut move follows: there is no corner to round");
  if (!toolpath_.endedProperly && !diags_.hasErrors() && n > 0)
    diags_.warning(Code::MissingProgramEnd, src_, program_.blocks.back().span(), "program ends without M02 or M30");
  if (options_.millTurn) finishFace();
  resolveHeights();
  if (dialect_ == Dialect::XyuvRel) resolveRel();
  // The wire offset applies to the programmed contour; a taper-angle taper is taken from the offset
  // path, a two-contour program's offset applies to both its contours (docs/taper.md).
  resolveWireOffsets();
  if (dialect_ == Dialect::TaperAngle) resolveTaperAngle();
  return {std::move(toolpath_), tally_};
}

void Interpreter::chooseDialect() {
  if (options_.dialect) {
    dialect_ = *options_.dialect;
  } else {
    const DialectDetection d = detectDialect(program_, machine_);
    dialect_ = d.dialect;
    if (d.ambiguous()) {
      std::string list, help;
      for (Dialect c : d.candidates) {
        list += std::string(list.empty() ? "" : " or ") + dialectName(c);
        help += std::string(help.empty() ? "choose with " : " or ") + "--dialect " + dialectName(c);
      }
      diags_.error(Code::DialectAmbiguous, src_, d.span,
                   "the 4-axis words fit more than one dialect, " + list + ": " + d.reason, help);
    } else if (dialect_ != Dialect::Plain) {
      diags_.note(Code::DialectChosen, src_, d.span,
                  std::string("read as ") + dialectName(dialect_) + " (4-axis taper), from " + d.reason,
                  "override with --dialect");
    }
  }
  toolpath_.dialect = dialect_;
}

/// cnc3 numbered its codes differently before: M106 P<guide distance> Q<lower guide height> and
/// M107 P<thickness> (15831944/cnc3 gcode.cpp, GCode::getSettings, commit 4ae9a321), where the
/// current editor writes M100 P Q and M101 P and uses M106/M107 for the generator. M106 with both
/// P and Q exists only in the earlier numbering.
void Interpreter::findLegacyTaperCodes() {
  for (const std::uint32_t k : program_.notPlain) {  // a plain block has no M, P or Q
    const Block& b = program_.blocks[k];
    bool m106 = false, p = false, q = false;
    const Word* at = nullptr;
    for (const Word& w : program_.wordsOf(b)) {
      if (w.letter == 'M' && w.isNumber() && std::lround(w.value) == 106) {
        m106 = true;
        at = &w;
      }
      p |= w.letter == 'P';
      q |= w.letter == 'Q';
    }
    if (m106 && p && q) {
      legacyTaperCodes_ = true;
      diags_.note(Code::MachineCode, src_, at->span(),
                  "M106 with P and Q: this program uses cnc3's earlier numbering, in which M106 P Q gives the wire "
                  "guides (L, H) and M107 P the workpiece thickness (now M100 and M101)");
      return;
    }
  }
}

void Interpreter::indexLabels() {
  // O numbers anywhere; N numbers count as labels too (Sodick puts `N0001 ... M99` after M02).
  for (const std::uint32_t i : program_.notPlain) {  // a plain block has no O or N
    for (const Word& w : program_.wordsOf(program_.blocks[i])) {
      if ((w.letter != 'O' && w.letter != 'N') || !w.isNumber()) continue;
      const long key = std::lround(w.value);
      auto& map = w.letter == 'O' ? oLabels_ : nLabels_;
      if (auto it = map.find(key); it != map.end()) {
        if (w.letter == 'O')
          diags_.warning(Code::DuplicateLabel, src_, w.span(),
                         "program number O" + std::to_string(key) + " appears again; calls go to the first");
        continue;
      }
      map.emplace(key, i);
    }
  }
}

void Interpreter::warnIntegerUnit() {
  if (options_.integerUnit == IntegerUnit::Millimetre && !program_.anyDecimalPoint &&
      program_.largestInteger > machine_.integerThreshold && program_.integerLengthWords > 0) {
    const Word& w = program_.largestIntegerWord;
    diags_.warning(Code::IntegerUnitSuspect, src_, w.span(),
                   "no coordinate has a decimal point and this one is " + formatFixed(w.value, 3) +
                       " mm: the file may be written in micrometres",
                   "if so, run with --integer-unit um");
  }
}

Flow Interpreter::executeBlock(std::size_t pc, std::size_t& next) {
  const Block& block = program_.blocks[pc];
  if (block.kind == BlockKind::MacroB) return Flow::Continue;  // the parser said it once for the file
  if (block.kind == BlockKind::MacroCall) return executeMacroCall(block);
  // Phase 1: read.
  BlockWords bw, ubw;
  if (!readBlock(block, bw, ubw)) return Flow::Continue;
  // Phase 2: fill in.
  const BlockPlan plan = fillIn(block, bw, ubw);
  // Phase 3: check.
  if (!checkBlock(block, bw, ubw, plan)) return Flow::Continue;
  // Phase 4: execute, in the documented order.
  warnIgnoredWords(bw, plan);
  if (const Word* f = bw['F']) takeFeed(*f, plan.inch);
  // The modes and settings a block may change besides its motion: none in most blocks (a motion
  // code, coordinates, a feed), which pass them by with one test.
  const bool settings = (bw.groups & ~(1U << static_cast<unsigned>(ModalGroup::Motion))) != 0 ||
                        dialect_ == Dialect::TaperAngle || bw.cornerRound || bw.cornerChamfer || options_.millTurn ||
                        bw.machineCount > 0;
  if (settings)
    if (const std::optional<Flow> done = executeSettings(bw, ubw, block, plan, pc, next)) return *done;
  holdMotion(bw);
  if (plan.homing && machine_.home && !bw.hasCode(GCode::MachineCoordinates)) {
    returnHome(bw, ubw, block, plan);
  } else if (plan.homing || plan.positionCode) {
    positionGone(bw, plan);
  } else if (plan.unknownValue && !plan.dwell && !plan.setPosition && !plan.noMotion) {
    valueUnknown(*plan.unknownValue, block, plan);
  } else if (!plan.dwell && !plan.setPosition && !plan.noMotion) {
    if (!executeMotion(bw, ubw, block, plan)) return Flow::Continue;
  }
  return executeProgramFlow(bw, pc, next);
}

/// F: the feed from here on, mm/min (an inch program's F is in inches).
void Interpreter::takeFeed(const Word& f, bool inch) {
  if (f.value <= 0)
    diags_.warning(Code::BadFeed, src_, f.span(), "feed F must be positive");
  else
    feed_ = f.value * (inch ? 25.4 : 1.0);
}

/// A move whose coordinate only the machine knows (a register, a macro variable): not drawn, and
/// the wire's position unknown from here.
void Interpreter::valueUnknown(const Word& w, const Block& block, const BlockPlan& plan) {
  const std::string written(program_.source->text().substr(w.offset, w.length));
  positionUnknown(
      "'" + written + "' (" + (w.kind == WordValue::Register ? "a register value" : "a macro variable") + ")",
      w.span());
  skipMove(block, plan.motion != Motion::Rapid);
}

/// A block whose code takes the wire where only the machine knows (G28, G30, a profile's code).
void Interpreter::positionGone(const BlockWords& bw, const BlockPlan& plan) {
  // Fill in sets the code's word with a profile's code; G28 and G30 are the non-modal group's.
  const Word* w = plan.positionCodeWord ? plan.positionCodeWord : bw.group(ModalGroup::NonModal);
  if (!w) return;
  const std::string what =
      plan.positionCode
          ? std::string(program_.source->text().substr(w->offset, w->length)) + " (" + plan.positionCode->note + ")"
          : gName(bw.code(ModalGroup::NonModal)) + " (" + info(bw.code(ModalGroup::NonModal)).meaning + ")";
  positionUnknown(what, w->span());
}

/// The part of executeBlock between the feed and the motion: units, the wire offset, the taper angle,
/// colon mode, G90/G91, the work offset, a corner word that has no move, a mill-turn face block, a
/// polar section, the profile's codes and G92. A flow when the block ends here.
std::optional<Flow> Interpreter::executeSettings(const BlockWords& bw, const BlockWords& ubw, const Block& block,
                                                 const BlockPlan& plan, std::size_t pc, std::size_t& next) {
  if (bw.group(ModalGroup::Units)) {
    inch_ = plan.inch;
    toolpath_.programUnit = inch_ ? LengthUnit::Inch : LengthUnit::Millimetre;
    tolerance_ = inch_ ? geometry::ArcTolerance::forInch() : geometry::ArcTolerance{};
  }
  if (const Word* o = bw.group(ModalGroup::WireOffset)) executeWireOffset(bw, *o);
  if (dialect_ == Dialect::TaperAngle && !executeTaperAngle(bw)) return Flow::Continue;
  if (bw.group(ModalGroup::ColonMode)) colonMode_ = bw.code(ModalGroup::ColonMode) != GCode::ColonOff;
  incremental_ = plan.incremental;
  if (const Word* w = bw.group(ModalGroup::WorkOffset)) {
    if (!warnedWorkOffset_) {
      warnedWorkOffset_ = true;
      diags_.warning(Code::WorkOffsetIgnored, src_, w->span(),
                     gName(bw.code(ModalGroup::WorkOffset)) +
                         " selects a work offset stored in the controller; Kerf takes it as zero");
    }
  }
  const Word* corner = bw.cornerRound ? bw.cornerRound : bw.cornerChamfer;
  const bool moves = !options_.millTurn && !plan.homing && !plan.positionCode && !plan.unknownValue && !plan.dwell &&
                     !plan.setPosition && !plan.noMotion;
  if (corner && !moves)  // executeMotion holds a corner word; no other block can round one
    diags_.error(Code::CornerNotMade, src_, corner->span(),
                 options_.millTurn ? "Kerf does not round or chamfer corners in a mill-turn face program"
                                   : "this block makes no cut move whose corner the word could round");
  if (options_.millTurn) {
    holdMotion(bw);
    executeFaceBlock(bw, block, plan);
    return executeProgramFlow(bw, pc, next);
  }
  if (const Word* p = bw.group(ModalGroup::Polar); p && bw.code(ModalGroup::Polar) == GCode::PolarOn) {
    skipPolarSection(pc, next, *p);
    return Flow::Continue;
  }
  if (bw.machineCount > 0) executeMachineCodes(bw, block);
  if (plan.setPosition && !executeSetPosition(bw, ubw, block)) return Flow::Continue;
  return std::nullopt;
}

void Interpreter::holdMotion(const BlockWords& bw) {
  if (const Word* mw = bw.group(ModalGroup::Motion)) {
    motion_ = motionOf(bw.code(ModalGroup::Motion));
    motionWord_.hold(mw);
  }
}

Flow Interpreter::executeProgramFlow(const BlockWords& bw, std::size_t pc, std::size_t& next) {
  for (std::size_t k = 0; k < bw.mCount; ++k) {
    const Flow f = executeM(*bw.m[k], bw, pc, next);
    if (f == Flow::Stop) return f;
  }
  for (std::size_t k = 0; k < bw.machineCount; ++k)
    if (bw.machine[k].code->effect == CodeEffect::ProgramEnd) {
      toolpath_.endedProperly = true;
      return Flow::Stop;
    }
  return Flow::Continue;
}

}  // namespace kerf::converter::interp

namespace kerf::converter {

Interpretation interpretProgram(const Program& program, const InterpreterOptions& options, Diagnostics& diags) {
  return interp::Interpreter(program, options, diags).run();
}

}  // namespace kerf::converter
