#include "gcode.h"
#include "kerf/converter/nc/program.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>

namespace kerf::converter {
namespace {
using G = GCode;
using MG = ModalGroup;
}  // namespace

// Every code Kerf knows under every profile. Meanings follow RS274/NGC and the wire-EDM usage in
// docs/formats.md; the ones with no effect on the programmed path are marked so.
constexpr std::array<GCodeInfo, kGCodeCount> kGCodeTable = {{
    {G::Rapid, 0, 0, MG::Motion, "rapid positioning (not cut)"},
    {G::Line, 1, 0, MG::Motion, "linear interpolation"},
    {G::ArcClockwise, 2, 0, MG::Motion, "circular interpolation, clockwise"},
    {G::ArcCounterClockwise, 3, 0, MG::Motion, "circular interpolation, counter-clockwise"},
    {G::Dwell, 4, 0, MG::NonModal, "dwell"},
    {G::ExactStopOnce, 9, 0, MG::NonModal, "exact stop for this block: no effect on the programmed path"},
    {G::PolarOn, 12, 1, MG::Polar, "polar coordinate interpolation"},
    {G::PolarOff, 13, 1, MG::Polar, "polar coordinate interpolation cancel"},
    {G::PlaneXY, 17, 0, MG::Plane, "XY plane"},
    {G::PlaneXZ, 18, 0, MG::Plane, "XZ plane"},
    {G::PlaneYZ, 19, 0, MG::Plane, "YZ plane"},
    {G::Inch, 20, 0, MG::Units, "inch"},
    {G::Millimetre, 21, 0, MG::Units, "millimetre"},
    {G::ReferenceReturn, 28, 0, MG::NonModal, "return to the machine's reference point"},
    {G::SecondReference, 30, 0, MG::NonModal, "return to the second reference point"},
    {G::OffsetCancel, 40, 0, MG::WireOffset, "wire offset cancel"},
    {G::OffsetLeft, 41, 0, MG::WireOffset, "wire offset left"},
    {G::OffsetRight, 42, 0, MG::WireOffset, "wire offset right"},
    {G::ToolLengthPlus, 43, 0, MG::ToolLength, "tool length offset (+H): no effect on the wire's path"},
    {G::ToolLengthMinus, 44, 0, MG::ToolLength, "tool length offset (-H): no effect on the wire's path"},
    {G::ToolLengthCancel, 49, 0, MG::ToolLength, "tool length offset cancel: no effect on the programmed path"},
    {G::TaperCancel, 50, 0, MG::Taper, "taper cancel"},
    {G::TaperLeft, 51, 0, MG::Taper, "taper, the wire leaning left of travel"},
    {G::TaperRight, 52, 0, MG::Taper, "taper, the wire leaning right of travel"},
    {G::MachineCoordinates, 53, 0, MG::NonModal, "move in machine coordinates"},
    {G::WorkOffset1, 54, 0, MG::WorkOffset, "work offset 1"},
    {G::WorkOffset2, 55, 0, MG::WorkOffset, "work offset 2"},
    {G::WorkOffset3, 56, 0, MG::WorkOffset, "work offset 3"},
    {G::WorkOffset4, 57, 0, MG::WorkOffset, "work offset 4"},
    {G::WorkOffset5, 58, 0, MG::WorkOffset, "work offset 5"},
    {G::WorkOffset6, 59, 0, MG::WorkOffset, "work offset 6"},
    {G::ExactStopMode, 61, 0, MG::PathControl, "exact stop mode: no effect on the programmed path"},
    {G::PathBlending, 64, 0, MG::PathControl, "path blending: no effect on the programmed path"},
    {G::InchOld, 70, 0, MG::Units, "inch (old form of G20)"},
    {G::MillimetreOld, 71, 0, MG::Units, "millimetre (old form of G21)"},
    {G::Absolute, 90, 0, MG::Distance, "absolute distances"},
    {G::Incremental, 91, 0, MG::Distance, "incremental distances"},
    {G::SetPosition, 92, 0, MG::NonModal, "set the current position"},
    {G::FeedPerMinute, 94, 0, MG::FeedMode, "feed per minute: no effect on the programmed path"},
    {G::FeedPerRevolution, 95, 0, MG::FeedMode, "feed per revolution: no effect on the programmed path"},
    {G::ReturnInitial, 98, 0, MG::ReturnMode,
     "canned-cycle return to the initial level, or feed per minute on a lathe: no effect on the programmed path"},
    {G::ReturnPlane, 99, 0, MG::ReturnMode,
     "canned-cycle return to the R level, or feed per revolution on a lathe: no effect on the programmed path"},
    {G::ColonOff, 140, 0, MG::ColonMode, "upper and lower contours alike (Sodick)"},
    {G::ColonOn, 141, 0, MG::ColonMode, "different upper and lower contours (Sodick)"},
    {G::ColonOnAlternate, 142, 0, MG::ColonMode, "different upper and lower contours (Sodick)"},
}};

namespace {

constexpr std::array<MCodeInfo, 12> kMCodes = {{
    {MCode::ProgramStop, 0, "program stop"},
    {MCode::OptionalStop, 1, "optional stop"},
    {MCode::ProgramEnd, 2, "end of program"},
    {MCode::SpindleOn, 3, "spindle on (the hot wire on a foam cutter): no effect on the path"},
    {MCode::SpindleReverse, 4, "spindle on, reversed: no effect on the path"},
    {MCode::SpindleOff, 5, "spindle off: no effect on the path"},
    {MCode::FlushingMist, 7, "coolant (flushing) mist: no effect on the path"},
    {MCode::FlushingOn, 8, "coolant (flushing) on: no effect on the path"},
    {MCode::FlushingOff, 9, "coolant (flushing) off: no effect on the path"},
    {MCode::ProgramEndRewind, 30, "end of program and rewind"},
    {MCode::CallSubprogram, 98, "call a subprogram"},
    {MCode::ReturnFromSubprogram, 99, "return from a subprogram"},
}};

}  // namespace

namespace detail {

constexpr std::array<std::uint8_t, 150> kWholeGCodes = [] {
  std::array<std::uint8_t, 150> index{};
  index.fill(kNoGCode);
  for (std::size_t k = 0; k < kGCodeTable.size(); ++k)
    if (kGCodeTable[k].fraction == 0 && kGCodeTable[k].number < static_cast<int>(index.size()))
      index[static_cast<std::size_t>(kGCodeTable[k].number)] = static_cast<std::uint8_t>(k);
  // Fanuc writes G12.1 / G13.1 also as G112 / G113.
  for (std::size_t k = 0; k < kGCodeTable.size(); ++k)
    if (kGCodeTable[k].fraction == 1 && (kGCodeTable[k].number == 12 || kGCodeTable[k].number == 13))
      index[static_cast<std::size_t>(kGCodeTable[k].number + 100)] = static_cast<std::uint8_t>(k);
  return index;
}();

bool splitFractionalGNumber(double value, int& number, int& fraction) {
  const long tenths = roundHalfAway(value * 10);
  if (value < 0 || std::abs(value * 10 - static_cast<double>(tenths)) > 1e-6) return false;
  number = static_cast<int>(tenths / 10);
  fraction = static_cast<int>(tenths % 10);
  return true;
}

const GCodeInfo* findFractionalGCode(int number, int fraction) {
  for (const GCodeInfo& g : kGCodeTable)
    if (g.number == number && g.fraction == fraction) return &g;
  return nullptr;
}

}  // namespace detail

std::string codeKey(char letter, double value) {
  std::string key(1, letter);
  int number = 0, fraction = 0;
  if (!splitGNumber(std::abs(value), number, fraction)) return key;
  key += std::to_string(number);
  if (fraction) key += "." + std::to_string(fraction);
  return key;
}

const GCodeInfo* findGCode(double value) {
  int number = 0, fraction = 0;
  if (!splitGNumber(value, number, fraction)) return nullptr;
  return findGCode(number, fraction);
}

bool isMotionCode(double value) {
  const GCodeInfo* g = findGCode(value);
  return g && g->group == ModalGroup::Motion;
}

const GCodeInfo* findWholeMotionCode(std::uint64_t number) {
  if (number >= detail::kWholeGCodes.size()) return nullptr;  // no motion code is that large
  const GCodeInfo* g = findGCode(static_cast<int>(number), 0);
  return g && g->group == ModalGroup::Motion ? g : nullptr;
}

bool isHomingCode(double value) {
  const GCodeInfo* g = findGCode(value);
  return g && (g->code == GCode::ReferenceReturn || g->code == GCode::SecondReference);
}

// The table is in the enum's order, so a code's entry is found by its value.
constexpr bool inEnumOrder() {
  for (std::size_t k = 0; k < kGCodeTable.size(); ++k)
    if (static_cast<std::size_t>(kGCodeTable[k].code) != k) return false;
  return true;
}
static_assert(inEnumOrder(), "kGCodeTable must list the codes in the order of enum GCode");

std::string gName(int number, int fraction) {
  char buf[24];
  if (fraction == 0)
    std::snprintf(buf, sizeof buf, "G%02d", number);
  else
    std::snprintf(buf, sizeof buf, "G%d.%d", number, fraction);
  return buf;
}

std::string gName(GCode code) {
  const GCodeInfo& g = info(code);
  return gName(g.number, g.fraction);
}

const MCodeInfo* findMCode(double value) {
  const long n = std::lround(value);
  if (std::abs(value - static_cast<double>(n)) > 1e-9) return nullptr;
  for (const MCodeInfo& m : kMCodes)
    if (m.number == n) return &m;
  return nullptr;
}

}  // namespace kerf::converter
