// Phase 1 (read): the block's words into BlockWords — one value per letter, G codes by modal
// group, M codes in order, and the codes the machine profile knows.
#include "interpreter_impl.h"

#include <cmath>

namespace kerf::converter::interp {
namespace {

bool isUpperLetter(char c) {
  return c == 'X' || c == 'Y' || c == 'U' || c == 'V' || c == 'I' || c == 'J' || c == 'R' || c == 'K' || c == 'L';
}

/// The profile's entry for a word's code (G60, T84) or its letter (C); null when it has none.
const KnownCode* profileCode(const MachineProfile& m, const Word& w) {
  if (m.codes.empty()) return nullptr;
  int number = -1, fraction = 0;
  if (!w.isNumber() || !splitGNumber(std::abs(w.value), number, fraction)) number = -1;
  return m.find(w.letter, number, fraction);
}

/// "the robofil profile knows G60 (...): --machine robofil".
std::string profileHint(const std::string& key, const MachineProfile& current) {
  const auto others = machinesKnowing(key, &current);
  if (others.empty()) return {};
  const KnownCode* k = others.front()->find(key);
  std::string names;
  for (const MachineProfile* m : others) names += std::string(names.empty() ? "" : " or ") + "--machine " + m->name;
  return "the " + others.front()->name + " profile knows " + key + " (" + k->note + "): read the program with " + names;
}

}  // namespace

bool Interpreter::splitsBlocks() const {
  return dialect_ == Dialect::XyuvAbs || dialect_ == Dialect::XyuvRel || dialect_ == Dialect::XyuvLinuxCnc ||
         dialect_ == Dialect::SodickColon;
}

void Interpreter::readCodeWord(const Word& w, BlockWords& bw) {
  if (options_.millTurn && readFaceWord(w)) return;
  auto addMachine = [&](const KnownCode* k) {
    if (bw.machineCount == bw.machine.size()) {
      diags_.error(Code::TooManyMCodes, src_, w.span(),
                   "more than " + std::to_string(bw.machine.size()) + " machine codes in one block");
      bw.bad = true;
      return;
    }
    bw.machine[bw.machineCount++] = {&w, k};
  };
  if (w.corner) {
    const Word*& slot = w.letter == 'R' ? bw.cornerRound : bw.cornerChamfer;
    if (slot || (w.letter == 'R' ? bw.cornerChamfer : bw.cornerRound)) {
      diags_.error(Code::RepeatedWord, src_, w.span(), "a block rounds or chamfers its corner once: one ,R or ,C");
      bw.bad = true;
      return;
    }
    slot = &w;
    return;
  }
  if (w.letter == 'G') {
    int number = 0, fraction = 0;
    if (!w.isNumber() || !splitGNumber(w.value, number, fraction)) {
      diags_.error(Code::UnknownGCode, src_, w.span(), "G code must be a whole number or have one decimal");
      bw.bad = true;
      return;
    }
    if (const KnownCode* k = machine_.codes.empty() ? nullptr : machine_.find('G', number, fraction);
        k && k->number >= 0) {  // the profile's meaning wins
      addMachine(k);
      return;
    }
    const GCodeInfo* gi = findGCode(number, fraction);
    if (!gi) {
      const std::string_view raw = src_->text().substr(w.offset, w.length);
      diags_.error(Code::UnknownGCode, src_, w.span(),
                   "unknown G code " + std::string(raw) +
                       (machine_.name == "generic" ? std::string{} : " (the " + machine_.name + " profile)"),
                   profileHint(codeKey('G', w.value), machine_));
      bw.bad = true;
      return;
    }
    if (bw.group(gi->group)) {
      diags_.error(
          Code::ModalGroupConflict, src_, w.span(),
          gName(gi->code) + " and " + gName(bw.code(gi->group)) + " are in the same group and cannot share a block");
      bw.bad = true;
      return;
    }
    bw.setGroup(gi->group, &w, gi->code);
    return;
  }
  if (w.letter == 'M') {
    if (const KnownCode* k = profileCode(machine_, w); k && k->number >= 0) {
      addMachine(k);
      return;
    }
    if (bw.mCount == bw.m.size()) {
      diags_.error(Code::TooManyMCodes, src_, w.span(),
                   "more than " + std::to_string(bw.m.size()) + " M codes in one block");
      bw.bad = true;
      return;
    }
    bw.m[bw.mCount++] = &w;
    return;
  }
  // In a taper-angle program A and T are the angle (execute.cpp), whatever else a profile says.
  const bool taperAngleWord = (w.letter == 'A' || w.letter == 'T') && dialect_ == Dialect::TaperAngle;
  // In a face program C is the table's axis, whatever a profile says C is.
  const bool faceAxis = options_.millTurn && w.letter == 'C';
  if (profileMayName(w.letter) && !taperAngleWord && !faceAxis) {
    if (const KnownCode* k = profileCode(machine_, w)) {
      addMachine(k);
      return;
    }
  }
  if (bw.has(w.letter)) {
    diags_.error(Code::RepeatedWord, src_, w.span(),
                 std::string("word '") + w.letter + "' appears twice on the same side of the block");
    bw.bad = true;
    return;
  }
  bw.setLetter(w.letter, &w);
}

/// In a two-sided dialect the upper side's coordinates and motion word go to ubw; every other word
/// (F, M, modal G codes) belongs to the block as a whole.
bool Interpreter::readBlock(const Block& block, BlockWords& bw, BlockWords& ubw) {
  const auto words = words_.words(block);
  const bool split = block.upperFrom < words.size() && splitsBlocks();
  for (std::size_t k = 0; k < words.size(); ++k) {
    const Word& w = words[k];
    const bool upperSide =
        split && k >= block.upperFrom && (isUpperLetter(w.letter) || (w.letter == 'G' && isMotionCode(w.value)));
    readWord(w, upperSide ? ubw : bw);
  }
  return !bw.bad && !ubw.bad;
}

}  // namespace kerf::converter::interp
