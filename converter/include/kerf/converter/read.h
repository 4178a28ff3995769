// Readers by format: the format is detected from the content, and every reader yields a Toolpath
// whose moves carry the span of the text they came from (docs/formats.md, docs/3b.md).
//
//   ISO G-code ──parse──▶ Program ──interpret──▶ Toolpath      (pipeline.h: machine profiles)
//   3B code    ──readThreeB──────────────────▶ Toolpath      (one Move per record)
//
// What follows the reader (checks, summary, explain, pictures, emitters) takes the source and the
// Toolpath, so a 3B file gets the same treatment as a G-code file.
#pragma once

#include "kerf/converter/diagnostics.h"
#include "kerf/converter/program.h"
#include "kerf/converter/source.h"
#include "kerf/converter/toolpath.h"

#include <optional>
#include <string>
#include <string_view>

namespace kerf::converter {

/// "iso", "3b".
const char* inputFormatName(InputFormat f);
/// "iso" | "3b" (any case); nothing for another name.
std::optional<InputFormat> parseInputFormat(std::string_view name);

struct FormatDetection {
  InputFormat format = InputFormat::Iso;
  std::string why;  ///< "the first record, B9900 B0 B9900 GX L3, is 3B code" (empty for ISO)
};

/// The format of a text, from its content: 3B when the first thing that is not blank or a `;`
/// comment is a B field and the text holds a count direction (GX or GY); ISO otherwise.
FormatDetection detectFormat(std::string_view text);

struct ThreeBOptions {
  geometry::Vec2 start{0, 0};  ///< where the first record starts (3B is relative), mm
};

/// Reads 3B code (docs/3b.md): records `B x B y B J G Z` token by token, with or without line
/// breaks between them, any spacing, empty fields (0), lower case, `;` comments to the end of the
/// line, and `DD` or `FF` as the end. A malformed record is an error at its line and column and
/// moves nothing; reading goes on at the next line. The result's blocks count the records.
Toolpath readThreeB(const SourceFile& source, const ThreeBOptions& options, Diagnostics& diags);

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
