// G and M codes as names: the table of every code Kerf knows under every machine profile, with
// its modal group and what it does (docs/interpreter.md). Codes a single machine knows beyond
// these come from its profile (machine.h).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace kerf::converter {

/// Modal groups: two codes of one group cannot share a block (K0203).
enum class ModalGroup : std::uint8_t {
  Motion,       ///< G00-G03
  NonModal,     ///< G04, G09, G28, G30, G53, G92
  Plane,        ///< G17-G19
  Units,        ///< G20/G21, G70/G71
  WireOffset,   ///< G40-G42
  ToolLength,   ///< G49
  Taper,        ///< G50-G52
  WorkOffset,   ///< G54-G59
  PathControl,  ///< G61, G64
  Distance,     ///< G90/G91
  FeedMode,     ///< G94/G95
  ReturnMode,   ///< G98/G99
  Polar,        ///< G12.1/G13.1 (G112/G113)
  ColonMode,    ///< G140-G142 (Sodick)
  Count
};

enum class GCode : std::uint8_t {
  Rapid,                ///< G00
  Line,                 ///< G01
  ArcClockwise,         ///< G02
  ArcCounterClockwise,  ///< G03
  Dwell,                ///< G04
  ExactStopOnce,        ///< G09
  PolarOn,              ///< G12.1 = G112
  PolarOff,             ///< G13.1 = G113
  PlaneXY,              ///< G17
  PlaneXZ,              ///< G18
  PlaneYZ,              ///< G19
  Inch,                 ///< G20
  Millimetre,           ///< G21
  ReferenceReturn,      ///< G28
  SecondReference,      ///< G30
  OffsetCancel,         ///< G40
  OffsetLeft,           ///< G41
  OffsetRight,          ///< G42
  ToolLengthPlus,       ///< G43
  ToolLengthMinus,      ///< G44
  ToolLengthCancel,     ///< G49
  TaperCancel,          ///< G50
  TaperLeft,            ///< G51
  TaperRight,           ///< G52
  MachineCoordinates,   ///< G53
  WorkOffset1,          ///< G54
  WorkOffset2,          ///< G55
  WorkOffset3,          ///< G56
  WorkOffset4,          ///< G57
  WorkOffset5,          ///< G58
  WorkOffset6,          ///< G59
  ExactStopMode,        ///< G61
  PathBlending,         ///< G64
  InchOld,              ///< G70
  MillimetreOld,        ///< G71
  Absolute,             ///< G90
  Incremental,          ///< G91
  SetPosition,          ///< G92
  FeedPerMinute,        ///< G94
  FeedPerRevolution,    ///< G95
  ReturnInitial,        ///< G98
  ReturnPlane,          ///< G99
  ColonOff,             ///< G140 (Sodick: upper and lower alike)
  ColonOn,              ///< G141 (Sodick: different upper and lower contours)
  ColonOnAlternate,     ///< G142
};

struct GCodeInfo {
  GCode code;
  int number;    ///< G number before the point
  int fraction;  ///< the digit after the point (G12.1: 1), else 0
  ModalGroup group;
  const char* meaning;  ///< one line, for messages and docs
};

/// The code written as `value` (G2, G02, G12.1, G112), or nothing when it is not in the table.
const GCodeInfo* findGCode(double value);
/// A G word's value that names a code of the motion group (G00-G03): what makes a block plain
/// for the parser (program.h) and a second motion word open a block's upper side.
bool isMotionCode(double value);
/// The motion-group code (G00-G03) of a whole code number as written without a point (G01: 1), or
/// nothing when the number names no code of that group.
const GCodeInfo* findWholeMotionCode(std::uint64_t number);
/// Word::motionCode for such a code: 1 + the code, 0 for none (it fits the field's three bits:
/// asserted below; the word's writer masks it to them).
inline unsigned motionCodeBits(const GCodeInfo* g) { return g ? static_cast<unsigned>(g->code) + 1 : 0U; }
/// The code Word::motionCode holds (not 0).
inline GCode codeOfMotionBits(std::uint8_t bits) { return static_cast<GCode>(bits - 1); }
static_assert(static_cast<unsigned>(GCode::ArcCounterClockwise) + 1 < 8, "Word::motionCode has three bits");
/// A G word's value that homes the axes (G28, G30): the axis letters after it may stand bare.
bool isHomingCode(double value);
/// The table of every code, in the order of enum GCode (gcode.cpp).
inline constexpr std::size_t kGCodeCount = static_cast<std::size_t>(GCode::ColonOnAlternate) + 1;
extern const std::array<GCodeInfo, kGCodeCount> kGCodeTable;
inline const GCodeInfo& info(GCode code) { return kGCodeTable[static_cast<std::size_t>(code)]; }
/// "G02", "G12.1".
std::string gName(int number, int fraction = 0);
std::string gName(GCode code);
/// "G60", "G12.1", "M28", "T84": a word's code as profiles and messages name it (the letter alone
/// when the value is no code number).
std::string codeKey(char letter, double value);

namespace detail {
inline constexpr std::uint8_t kNoGCode = 0xFF;
/// kGCodeTable's index of each whole code G0 - G149 (G112 and G113 are G12.1 and G13.1, as Fanuc
/// also writes them), kNoGCode where there is none: a G word's entry in one look.
extern const std::array<std::uint8_t, 150> kWholeGCodes;
bool splitFractionalGNumber(double value, int& number, int& fraction);
const GCodeInfo* findFractionalGCode(int number, int fraction);
}  // namespace detail

/// The number written, split as (number, fraction); false when it is not a whole number or one
/// with a single decimal. Inline, as findGCode(int, int): every G word of a program asks.
inline bool splitGNumber(double value, int& number, int& fraction) {
  // A whole number (nearly every code written): the general rule gives the same.
  if (value >= 0 && value < 1e6 && value == static_cast<double>(static_cast<int>(value))) {
    number = static_cast<int>(value);
    fraction = 0;
    return true;
  }
  return detail::splitFractionalGNumber(value, number, fraction);
}

/// findGCode for a code already split into its number and tenths (splitGNumber).
inline const GCodeInfo* findGCode(int number, int fraction) {
  if (fraction == 0 && static_cast<unsigned>(number) < detail::kWholeGCodes.size()) {
    const std::uint8_t k = detail::kWholeGCodes[static_cast<std::size_t>(number)];
    return k == detail::kNoGCode ? nullptr : &kGCodeTable[k];
  }
  return detail::findFractionalGCode(number, fraction);
}

/// M codes every profile knows.
enum class MCode : std::uint8_t {
  ProgramStop,           ///< M00
  OptionalStop,          ///< M01
  ProgramEnd,            ///< M02
  SpindleOn,             ///< M03 (the hot wire on a foam cutter)
  SpindleReverse,        ///< M04
  SpindleOff,            ///< M05
  FlushingMist,          ///< M07
  FlushingOn,            ///< M08
  FlushingOff,           ///< M09
  ProgramEndRewind,      ///< M30
  CallSubprogram,        ///< M98
  ReturnFromSubprogram,  ///< M99
};
struct MCodeInfo {
  MCode code;
  int number;
  const char* meaning;
};
const MCodeInfo* findMCode(double value);

}  // namespace kerf::converter
