// The mill-turn reader (docs/polar.md): X/C face programs and G12.1/G112 polar interpolation, read
// into the Cartesian face plane.
#pragma once

#include "kerf/converter/nc/diagnostics.h"
#include "kerf/converter/nc/program.h"
#include "kerf/converter/toolpath.h"

#include <cstddef>
#include <string>

namespace kerf::converter {

struct MillTurnOptions {
  std::string machine = "fanuc";      ///< the profile's name, for the summary
  bool polarXDiameter = false;        ///< X inside G12.1 is a diameter (--polar-x diameter)
  bool polarCDiameter = false;        ///< C inside G12.1 is a diameter (Star machines)
  bool polarFrameTable = false;       ///< the G12.1 frame is the table's at C 0, not turned with C (--polar-frame)
  double spiralTolerance = 1e-4;      ///< mm: X/C cutting moves drawn as arcs this close to the machine's spiral
  std::size_t spiralBudget = 100000;  ///< pieces per X/C move at most (a C far off is refused, not expanded)
};

/// The program uses polar coordinate interpolation (G12.1 or G112).
bool isMillTurnProgram(const Program& program);
/// Some block moves X and C together without Y (an explicit X/C face program, seed 002's O31), or
/// homes the table (`G28 C0.`, seed 002's O30): a mill-turn lathe, where X is a diameter.
bool hasRotaryMoves(const Program& program);

/// Reads a mill-turn face program (docs/polar.md) into the Cartesian face plane: X/C moves outside
/// polar mode (X a diameter, C the table angle; a C step longer than the shortest way is an error,
/// K0237), Cartesian X/C inside G12.1/G112 ... G13.1/G113. Z (depth), S, T, M words do not move
/// the face point. Macro B statements are left to the parser's diagnostics.
Toolpath readMillTurn(const Program& program, const MillTurnOptions& options, Diagnostics& diags);

}  // namespace kerf::converter
