// Interpreter: Program -> Toolpath.
//
// Each block runs in fixed phases, after LinuxCNC rs274ngc's execute_block order, one source file
// each under converter/src/interpret/ (docs/interpreter.md):
//   1. read      — collect the block's words: one value per letter, G and M codes by modal group
//                  (read_block.cpp)
//   2. fill in   — take what the block leaves out from the modal state: motion, distance mode,
//                  units (fill_in.cpp)
//   3. check     — refuse combinations that cannot mean anything: two motions, R with I J, words
//                  of another dialect, a wire offset started on an arc (check_block.cpp)
//   4. execute   — in this order: feed (F), dwell (G04), plane (G17/18/19), units (G20/21,
//                  G70/71), wire offset (G40/41/42 with D/H), taper (G50/51/52), distance mode
//                  (G90/91), work offset (G54-G59), set position (G92), motion (G00-G03), then
//                  program flow (M00/M01, M98/M99, M02/M30) (execute.cpp, motion.cpp,
//                  program_flow.cpp)
// and every move carries the block it came from. A 4-axis block has two sides (Block::upperFrom):
// the lower side's words build Move::lower, the upper side's Toolpath::upper (upper_side.cpp);
// taper-angle and xyuv-rel programs get their upper (and, with a program plane above the lower
// plane, lower) contours after the last block, once the plane heights are known (heights.cpp,
// taper_offsets.cpp). Codes a machine knows beyond the standard set come from its profile
// (machine_codes.cpp). A mill-turn face program (mill_turn.h) takes the same phases with its own
// words: X/C and polar interpolation on the lathe's face (mill_turn.cpp).
#pragma once

#include "kerf/converter/interpret/machine.h"
#include "kerf/converter/interpret/mill_turn.h"
#include "kerf/converter/nc/diagnostics.h"
#include "kerf/converter/nc/program.h"
#include "kerf/converter/toolpath.h"

#include <array>
#include <cstddef>
#include <optional>

namespace kerf::converter {

struct InterpreterOptions {
  /// The machine's profile; null: the generic profile.
  const MachineProfile* machine = nullptr;
  /// The 4-axis dialect; nothing: detected from the words (dialect.h), with the choice reported.
  std::optional<Dialect> dialect;
  // Plane heights in mm (docs/taper.md); these override what the program says.
  std::optional<double> lowerZ;     ///< --lower-z (default 0)
  std::optional<double> upperZ;     ///< --upper-z
  std::optional<double> thickness;  ///< --thickness: upper - lower
  std::optional<double> programZ;   ///< --program-z: z of the programmed contour
  /// --guides: the wire guides' z, mm, the part's lower face at 0.
  std::optional<std::array<double, 2>> guides;

  IntegerUnit integerUnit = IntegerUnit::Millimetre;
  ArcCentreMode arcCentre = ArcCentreMode::Incremental;
  std::optional<double> wireOffset;  ///< --offset, mm: for a bare G41/G42, or a register no table gives
  /// Registers the program's own table does not give: --offsets FILE's, then the profile's.
  OffsetTable offsets;
  bool blockDelete = true;        ///< skip blocks that start with '/'
  std::size_t maxCallDepth = 16;  ///< M98 nesting
  std::size_t maxExecutedBlocks = 20'000'000;
  std::size_t maxMoves = 10'000'000;
  /// Keep how each arc's centre was written (Toolpath::centreWords, 16 bytes a move): `kerf
  /// explain` shows it; a check does not need it.
  bool recordCentreWords = true;
  /// A mill-turn face program (mill_turn.h): X a diameter and C the table angle, G12.1/G112
  /// polar interpolation; nothing: a wire program.
  std::optional<MillTurnOptions> millTurn;
};

/// How the arcs given by I J close under each convention (for detecting the convention).
struct ArcCentreTally {
  std::size_t arcs = 0;             ///< arcs given by I J (lower side)
  std::size_t closes[3] = {};       ///< of those, how many close as incremental, reversed, absolute
  std::size_t only[3] = {};         ///< of those, how many close that way and no other (evidence that decides)
  std::size_t closeNoWay = 0;       ///< arcs that close no way: errors whatever the convention
  std::uint32_t firstFailLine = 0;  ///< the first arc that failed under the convention in force
};

/// The toolpath, and what the interpreter learnt about the conventions on the way.
struct Interpretation {
  Toolpath toolpath;
  ArcCentreTally arcs;
};

Interpretation interpretProgram(const Program& program, const InterpreterOptions& options, Diagnostics& diags);

/// The toolpath alone.
inline Toolpath interpret(const Program& program, const InterpreterOptions& options, Diagnostics& diags) {
  return interpretProgram(program, options, diags).toolpath;
}

}  // namespace kerf::converter
