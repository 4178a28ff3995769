// Toolpath: what the program makes the wire do, as exact segments, one Move per motion.
#pragma once

#include "kerf/converter/nc/program.h"
#include "kerf/geometry/ruled_surface.h"
#include "kerf/geometry/segment.h"

#include <algorithm>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace kerf::converter {

/// The format a program was read from (read.h).
enum class InputFormat : std::uint8_t {
  Iso,     ///< ISO 6983 G-code, in any machine's dialect
  ThreeB,  ///< Chinese fast-wire 3B code: `B x B y B J G Z`
  Dxf,     ///< a DXF drawing (read_dxf.h): its contours, not a wire path
  Curve,   ///< a curve (read_curve.h): an expression or a point list, fitted with biarcs; a drawing too
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

/// Move::modes: the distance and unit modes in force when the block ran (an ISO program's G91 and
/// G20; 3B is incremental in µm).
enum ModeBit : std::uint8_t { kModeIncremental = 1, kModeInch = 2 };

struct Move {
  // A program holds one move per block, so the move is kept small (the static_assert below). The
  // small fields sit in the segment's tail padding (a [[no_unique_address]] member's padding
  // may hold the members after it); what only some programs or commands need lives beside the
  // moves in the Toolpath: the upper contour, the taper angle, the centre as written, the feeds
  // (Toolpath::feedOf). What can be computed from the segment (the arc's radius, its radius error)
  // is computed, not stored. The small fields are bits, so that the line and the span fit in 72 bytes.
  [[no_unique_address]] geometry::Segment lower;  ///< the contour on the lower plane
  std::uint8_t callDepth : 6 = 0;                 ///< 0 in the main program (kMaxCallDepth at most: calls nest 16 deep)
  std::uint8_t modes : 2 = 0;  ///< the modes in force at the block (ModeBit): what `kerf explain` and the window say
  MoveKind kind : 2 = MoveKind::Line;
  CentreForm centreForm : 3 = CentreForm::None;
  WireOffset wireOffset : 2 = WireOffset::Off;
  std::uint32_t line = 0;  ///< 1-based source line of that block
  SourceSpan span;         ///< the block's text

  /// The deepest call depth a move records (a deeper one records this).
  static constexpr std::size_t kMaxCallDepth = 63;
  /// callDepth = depth, kMaxCallDepth at most (masked too, so that the compiler sees it fit the bits).
  void setCallDepth(std::size_t depth) { callDepth = std::min(depth, kMaxCallDepth) & kMaxCallDepth; }

  [[nodiscard]] bool isCut() const { return kind != MoveKind::Rapid; }
  /// How far the arc's end lies off its circle: |end - centre| - |start - centre|, mm (0 for a line).
  [[nodiscard]] double radiusError() const { return lower.radiusError(); }
};
static_assert(sizeof(Move) <= 72, "a move is stored for every block: keep it small");

/// The moves of a toolpath, in the order the program runs them.
using MoveList = std::vector<Move>;

enum class LengthUnit : std::uint8_t { Millimetre, Inch };

/// What coordinates written without a decimal point mean (docs/formats.md).
enum class IntegerUnit : std::uint8_t { Millimetre, Micrometre };

/// How I J give an arc's centre (docs/formats.md).
enum class ArcCentreMode : std::uint8_t {
  Incremental,  ///< centre - start (ISO default)
  Reversed,     ///< start - centre (some Agie/Charmilles/Mitsubishi posts)
  Absolute,     ///< the centre itself (Charmilles Robofil)
};

/// The I J convention an arc's centre was given in (Incremental for a form that is not I J).
constexpr ArcCentreMode arcCentreOf(CentreForm f) {
  return f == CentreForm::Reversed   ? ArcCentreMode::Reversed
         : f == CentreForm::Absolute ? ArcCentreMode::Absolute
                                     : ArcCentreMode::Incremental;
}

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
  /// The wire guides' heights (the machine's lower and upper guide, or a foam cutter's carriages),
  /// z in the planes' frame, mm: what the axes move (docs/taper.md, "The wire between its guides").
  /// From --guides, cnc3's M100 P Q, or the profile's `guides`; nothing when none gives them.
  std::optional<geometry::Planes> guides;
  std::string guidesSource;
};

