// The structure of a wire program as a shop writes it: contours, each cut from a start hole in
// one or more passes (a rough cut, skims, a cut-off), found from the toolpath's geometry and its
// G41/G42 runs, never from comments (docs/passes.md).
#pragma once

#include "kerf/converter/toolpath.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace kerf::converter {

/// One pass over a contour: from the start hole (or where the last pass left off) along the
/// contour and back. Indices are into Toolpath::moves; every move of a pass is a cut.
struct Pass {
  std::size_t first = 0, end = 0;  ///< its moves [first, end), lead-in and lead-out included
  /// Its moves along the contour itself, [alongFirst, alongEnd): without the lead-in (a first
  /// move from the start hole) and the lead-out (a last move back to it).
  std::size_t alongFirst = 0, alongEnd = 0;
  WireOffset side = WireOffset::Off;  ///< the G41/G42 in force along the contour (Off: none)
  std::string offsetRegister;         ///< "H001" as the program names it; empty: none named
  std::optional<double> offset;       ///< mm, when a table or --offset gives it
  /// +1 counter-clockwise, -1 clockwise (the sign of the area the programmed contour encloses,
  /// closed by its chord when open), 0 when it encloses none.
  int direction = 0;
  bool closes = false;  ///< the programmed contour ends where it starts (within the tolerance)
  /// A cut-off: a later pass, shorter than half of an earlier one that leaves a tab, that runs from
  /// where that pass stopped to where it began — through the tab.
  bool cutOff = false;
  double gap = 0.0;                     ///< mm from its end back to its start: the tab it leaves when it does not close
  double length = 0.0;                  ///< mm of wire path, lead-in and lead-out included
  geometry::Vec2 from{0, 0}, to{0, 0};  ///< where its programmed contour starts and ends, mm
  double alongLength = 0.0;             ///< mm of programmed contour
  std::uint32_t firstLine = 0, lastLine = 0;  ///< the source lines of its first and last moves
  /// The machining condition in force along it (Toolpath::conditions, at its first move along the
  /// contour: "C001"); empty when the program selects none.
  std::string condition;
  /// The cutting-time estimate (structure/cutting_time.h), minutes; nothing when the model cannot
  /// tell (a rough cut of unknown thickness).
  std::optional<double> minutes;
};

/// A start hole and the passes cut from it, in order.
struct Contour {
  geometry::Vec2 startHole{0, 0};  ///< where its first cut starts, mm
  /// Its moves [first, end): the runs of cuts between rapids that start from its hole (the rapids
  /// between them included). A stop without a rapid (M00 before a cut-off) does not end a run.
  std::size_t first = 0, end = 0;
  std::vector<Pass> passes;
};

/// A program's cutting time, minutes (structure/cutting_time.h; docs/passes.md, "Cutting time").
struct TimeEstimate {
  double cutting = 0.0;         ///< the passes that have a time
  double rapids = 0.0;          ///< the rapids, at the profile's rapid speed
  double threading = 0.0;       ///< one threading of the wire a contour
  std::size_t passesTimed = 0;  ///< the passes that have a time
  /// Empty when every pass has a time; else why some have none (then the total is a lower bound).
  std::string missing;
  std::string model;  ///< the speeds taken and where they come from, one line
  [[nodiscard]] double total() const { return cutting + rapids + threading; }
};

struct Structure {
  std::vector<Contour> contours;
  TimeEstimate time;  ///< filled by estimateTime
  /// Some contour is cut in more than one pass (the checks then test each pass alone).
  [[nodiscard]] bool multiPass() const;
};

/// Whether the passes cut the contour free: one closes it, or a cut-off runs through the tab.
bool cutsFree(const Contour& contour);

/// Which side of its programmed contour a pass's wire runs on: +1 inside (G41 along a
/// counter-clockwise contour, G42 along a clockwise one: a die opening), -1 outside (a punch), 0
/// when the pass has no offset side or no direction, or is a cut-off (too short to tell).
int keptSide(const Pass& pass);

/// The contours and passes of a toolpath. A contour is the runs of cuts (between rapids) that
/// start from one start hole; a new pass starts with each run, where a G41/G42 run starts and
/// after a pass that returns to the start hole. Lengths and positions in mm; `tolerance` (mm) says when two points are
/// one.
Structure findStructure(const Toolpath& toolpath, double tolerance);

/// What pass `index` (0 = the first) of its contour is, for a sentence: "the rough cut", "a skim",
/// "the cut-off through the tab".
const char* passRole(const Pass& pass, std::size_t index);

/// "pass 2 of contour 1" (both 0-based in, 1-based out).
std::string passName(std::size_t contour, std::size_t index);

/// Each move's pass number in its contour (1 = the first, the rough cut), 0 for a move in no pass
/// (a rapid, a move before the first cut); one entry for each of a toolpath's `moves` moves.
/// Numbers above 255 read 255.
std::vector<std::uint8_t> movePasses(const Structure& structure, std::size_t moves);

/// The toolpath of one pass number: of every contour its pass `pass` (1 = the rough cut) and every
/// rapid, in program order; where two kept moves do not meet (within `tolerance`, mm), a rapid from
/// the one's end to the other's start joins them, with the later move's place in the source. The
/// per-move data (upper contour, offsets, taper angles, centres as written) follows its moves;
/// stops and offset runs are kept where their moves are. Nothing when no contour has that pass.
std::optional<Toolpath> toolpathOfPass(const Toolpath& toolpath, const Structure& structure, std::size_t pass,
                                       double tolerance);

/// "counter-clockwise", "clockwise" or "neither".
const char* directionName(int direction);
/// A pass's offset as every output says it: "G41 H001 = 0.180 mm", "G41 = 0.150 mm" (a value with
/// no register), "G42 (offset at the machine)", "no offset".
std::string offsetText(const Pass& p);

}  // namespace kerf::converter
