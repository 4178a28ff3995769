// Interpreter: Program -> Toolpath, for 2-axis ISO wire programs.
//
// Each block runs in fixed phases, after LinuxCNC rs274ngc's execute_block order:
//   1. read      — collect the block's words, one value per letter, G and M codes by group
//   2. fill in   — take what the block leaves out from the modal state (motion, distance, units)
//   3. check     — refuse combinations that cannot mean anything (two motions, R with I J, ...)
//   4. execute   — in this order: feed (F), dwell (G04), plane (G17/18/19), units (G20/21,
//                  G70/71), wire offset (G40/41/42 with D/H), distance mode (G90/91), work offset
//                  (G54-G59), set position (G92), motion (G00-G03), then program flow
//                  (M00/M01, M98/M99, M02/M30)
// and every move carries the block it came from. A 4-axis block has two sides (Block::upperFrom):
// the lower side's words build Move::lower, the upper side's Toolpath::upper; taper-angle and
// xyuv-rel programs get their upper (and, with a program plane above the lower plane, lower)
// contours after the last block, once the plane heights are known.
#pragma once

#include "kerf/converter/diagnostics.h"
#include "kerf/converter/program.h"
#include "kerf/converter/toolpath.h"
#include "kerf/geometry/arc.h"

#include <cstddef>
#include <optional>

namespace kerf::converter {

/// What coordinates written without a decimal point mean (FORMATS.md §1).
enum class IntegerUnit : std::uint8_t { Millimetre, Micrometre };

/// How I J give an arc's centre (FORMATS.md §1).
enum class ArcCentreMode : std::uint8_t {
  Incremental,  ///< centre - start (ISO default)
  Reversed,     ///< start - centre (some Agie/Charmilles/Mitsubishi posts)
  Absolute,     ///< the centre itself
};

struct InterpreterOptions {
  /// The 4-axis dialect; nothing: detected from the words (dialect.h), with the choice reported.
  std::optional<Dialect> dialect;
  // Plane heights in mm (FORMATS.md §2); these override what the program says.
  std::optional<double> lowerZ;     ///< --lower-z (default 0)
  std::optional<double> upperZ;     ///< --upper-z
  std::optional<double> thickness;  ///< --thickness: upper - lower
  std::optional<double> programZ;   ///< --program-z: z of the programmed contour

  IntegerUnit integerUnit = IntegerUnit::Millimetre;
  ArcCentreMode arcCentre = ArcCentreMode::Incremental;
  std::optional<double> wireOffset;  ///< --offset, mm: for a bare G41/G42
  bool blockDelete = true;           ///< skip blocks that start with '/'
  std::size_t maxCallDepth = 16;     ///< M98 nesting
  std::size_t maxExecutedBlocks = 20'000'000;
  std::size_t maxMoves = 10'000'000;
};

Toolpath interpret(const Program& program, const InterpreterOptions& options, Diagnostics& diags);

}  // namespace kerf::converter
