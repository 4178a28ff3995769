// Toolpath: what the program makes the wire do, as exact segments, one Move per motion.
#pragma once

#include "kerf/converter/program.h"
#include "kerf/geometry/ruled_surface.h"
#include "kerf/geometry/segment.h"

#include <cstdint>
#include <string>
#include <vector>

namespace kerf::converter {

/// The format a program was read from (read.h).
enum class InputFormat : std::uint8_t {
  Iso,     ///< ISO 6983 G-code, in any machine's dialect
  ThreeB,  ///< Chinese fast-wire 3B code: `B x B y B J G Z`
  Dxf,     ///< a DXF drawing (dxf.h): its contours, not a wire path
  Curve,   ///< a curve (curve.h): an expression or a point list, fitted with biarcs; a drawing too
};

enum class MoveKind : std::uint8_t { Rapid, Line, Arc };

/// How an arc's centre was given in the program.
enum class CentreForm : std::uint8_t { None, Radius, Incremental, Reversed, Absolute };

enum class WireOffset : std::uint8_t { Off, Left, Right };

/// What a move is for the wire offset (Toolpath::offsetRole).
enum class OffsetRole : std::uint8_t {
  None,     ///< not offset: the programmed move
  Element,  ///< the offset of a programmed move (or the part of it the wire reaches)
  Corner,   ///< an arc the wire rolls round a convex corner (no block of its own)
  StartUp,  ///< the move that starts the offset: from the programmed point to the offset path
  Cancel,   ///< the move that cancels it: from the offset path back to the programmed point
};

struct Move {
  // The fields largest first, so the move packs into 128 bytes (it took 192, then 160): 124 bytes
  // of fields, rounded up by the segment's 16-byte alignment. What can be computed from the
  // segment (the arc's radius error) is computed, not stored.
  // The contour on the lower plane. The upper contour of a 4-axis program (Move {lower, upper |
  // none} in the design) lives in Toolpath::upper, parallel to the moves, so 2-axis programs do not
  // pay 80 bytes a move for it.
  geometry::Segment lower;
  /// How the arc's centre was programmed (for `kerf explain`), in mm: I J (or 3B's x y) as written
  /// when centreForm is Incremental, Reversed or Absolute; the signed R in x when it is Radius.
  geometry::Vec2 centreWords{0, 0};
  double feed = 0.0;           ///< mm/min (0: none programmed)
  SourceSpan span;             ///< the block's text
  std::uint32_t line = 0;      ///< 1-based source line of that block
  float taperDegrees = 0.0f;   ///< taper-angle dialect: the angle in force, > 0 leaning left (G51)
  std::uint8_t callDepth = 0;  ///< 0 in the main program (at most 255: calls nest 16 deep)
  MoveKind kind = MoveKind::Line;
  CentreForm centreForm = CentreForm::None;
  WireOffset wireOffset = WireOffset::Off;

  [[nodiscard]] bool isCut() const { return kind != MoveKind::Rapid; }
  /// I J as programmed, mm ((0, 0) when the arc was given by R).
  [[nodiscard]] geometry::Vec2 programmedCentreWords() const {
    return centreForm == CentreForm::Radius ? geometry::Vec2(0, 0) : centreWords;
  }
  /// The signed R as programmed, mm (0 when the centre was given otherwise).
  [[nodiscard]] double programmedRadius() const { return centreForm == CentreForm::Radius ? centreWords.x() : 0.0; }
  /// How far the arc's end lies off its circle: |end - centre| - |start - centre|, mm (0 for a line).
  [[nodiscard]] double radiusError() const { return lower.radiusError(); }
};
static_assert(sizeof(Move) <= 128, "a move is stored for every block: keep it small");

enum class LengthUnit : std::uint8_t { Millimetre, Inch };

/// What coordinates written without a decimal point mean (docs/formats.md).
enum class IntegerUnit : std::uint8_t { Millimetre, Micrometre };

/// How I J give an arc's centre (docs/formats.md).
enum class ArcCentreMode : std::uint8_t {
  Incremental,  ///< centre - start (ISO default)
  Reversed,     ///< start - centre (some Agie/Charmilles/Mitsubishi posts)
  Absolute,     ///< the centre itself (Charmilles Robofil)
};

/// How a program gives its upper contour (docs/taper.md). Plain programs have none: the wire is
/// vertical.
enum class Dialect : std::uint8_t {
  Plain,         ///< 2-axis: no upper contour
  XyuvAbs,       ///< U V: the upper contour, absolute; its own motion word and centre (cnc3)
  XyuvRel,       ///< U V: upper minus lower; K L: lower centre to upper centre
  XyuvLinuxCnc,  ///< U V: the upper contour, absolute; U V move linearly during an XY arc (LinuxCNC)
  SodickColon,   ///< `lower : upper`
  TaperAngle,    ///< G51/G52 with A or T: the upper contour is an offset of the programmed one
  TwoFile,       ///< lower and upper contours from two plain files, paired move by move
};

/// "plain", "xyuv-abs", "xyuv-rel", "xyuv-linuxcnc", "sodick-colon", "taper-angle", "two-file".
const char* dialectName(Dialect d);

/// Where the heights of the planes came from.
struct PlaneHeights {
  geometry::Planes planes;  ///< lower and upper z, mm
  double programZ = 0.0;    ///< z of the programmed contour (taper-angle, xyuv-rel), mm
  bool known = false;       ///< both planes are known (a taper program needs them)
  std::string source;       ///< "M101 P (line 3)", "--thickness", ...
};

/// How the program was read: the machine profile and the conventions in force (machine.h).
struct Reading {
  std::string machine = "generic";
  IntegerUnit integerUnit = IntegerUnit::Millimetre;
  ArcCentreMode arcCentre = ArcCentreMode::Incremental;
};

struct Toolpath {
  std::vector<Move> moves;
  InputFormat format = InputFormat::Iso;
  std::size_t blocks = 0;  ///< blocks (ISO) or records (3B) read
  Reading reading;
  geometry::Vec2 start{0, 0};                       ///< where the wire is before the first move
  LengthUnit programUnit = LengthUnit::Millimetre;  ///< the last G20/G21 in force
  bool endedProperly = false;                       ///< an M02 or M30 was reached
  std::vector<Setting> settings;
  /// Where the wire may be cut and threaded again: the index of the move that follows each M00,
  /// M01 or profile `rethread` code, in order (a rapid between cuts with one beside it goes to a
  /// new start hole).
  std::vector<std::uint32_t> stops;

  Dialect dialect = Dialect::Plain;
  /// The upper contour, one segment per move (same index), or empty for a plain program.
  std::vector<geometry::Segment> upper;
  PlaneHeights heights;

  /// Where G41/G42 were applied (a plain program whose offset value is known): per move, what the
  /// move is for the offset and the programmed segment it came from (the wire-centre path is in
  /// moves). Empty when no offset was applied.
  std::vector<OffsetRole> offsetRole;
  std::vector<geometry::Segment> programmed;

  [[nodiscard]] bool isTaper() const { return !upper.empty(); }
  /// The upper segment of move i: the lower one where the wire is vertical.
  [[nodiscard]] const geometry::Segment& upperOf(std::size_t i) const {
    return upper.empty() ? moves[i].lower : upper[i];
  }
};

}  // namespace kerf::converter
