// Program flow: M codes, subprogram calls (M98 P L) and returns (M99).
#include "interpreter_impl.h"

#include <cmath>

namespace kerf::converter::interp {

Flow Interpreter::executeM(const Word& m, const BlockWords& bw, std::size_t pc, std::size_t& next) {
  const MCodeInfo* info = findMCode(m.value);
  if (!info) {
    const long code = std::lround(m.value);
    if (warnedM_.insert(code).second) {
      const std::string key = "M" + std::to_string(code);
      std::string help;
      if (const auto others = machinesKnowing(key, &machine_); !others.empty())
        help = "the " + others.front()->name + " profile knows " + key + " (" + others.front()->find(key)->note +
               "): read the program with --machine " + others.front()->name;
      diags_.warning(Code::UnknownMCode, src_, m.span(),
                     key + " is a machine function Kerf does not know; it has no effect on the path", help);
    }
    return Flow::Continue;
  }
  switch (info->code) {
    case MCode::ProgramEnd:
    case MCode::ProgramEndRewind: toolpath_.endedProperly = true; return Flow::Stop;
    case MCode::CallSubprogram: return call(m, bw, pc, next);
    case MCode::ReturnFromSubprogram:
      if (stack_.empty()) {
        diags_.warning(Code::ReturnOutsideSubprogram, src_, m.span(), "M99 in the main program ends it here");
        toolpath_.endedProperly = true;
        return Flow::Stop;
      }
      if (--stack_.back().remaining > 0) {
        next = stack_.back().start;
      } else {
        next = stack_.back().returnTo;
        stack_.pop_back();
      }
      return Flow::Continue;
    case MCode::ProgramStop:
    case MCode::OptionalStop:  // the operator may cut and thread the wire here
      toolpath_.stops.push_back(static_cast<std::uint32_t>(toolpath_.moves.size()));
      return Flow::Continue;
    default: return Flow::Continue;  // spindle (hot wire), flushing: the wire path goes on
  }
}

Flow Interpreter::call(const Word& m, const BlockWords& bw, std::size_t pc, std::size_t& next) {
  const Word* p = bw['P'];
  if (!p) {
    diags_.error(Code::CallWithoutProgram, src_, m.span(), "M98 needs the subprogram number in P");
    return Flow::Continue;
  }
  const long label = std::lround(p->value);
  long repeats = 1;
  if (const Word* l = bw['L']) {
    repeats = std::lround(l->value);
    if (!l->isNumber() || repeats < 1 || repeats > 9999 || std::abs(l->value - static_cast<double>(repeats)) > 1e-9) {
      diags_.error(Code::BadRepeatCount, src_, l->span(), "repeat count L must be a whole number from 1 to 9999");
      return Flow::Continue;
    }
  }
  std::size_t target = 0;
  if (const std::optional<std::size_t> found = findSubprogram(label, pc)) {
    target = *found;
  } else {
    std::string help;
    long best = -1;
    for (const auto& [k, v] : oLabels_)
      if (best < 0 || std::abs(k - label) < std::abs(best - label)) best = k;
    if (best >= 0) help = "the nearest program number is O" + std::to_string(best);
    diags_.error(Code::SubprogramNotFound, src_, p->span(),
                 "no subprogram O" + std::to_string(label) + " or N" + std::to_string(label) + " in this file", help);
    return Flow::Continue;
  }
  if (stack_.size() >= options_.maxCallDepth) {
    diags_.error(Code::CallTooDeep, src_, m.span(),
                 "subprogram calls nest deeper than " + std::to_string(options_.maxCallDepth) + " levels (recursion?)");
    return Flow::Stop;
  }
  // A repeat bomb (M98 P1 L9999 calling M98 P2 L9999 ...) is refused before it expands: the blocks
  // the call would run, counted from the text, must fit the budget that is left.
  const std::uint64_t budget = options_.maxExecutedBlocks;
  const std::uint64_t once = blocksOfCall(target, budget + 1, 1);
  const std::uint64_t total = once > (budget + 1) / static_cast<std::uint64_t>(repeats)
                                  ? budget + 1
                                  : once * static_cast<std::uint64_t>(repeats);
  if (executed_ + total > budget) {
    diags_.error(Code::ExecutionLimit, src_, m.span(),
                 "this call would run " +
                     (total > budget ? "more than " + std::to_string(budget) : std::to_string(total)) + " blocks (" +
                     std::to_string(repeats) + " times a subprogram of " +
                     (once > budget ? "more than " + std::to_string(budget) : std::to_string(once)) +
                     " blocks with its own calls), beyond the limit of " + std::to_string(budget) +
                     " executed blocks: refused before it runs",
                 "a repeat count L multiplies every call inside the subprogram");
    return Flow::Stop;
  }
  stack_.push_back({pc + 1, target, repeats, pc});
  next = target;
  return Flow::Continue;
}

std::optional<std::size_t> Interpreter::findSubprogram(long label, std::size_t callingBlock) const {
  if (auto it = oLabels_.find(label); it != oLabels_.end()) return it->second;
  if (auto jt = nLabels_.find(label); jt != nLabels_.end() && jt->second != callingBlock) return jt->second;
  return std::nullopt;
}

std::uint64_t Interpreter::blocksOfCall(std::size_t target, std::uint64_t cap, std::size_t depth) {
  if (auto it = blocksOfCall_.find(target); it != blocksOfCall_.end()) return std::min(it->second, cap);
  // Deeper than calls may nest: the run stops there anyway (K0504), so count nothing more.
  if (depth > options_.maxCallDepth) return 0;
  std::uint64_t count = 0;
  for (std::size_t pc = target; pc < program_.blocks.size() && count < cap; ++pc) {
    ++count;
    if (program_.blocks[pc].plain) continue;  // no M word
    const std::span<const Word> words = program_.wordsOf(program_.blocks[pc]);
    bool returns = false;
    for (const Word& w : words) {
      if (w.letter != 'M' || !w.isNumber()) continue;
      const long code = std::lround(w.value);
      if (code == 99 || code == 2 || code == 30) returns = true;
      if (code != 98) continue;
      long label = -1, repeats = 1;
      for (const Word& a : words) {
        if (a.letter == 'P' && a.isNumber()) label = std::lround(a.value);
        if (a.letter == 'L' && a.isNumber()) repeats = std::clamp(std::lround(a.value), 1L, 9999L);
      }
      const std::optional<std::size_t> callee = findSubprogram(label, pc);
      if (!callee || *callee == target) continue;  // not found, or recursion: reported when it runs
      const std::uint64_t inner = blocksOfCall(*callee, cap, depth + 1);
      const auto r = static_cast<std::uint64_t>(repeats);
      count = inner > (cap - count) / r ? cap : count + inner * r;
    }
    if (returns) break;
  }
  count = std::min(count, cap);
  if (count < cap) blocksOfCall_[target] = count;  // a capped count depends on the cap
  return count;
}

}  // namespace kerf::converter::interp