/// How the program was read: the machine profile and the conventions in force (machine.h).
struct Reading {
  std::string machine = "generic";
  IntegerUnit integerUnit = IntegerUnit::Millimetre;
  ArcCentreMode arcCentre = ArcCentreMode::Incremental;
};

/// A run of moves cut under one G41/G42 (a side, a register, a value): the moves that start it,
/// carry it and, when the program cancels it with a line, the G40 move that leaves it. Indices are
/// into Toolpath::moves as the checks see them (after the wire offset was applied).
struct OffsetSpan {
  std::uint32_t first = 0;  ///< the move that starts the offset (the G41/G42 block's move)
  std::uint32_t end = 0;    ///< one past the last move under it, the cancelling move included
  WireOffset side = WireOffset::Left;
  std::string offsetRegister;   ///< "H001", "D12" as the program names it; empty: none named
  std::optional<double> value;  ///< mm: the register's value from the program's table or --offset
  bool cancelled = false;       ///< its last move is the G40 line that leaves the offset
};

/// One move with its entry in every table indexed by move (MoveTables): what Toolpath::rowOf reads
/// and Toolpath::replaceMoves writes. An entry of a table the toolpath does not keep is ignored.
struct MoveRow {
  Move move;
  geometry::Segment upper;       ///< the upper plane's segment (a taper program's)
  geometry::Segment programmed;  ///< the programmed segment (where the wire offset was applied)
  OffsetRole offsetRole = OffsetRole::None;
  float taperDegrees = 0.0F;         ///< the taper-angle dialect's angle in force, degrees
  geometry::Vec2 centreWords{0, 0};  ///< I J or R as written (InterpreterOptions::recordCentreWords)
  double feed = 0.0;                 ///< the feed in force, mm/min (0: none programmed): Toolpath::feedChanges
};

/// The tables indexed by move: `moves`, and each of the others either empty (not kept for this
/// program) or holding one entry per move. A table indexed by move is a member here and has its
/// MoveRow field, so that the one operation that rebuilds the moves (Toolpath::replaceMoves)
/// keeps them all aligned; toolpath.cpp asserts the count and toolpath_test checks the alignment.
struct MoveTables {
  MoveList moves;
  /// The upper contour, one segment per move, or empty for a plain program.
  std::vector<geometry::Segment> upper;
  /// Where G41/G42 were applied (a program whose offset value is known): per move, what the move
  /// is for the offset and the programmed segment it came from (the wire-centre path is in
  /// moves). Empty when no offset was applied.
  std::vector<OffsetRole> offsetRole;
  std::vector<geometry::Segment> programmed;
  /// The taper-angle dialect: per move, the angle in force in degrees, > 0 leaning left (G51);
  /// empty for other dialects.
  std::vector<float> taperDegrees;
  /// How each arc's centre was programmed (for `kerf explain`), per move, in mm: I J (or 3B's x y)
  /// as written when centreForm is Incremental, Reversed or Absolute; the signed R in x when it is
  /// Radius. Kept only when asked for (InterpreterOptions::recordCentreWords): empty otherwise.
  std::vector<geometry::Vec2> centreWords;
};

struct Toolpath : MoveTables {
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
  /// The machining conditions the program selects (a profile's `condition` code: Sodick C001), in
  /// order: from move `from` on, `name` is in force (as written, upper case).
  struct ConditionChange {
    std::uint32_t from = 0;
    std::string name;
  };
  std::vector<ConditionChange> conditions;

  Dialect dialect = Dialect::Plain;
  PlaneHeights heights;

  std::vector<OffsetSpan> offsetSpans;  ///< every G41/G42 run, in order (applied or not)

