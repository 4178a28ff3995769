// Mill-turn face programs (docs/polar.md, seed 002, FORMATS §5): a program for a lathe's face,
// read by the one interpreter into the Cartesian face plane. Which programs are mill-turn is
// decided here; how they are read is the interpreter's (InterpreterOptions::millTurn).
//
// The face plane is the table's frame at C = 0: the tool at radius r and table angle C is
// r (cos C, sin C) [sourced: seed 002, O31's X64.404 C-115.769 is O30's X-28. Y-29.]. Outside polar
// mode X is a diameter, Y a linear axis, C the table angle in degrees. Inside G12.1/G112 ...
// G13.1/G113 the program is Cartesian in a frame whose x axis passes through the tool when G12.1
// is commanded (FORMATS §5: C is 0 there): X is a radius or a diameter (--polar-x, the profile's
// polar_x), C the virtual linear axis in mm (a diameter on Star machines: the profile's polar_c).
// Z (depth), S, T and most M words do not move the face point.
#pragma once

#include "kerf/converter/nc/program.h"

#include <cstddef>

namespace kerf::converter {

struct MillTurnOptions {
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

}  // namespace kerf::converter
