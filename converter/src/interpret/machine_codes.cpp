// Codes the machine profile knows beyond the standard set (machine.h), Sodick macro calls, the
// polar section Kerf does not read, and the wire's position where only the machine knows it.
#include "interpreter_impl.h"

#include <cmath>

namespace kerf::converter::interp {
namespace {

std::string written(const SourceFile* src, const Word& w) {
  return std::string(src->text().substr(w.offset, w.length));
}

/// A condition's name as the pass table shows it: the word as written, upper case ("c001": "C001").
std::string conditionName(std::string word) {
  for (char& c : word)
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  return word;
}

}  // namespace

bool Interpreter::recordGuides(const BlockWords& bw, const Block& block, const std::string& code) {
  const Word* p = bw['P'];
  const Word* q = bw['Q'];
  if (!p || !q || !p->isNumber() || !q->isNumber()) return false;
  const std::string where = " on line " + std::to_string(lineOf(block));
  fileGuideSpacing_ = Height{length(*p), code + " P" + where};
  fileGuideBelow_ = Height{length(*q), code + " Q" + where};
  return true;
}

void Interpreter::executeMachineCodes(const BlockWords& bw, const Block& block) {
  for (std::size_t k = 0; k < bw.machineCount; ++k) {
    const Word& w = *bw.machine[k].word;
    const KnownCode& code = *bw.machine[k].code;
    const std::string key = w.isNumber() ? codeKey(w.letter, w.value) : std::string(1, w.letter);
    const std::string as = written(src_, w);
    CodeEffect effect = code.effect;
    // cnc3's earlier numbering: M106 P L Q H gave the guides (said once, with the numbering) and
    // M107 P T the thickness.
    if (legacyTaperCodes_ && key == "M106") {  // the guides, said with the numbering (interpreter.cpp)
      recordGuides(bw, block, as);
      continue;
    }
    if (legacyTaperCodes_ && key == "M107") effect = CodeEffect::Thickness;
    switch (effect) {
      case CodeEffect::Guides: {
        // P the guides' spacing L, Q the lower guide below the work's lower face H: the guides at
        // (-H, L - H) above it (papayaved/cnc3: uv_sizing_widget.cpp names them L and H).
        const Word* p = bw['P'];
        const Word* q = bw['Q'];
        const bool given = recordGuides(bw, block, as);
        if (notedCodes_.insert(key).second)
          diags_.note(Code::MachineCode, src_, w.span(),
                      given ? as + ": " + code.note + ": the guides " + formatFixed(length(*p), 3) +
                                  " mm apart, the lower " + formatFixed(length(*q), 3) + " mm below the work [" +
                                  machine_.name + " profile]"
                            : as +
                                  " without P and Q gives no guide geometry (older cnc3 programs write it alone, "
                                  "as 'Apply') [" +
                                  machine_.name + " profile]");
        break;
      }
      case CodeEffect::Rethread:
        toolpath_.stops.push_back(static_cast<std::uint32_t>(toolpath_.moves.size()));
        if (notedCodes_.insert(key).second)
          diags_.note(Code::MachineCode, src_, w.span(), as + ": " + code.note + " [" + machine_.name + " profile]");
        break;
      case CodeEffect::Condition:
        toolpath_.conditions.push_back({static_cast<std::uint32_t>(toolpath_.moves.size()), conditionName(as)});
        if (notedCodes_.insert(std::string(1, w.letter)).second)
          diags_.note(Code::MachineCode, src_, w.span(), as + ": " + code.note + " [" + machine_.name + " profile]");
        break;
      case CodeEffect::Harmless:
      case CodeEffect::NoMotion:
        if (notedCodes_.insert(key).second)
          diags_.note(Code::MachineCode, src_, w.span(), as + ": " + code.note + " [" + machine_.name + " profile]");
        break;
      case CodeEffect::NotModelled:
        if (notedCodes_.insert(key).second)
          diags_.warning(Code::CodeNotModelled, src_, w.span(),
                         as + ": " + code.note +
                             ": Kerf does not model it, so the geometry, the checks and the "
                             "picture do not show what it changes [" +
                             machine_.name + " profile]");
        break;
      case CodeEffect::Thickness:
        if (const Word* p = bw['P']; p && p->isNumber()) {
          setHeight(fileThickness_, length(*p), (key + " P").c_str(), lineOf(block));
        } else {
          diags_.warning(Code::ParameterMissing, src_, w.span(),
                         as + " sets the workpiece thickness with P, and has none");
        }
        break;
      case CodeEffect::CornerEqual:
      case CodeEffect::CornerConicalMin:
      case CodeEffect::CornerConicalMean:
      case CodeEffect::CornerConicalMax:
      case CodeEffect::CornerRounded:
      case CodeEffect::CornerCylindrical:
        // The model of the corners words make, or what the program's own corners and arcs become.
        (effect == CodeEffect::CornerRounded || effect == CodeEffect::CornerCylindrical ? programCorners_
                                                                                        : taperCorner_) = effect;
        if (notedCodes_.insert(key).second)
          diags_.note(Code::MachineCode, src_, w.span(), as + ": " + code.note + " [" + machine_.name + " profile]");
        break;
      case CodeEffect::Position:    // executeBlock: the wire goes where only the machine knows
      case CodeEffect::ProgramEnd:  // executeBlock: after the motion, as M02
        break;
    }
  }
}

Flow Interpreter::executeMacroCall(const Block& block) {
  const std::string_view text = program_.textOf(block);
  std::string name = "Q";
  for (std::size_t k = 1; k < text.size() && text[k] != '('; ++k)
    name += static_cast<char>(text[k] >= 'a' && text[k] <= 'z' ? text[k] - 'a' + 'A' : text[k]);
  const KnownCode* code = machine_.find(name);
  const std::string call(text.substr(0, text.find(')') + 1));
  if (!code) {
    std::string help;
    if (const auto others = machinesKnowing(name, &machine_); !others.empty())
      help = "the " + others.front()->name + " profile knows " + name + " (" + others.front()->find(name)->note +
             "): read the program with --machine " + others.front()->name;
    positionUnknown("the macro call " + call + " (its moves are stored in the controller, and the " + machine_.name +
                        " profile does not know it)",
                    block.span(), help);
    return Flow::Continue;
  }
  switch (code->effect) {
    case CodeEffect::Position: positionUnknown(call + " (" + code->note + ")", block.span()); break;
    case CodeEffect::NotModelled:
      if (notedCodes_.insert(name).second)
        diags_.warning(Code::CodeNotModelled, src_, block.span(),
                       call + ": " + code->note + ": Kerf does not model it [" + machine_.name + " profile]");
      break;
    case CodeEffect::ProgramEnd: toolpath_.endedProperly = true; return Flow::Stop;
    default:
      if (notedCodes_.insert(name).second)
        diags_.note(Code::MachineCode, src_, block.span(),
                    call + ": " + code->note + " [" + machine_.name + " profile]");
      break;
  }
  return Flow::Continue;
}

void Interpreter::positionUnknown(std::string cause, SourceSpan span, std::string help, bool silent) {
  if (unknown_.active) return;  // one diagnostic for the whole stretch
  unknown_ = UnknownPosition{};
  unknown_.active = true;
  unknown_.cause = std::move(cause);
  unknown_.span = span;
  unknown_.help = std::move(help);
  unknown_.silent = silent;
}

void Interpreter::returnHome(const BlockWords& bw, const BlockWords& ubw, const Block& block, const BlockPlan& plan) {
  const bool upperAbsolute =
      dialect_ == Dialect::XyuvAbs || dialect_ == Dialect::XyuvLinuxCnc || dialect_ == Dialect::SodickColon;
  auto named = [&](char c) { return bw.has(c) || ubw.has(c); };
  // The intermediate point, where the words move the wire at all: a bare letter (`G28 X Y`) only
  // names an axis, and under G91 X0 Y0 stays where it is.
  bool through = false;
  for (char c : {'X', 'Y', 'U', 'V'})
    for (const BlockWords* side : {&bw, &ubw})
      if (const Word* w = (*side)[c]; w && w->isNumber()) through |= !plan.incremental || w->value != 0.0;
  if (through && !unknown_.active) {
    const Motion held = motion_;
    motion_ = Motion::Rapid;
    executeMotion(bw, ubw, block, plan);
    motion_ = held;
  }
  const bool all = !plan.lowerWords && !plan.upperWords;
  const Vec2 home((*machine_.home)[0], (*machine_.home)[1]);
  Vec2 lowerEnd = position_, upperEnd = upperAbsolute ? upperPosition_ : position_;
  if (all || named('X')) lowerEnd.x() = home.x();
  if (all || named('Y')) lowerEnd.y() = home.y();
  if (upperAbsolute) {
    if (all || named('U')) upperEnd.x() = home.x();
    if (all || named('V')) upperEnd.y() = home.y();
  } else {
    upperEnd = lowerEnd;
  }
  if (!notedHome_) {
    notedHome_ = true;
    const Word* w = bw.group(ModalGroup::NonModal);
    diags_.note(Code::HomePositionTaken, src_, w ? w->span() : block.span(),
                gName(bw.code(ModalGroup::NonModal)) + " goes to the machine's home, taken as (" +
                    formatFixed(home.x(), 3) + ", " + formatFixed(home.y(), 3) +
                    ") in the frame the program starts in: drawn as a rapid, and the path after it from there",
                "the profile's `home = X, Y` says where it is; `home = unknown` leaves the position to the machine");
  }
  const Vec2 upperStart = upperAbsolute ? upperPosition_ : position_;
  if (unknown_.active) positionKnownAgain(block);  // the home is a known place
  if ((lowerEnd - position_).norm() > 1e-12 || (upperEnd - upperStart).norm() > 1e-12) {
    Move move;
    move.line = lineOf(block);
    move.span = block.span();
    move.kind = MoveKind::Rapid;
    move.wireOffset = wireOffset_;
    move.setCallDepth(stack_.size());
    move.lower = Segment::line(position_, lowerEnd);
    push(std::move(move), Segment::line(upperStart, upperEnd));
  }
  position_ = lowerEnd;
  upperPosition_ = upperEnd;
}

void Interpreter::skipMove(const Block& block, bool cut) {
  ++unknown_.skippedMoves;
  if (cut) ++unknown_.skippedCuts;
  unknown_.lastSkippedLine = lineOf(block);
  if (unknown_.firstSkippedLine == 0) unknown_.firstSkippedLine = unknown_.lastSkippedLine;
}

void Interpreter::positionKnownAgain(const Block& block) { flushUnknown(&block); }

void Interpreter::flushUnknown(const Block* knownAgain) {
  if (!unknown_.active) return;
  const UnknownPosition u = unknown_;
  unknown_ = UnknownPosition{};
  if (u.silent && u.skippedCuts == 0) return;
  std::string message = u.cause + ": the wire's position after it is known only at the machine";
  if (u.skippedMoves > 0) {
    message += "; the " + std::to_string(u.skippedMoves) + (u.skippedMoves == 1 ? " move" : " moves") + " on line" +
               (u.firstSkippedLine == u.lastSkippedLine
                    ? " " + std::to_string(u.firstSkippedLine)
                    : "s " + std::to_string(u.firstSkippedLine) + " to " + std::to_string(u.lastSkippedLine)) +
               " (" + std::to_string(u.skippedCuts) + " cut) cannot be drawn or checked";
  }
  message += knownAgain ? "; line " + std::to_string(lineOf(*knownAgain)) + " gives it again"
                        : "; it stays unknown to the end of the program";
  std::string help = u.help;
  if (help.empty() && u.skippedCuts > 0)
    help = "give the position before the cut with G92 X Y or an absolute move with X and Y";
  Diagnostic d;
  d.severity = u.skippedCuts > 0 ? Severity::Error : Severity::Note;
  d.code = Code::PositionUnknown;
  d.source = src_;
  d.span = u.span;
  d.message = std::move(message);
  d.help = std::move(help);
  diags_.report(std::move(d));
}

bool Interpreter::skipPolarSection(std::size_t pc, std::size_t& next, const Word& polarWord) {
  // The section runs to G13.1 (G113); without one, to the program's end (M02/M30 still end it).
  std::size_t end = program_.blocks.size();
  bool cancelled = false;
  std::string cancelWord = "G13.1";
  for (std::size_t k = pc + 1; k < program_.blocks.size() && end == program_.blocks.size(); ++k) {
    if (program_.blocks[k].plain) continue;  // no G13.1, M02 or M30
    for (const Word& w : program_.wordsOf(program_.blocks[k])) {
      if (w.letter == 'G' && w.isNumber()) {
        if (const GCodeInfo* g = findGCode(w.value); g && g->code == GCode::PolarOff) {
          end = k + 1;
          cancelled = true;
          cancelWord = written(src_, w);
          break;
        }
      }
      if (w.letter == 'M' && w.isNumber() && (std::lround(w.value) == 2 || std::lround(w.value) == 30)) {
        end = k;
        break;
      }
    }
  }
  const std::string what = written(src_, polarWord);
  std::string message = what + " (polar coordinate interpolation, X and C words) is not supported yet: ";
  if (cancelled)
    message += "the blocks up to " + cancelWord + " on line " + std::to_string(lineOf(program_.blocks[end - 1])) +
               " are not read";
  else if (end > pc + 1)
    message += "the blocks from here to line " + std::to_string(lineOf(program_.blocks[end - 1])) +
               " are not read (no G13.1 follows)";
  else
    message += "no G13.1 follows it";
  diags_.error(Code::PolarNotSupported, src_, polarWord.span(), message,
               "Kerf reads X Y programs: write the section with X and Y to have it checked");
  next = end;
  positionUnknown(
      "the polar section (" + what + " on line " + std::to_string(src_->locate(polarWord.offset).line) + ")",
      polarWord.span(), {}, true);
  return true;
}

}  // namespace kerf::converter::interp
