// Toolpath: what the program makes the wire do, as exact segments, one Move per motion.
#pragma once

#include "kerf/converter/program.h"
#include "kerf/geometry/segment.h"

#include <cstdint>
#include <string>
#include <vector>

namespace kerf::converter {

enum class MoveKind : std::uint8_t { Rapid, Line, Arc };

/// How an arc's centre was given in the program.
enum class CentreForm : std::uint8_t { None, Radius, Incremental, Reversed, Absolute };

enum class WireOffset : std::uint8_t { Off, Left, Right };

struct Move {
  MoveKind kind = MoveKind::Line;
  // The contour on the program plane (z = 0). The upper contour of 4-axis programs (DESIGN.md:
  // Move {lower, upper | none}) is added with taper support; 2-axis moves carry none, and a
  // per-move optional would cost 88 bytes on every move of every program, so its storage is
  // left to that change.
  geometry::Segment lower;
  std::uint32_t block = 0;  ///< index into Program::blocks
  std::uint32_t line = 0;   ///< 1-based source line of that block
  SourceSpan span;          ///< the block's text
  // How the geometry followed from the words (for `kerf explain`).
  CentreForm centreForm = CentreForm::None;
  double programmedRadius = 0.0;               ///< signed R as programmed, mm
  geometry::Vec2 programmedCentreWords{0, 0};  ///< I J as programmed, mm
  double radiusError = 0.0;                    ///< |end - centre| - |start - centre|, mm
  double feed = 0.0;                           ///< mm/min (0: none programmed)
  WireOffset wireOffset = WireOffset::Off;
  std::uint16_t callDepth = 0;  ///< 0 in the main program

  [[nodiscard]] bool isCut() const { return kind != MoveKind::Rapid; }
};

enum class LengthUnit : std::uint8_t { Millimetre, Inch };

struct Toolpath {
  std::vector<Move> moves;
  geometry::Vec2 start{0, 0};                       ///< where the wire is before the first move
  LengthUnit programUnit = LengthUnit::Millimetre;  ///< the last G20/G21 in force
  bool endedProperly = false;                       ///< an M02 or M30 was reached
  std::vector<Setting> settings;
};

}  // namespace kerf::converter