  /// A corner rounded or chamfered at a block's end (`,R r`, `,C c`, NCVC's bare R): the move the
  /// interpreter inserted for it, between the two elements it trimmed.
  struct CornerMade {
    std::uint32_t move = 0;      ///< the fillet (an arc) or the chamfer (a line)
    double size = 0.0;           ///< r or c, mm
    bool chamfer = false;        ///< `,C`
    geometry::Vec2 sharp{0, 0};  ///< where the two elements met (the sharp corner), program plane
  };
  std::vector<CornerMade> corners;  ///< in move order
  /// The corner made as move i, or null.
  [[nodiscard]] const CornerMade* cornerAt(std::size_t i) const;

  /// The feeds programmed: from move `from` on, the feed is `mmPerMinute` (0: none programmed),
  /// in move order, each a change from the one before. Feeds change seldom, so they are kept as
  /// changes, not in every move; replaceMoves keeps them aligned with the moves (MoveRow::feed).
  struct FeedChange {
    std::uint32_t from = 0;
    double mmPerMinute = 0.0;
  };
  std::vector<FeedChange> feedChanges;
  /// From move `from` (the next move appended, or a later one) on, the feed is mmPerMinute (0:
  /// none; a value <= 0 is none).
  void setFeedFrom(std::size_t from, double mmPerMinute) {
    const double feed = mmPerMinute > 0 ? mmPerMinute : 0.0;  // inline: the interpreter asks at every move
    if (feed != (feedChanges.empty() ? 0.0 : feedChanges.back().mmPerMinute)) changeFeedFrom(from, feed);
  }
  /// The feed of move i, mm/min (0: none programmed).
  [[nodiscard]] double feedOf(std::size_t i) const;
  /// The taper angle in force at move i, degrees (taper-angle dialect; 0 otherwise).
  [[nodiscard]] double taperDegreesOf(std::size_t i) const {
    return i < taperDegrees.size() ? static_cast<double>(taperDegrees[i]) : 0.0;
  }
  /// I J as programmed for move i, mm ((0, 0) when the arc was given by R or not recorded).
  [[nodiscard]] geometry::Vec2 programmedCentreWords(std::size_t i) const {
    return i < centreWords.size() && moves[i].centreForm != CentreForm::Radius ? centreWords[i] : geometry::Vec2(0, 0);
  }
  /// The signed R as programmed for move i, mm (0 when the centre was given otherwise or not recorded).
  [[nodiscard]] double programmedRadius(std::size_t i) const {
    return i < centreWords.size() && moves[i].centreForm == CentreForm::Radius ? centreWords[i].x() : 0.0;
  }

  /// Move i with its entry in every table (a table not kept gives the move's own segment for
  /// upper and programmed, OffsetRole::None, 0 and (0, 0)).
  [[nodiscard]] MoveRow rowOf(std::size_t i) const;
  /// Replaces the moves and every table indexed by move with `rows`, and renumbers the lists that
  /// name moves (stops, conditions, offsetSpans, corners): newIndex[i] is the new number of old move
  /// i, newIndex[old count] the new count (an old move that became none maps where the next one
  /// does). A stop that lands on the one before it is dropped, an offset span that had moves and has
  /// none left, and a corner whose move became none. A table is kept when it was (the offset
  /// tables also when `offsetApplied`); the others stay empty.
  void replaceMoves(std::vector<MoveRow>&& rows, const std::vector<std::uint32_t>& newIndex,
                    bool offsetApplied = false);

 private:
  void renumberMoveLists(const std::vector<std::uint32_t>& newIndex);
  void changeFeedFrom(std::size_t from, double feed);  // setFeedFrom's change (feed >= 0)

 public:
  [[nodiscard]] bool isTaper() const { return !upper.empty(); }
  /// The upper segment of move i: the lower one where the wire is vertical.
  [[nodiscard]] const geometry::Segment& upperOf(std::size_t i) const {
    return upper.empty() ? moves[i].lower : upper[i];
  }
};

}  // namespace kerf::converter
