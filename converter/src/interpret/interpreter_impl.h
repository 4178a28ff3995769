// The interpreter's state and its phases (interpreter.h gives the order). One class, its member
// functions defined by phase in the files of this folder:
//   interpreter.cpp    the block loop, limits, labels; phase 4's order (feed, units, distance,
//                      work offset there); the end of the program
//   read_block.cpp     phase 1: words -> BlockWords
//   fill_in.cpp        phase 2: BlockWords + modal state -> BlockPlan
//   check_block.cpp    phase 3: what cannot mean anything
//   execute.cpp        phase 4: words no code reads, G92, the taper angle (G50-G52 with A or T)
//   motion.cpp         phase 4: the motion, arcs from R or I J
//   corner.cpp         phase 4: the corner at a block's end (,R ,C), made when the next move comes
//   upper_side.cpp     the upper side of a 4-axis move, by dialect
//   wire_offset.cpp    G40/G41/G42 with D/H
//   program_flow.cpp   M codes, M98/M99
//   machine_codes.cpp  codes the machine profile knows; positions known only at the machine
//   mill_turn.cpp      a mill-turn face program: X/C, polar interpolation
//   heights.cpp        the plane heights, after the last block
//   taper_offsets.cpp  taper-angle and xyuv-rel contours, after the last block
// Beside the class: dialect.cpp (choosing the 4-axis dialect), machine.cpp (machine profiles),
// offset_table.cpp (--offsets), analysis.cpp (a program read as its machine means it) and
// workpiece.cpp (the part between the work's faces). The G-code table is nc/gcode.h: the parser
// classifies G words by it too.
// Sections: 1. a block's words and plan  2. what is kept between blocks  3. the interpreter
#pragma once

#include "../nc/gcode.h"
#include "kerf/converter/interpret/interpreter.h"
#include "kerf/converter/interpret/mill_turn.h"
#include "kerf/converter/nc/number_format.h"
#include "kerf/geometry/arc.h"
#include "kerf/geometry/offset.h"
#include "kerf/geometry/polar.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace kerf::converter::interp {

using geometry::Segment;
using geometry::Vec2;

// ---- 1. a block's words and plan ----------------------------------------------------------------

enum class Motion : std::uint8_t { None, Rapid, Line, Clockwise, CounterClockwise };
Motion motionOf(GCode code);

/// Phase 1: one side of a block's words — one value per letter, G codes by modal group.
/// The letters of `letters` as BlockWords::letters bits.
constexpr std::uint32_t letterBits(std::string_view letters) {
  std::uint32_t bits = 0;
  for (const char c : letters) bits |= 1U << static_cast<unsigned>(c - 'A');
  return bits;
}

/// Letters a profile may name as codes (T84) or as a whole letter (C): never the geometry's.
inline constexpr std::uint32_t kProfileLetters = letterBits("ACEQSTWZ");
constexpr bool profileMayName(char c) { return (kProfileLetters >> static_cast<unsigned>(c - 'A') & 1U) != 0; }
/// A word's letter (upper case A-Z) that only takes its slot in BlockWords: no G or M, none a
/// profile may name.
constexpr bool isPlainAddress(char c) {
  return (~(kProfileLetters | letterBits("GM")) >> static_cast<unsigned>(c - 'A') & 1U) != 0;
}

struct BlockWords {
  // A table entry holds something only where its mask has the bit (m and machine: below their
  // counts); the rest is left unwritten, so that making a block's BlockWords (three a block) sets
  // a few words, not 450 bytes.
  std::uint32_t letters = 0;           ///< bit c - 'A': letter[c - 'A'] holds the block's word c
  std::uint32_t groups = 0;            ///< bit g: g[g] and gCode[g] hold the block's code of modal group g
  std::array<const Word*, 26> letter;  // X Y I J R F P L D H ... (not G, M)
  std::array<const Word*, static_cast<std::size_t>(ModalGroup::Count)> g;
  std::array<GCode, static_cast<std::size_t>(ModalGroup::Count)> gCode;
  std::array<const Word*, 4> m;  // M codes the standard set or no profile knows
  std::size_t mCount = 0;
  /// Codes the machine profile knows (G, M, T, C ... and macro calls), in the order written. A
  /// plain struct, not a std::pair, whose constructor would clear all six for every block.
  struct MachineWord {
    const Word* word;
    const KnownCode* code;
  };
  std::array<MachineWord, 6> machine;
  std::size_t machineCount = 0;
  /// The corner at the block's end: Fanuc's `,R` and `,C` (Word::corner), or a bare R on a cut
  /// block where the profile reads it so (`cut_r = corner`, NCVC).
  const Word* cornerRound = nullptr;
  const Word* cornerChamfer = nullptr;
  bool bad = false;

  BlockWords() {}  // NOLINT: the tables stay unwritten (see above)
  BlockWords(const BlockWords& other) { *this = other; }
  BlockWords& operator=(const BlockWords& other) {
    letters = other.letters;
    groups = other.groups;
    for (std::uint32_t bits = letters; bits; bits &= bits - 1)
      letter[std::countr_zero(bits)] = other.letter[std::countr_zero(bits)];
    for (std::uint32_t bits = groups; bits; bits &= bits - 1) {
      g[std::countr_zero(bits)] = other.g[std::countr_zero(bits)];
      gCode[std::countr_zero(bits)] = other.gCode[std::countr_zero(bits)];
    }
    mCount = other.mCount;
    std::copy_n(other.m.begin(), mCount, m.begin());
    machineCount = other.machineCount;
    std::copy_n(other.machine.begin(), machineCount, machine.begin());
    cornerRound = other.cornerRound;
    cornerChamfer = other.cornerChamfer;
    bad = other.bad;
    return *this;
  }

  [[nodiscard]] const Word* operator[](char c) const {
    const auto i = static_cast<unsigned>(c - 'A');
    return (letters >> i & 1U) != 0 ? letter[i] : nullptr;
  }
  [[nodiscard]] bool has(char c) const { return (*this)[c] != nullptr; }
  /// Some letter of `mask` (letterBits) is in the block.
  [[nodiscard]] bool hasAny(std::uint32_t mask) const { return (letters & mask) != 0; }
  void setLetter(char c, const Word* w) {
    const auto i = static_cast<unsigned>(c - 'A');
    letter[i] = w;
    letters |= 1U << i;
  }
  void clearLetter(char c) { letters &= ~(1U << static_cast<unsigned>(c - 'A')); }
  [[nodiscard]] const Word* group(ModalGroup gr) const {
    const auto i = static_cast<unsigned>(gr);
    return (groups >> i & 1U) != 0 ? g[i] : nullptr;
  }
  /// The group's code; GCode::Rapid when the block has none in it.
  [[nodiscard]] GCode code(ModalGroup gr) const {
    const auto i = static_cast<unsigned>(gr);
    return (groups >> i & 1U) != 0 ? gCode[i] : GCode{};
  }
  void setGroup(ModalGroup gr, const Word* w, GCode c) {
    const auto i = static_cast<unsigned>(gr);
    g[i] = w;
    gCode[i] = c;
    groups |= 1U << i;
  }
  [[nodiscard]] bool hasCode(GCode c) const {
    const ModalGroup gr = info(c).group;
    return group(gr) && code(gr) == c;
  }
};
static_assert(static_cast<std::size_t>(ModalGroup::Count) <= 32, "BlockWords::groups has a bit a group");

/// Phase 2: what the block does, with what it leaves out taken from the modal state.
struct BlockPlan {
  Motion motion = Motion::None;  ///< the motion in force for this block
  const Word* motionWord = nullptr;
  bool incremental = false;                 ///< G91 in force
  bool inch = false;                        ///< G20/G70 in force
  bool setPosition = false;                 ///< G92
  bool dwell = false;                       ///< G04
  bool homing = false;                      ///< G28 / G30 / G53: the wire goes where only the machine knows
  bool lowerWords = false;                  ///< X Y I J R on the lower side
  bool upperWords = false;                  ///< U V (X Y I J R K L after ':' or a second motion word)
  const Word* unknownValue = nullptr;       ///< a coordinate known only at the machine (register, macro)
  const KnownCode* positionCode = nullptr;  ///< a profile code that moves the wire somewhere unknown
  const Word* positionCodeWord = nullptr;
  bool noMotion = false;  ///< a profile code takes the axis words as parameters
};

// ---- 2. what is kept between blocks -------------------------------------------------------------

struct Frame {
  std::size_t returnTo = 0;  // block index to continue at after the last repeat
  std::size_t start = 0;     // first block of the subprogram
  long remaining = 1;        // repeats left including the current one
  std::size_t callBlock = 0;
};

enum class TaperPhase : std::uint8_t { Off, Starting, On, Ending };

/// xyuv-rel: what a move's words said, resolved into contours once the heights are known.
struct RelRecord {
  std::size_t index = 0;                    // the move
  Vec2 offsetStart{0, 0}, offsetEnd{0, 0};  // upper minus lower at the move's ends
  Vec2 centreShift{0, 0};                   // K L: lower centre to upper centre
  geometry::ArcTolerance tolerance;
};

/// taper-angle: the lean of a move, resolved into offsets once the heights are known.
struct TaperRecord {
  std::size_t index = 0;
  double tanLeft = 0.0;          // tan(angle), > 0 leaning left of travel
  bool start = false;            // the move that starts the taper (its start stays vertical)
  bool end = false;              // the move that ends it (its end is vertical again)
  bool cylindricalArcs = false;  // corner-cylindrical in force: an arc between tangent neighbours keeps its radius
};

/// A run of moves under one G41/G42 as the interpreter records it (wire_offset.cpp applies it).
struct OffsetRun {
  std::size_t first = 0, end = 0;  // moves [first, end) carry the offset; first starts it up
  WireOffset side = WireOffset::Off;
  std::optional<double> value;
  std::string offsetRegister;
};

/// taper-angle: a corner made inside a taper, made again on the other planes by its model
/// (resolveTaperAngle).
struct TaperCorner {
  std::size_t move = 0;  // the corner's move
  CodeEffect model = CodeEffect::CornerEqual;
  double size = 0.0;  // at the program plane, mm
  std::optional<double> upperSize;
  bool chamfer = false;
  bool leftTurn = false;  // the contour turns left (counter-clockwise) at the corner
};

struct Height {
  double value = 0.0;  // mm
  std::string source;
};

/// The wire's position known only at the machine, from a cause until a block gives it again:
/// one diagnostic for the whole stretch (machine_codes.cpp).
struct UnknownPosition {
  bool active = false;
  std::string cause;  ///< "G28 (return to the machine's reference point)", "XH111 + H112 (a register)"
  SourceSpan span;
  std::string help;
  bool silent = false;  ///< the cause was reported already (an unsupported polar section)
  std::size_t skippedMoves = 0, skippedCuts = 0;
  std::uint32_t firstSkippedLine = 0, lastSkippedLine = 0;
};

enum class Flow : std::uint8_t { Continue, Stop };

/// A word kept past its block (the motion word in force, a G41 not yet carried out): a copy, so
/// that nothing the interpreter holds points into the parse of blocks it has left.
class HeldWord {
 public:
  void hold(const Word* w) {
    held_ = w != nullptr;
    if (w) word_ = *w;
  }
  [[nodiscard]] const Word* get() const { return held_ ? &word_ : nullptr; }

 private:
  Word word_;
  bool held_ = false;
};

// ---- 3. the interpreter -------------------------------------------------------------------------

class Interpreter {
 public:
  Interpreter(const Program& program, const InterpreterOptions& options, Diagnostics& diags);
  Interpretation run();

 private:
  // interpreter.cpp
  void chooseDialect();
  void indexLabels();
  void findLegacyTaperCodes();
  void warnIntegerUnit();
  Flow executeBlock(std::size_t pc, std::size_t& next);
  void takeFeed(const Word& f, bool inch);
  void valueUnknown(const Word& w, const Block& block, const BlockPlan& plan);
  void positionGone(const BlockWords& bw, const BlockPlan& plan);
  std::optional<Flow> executeSettings(const BlockWords& bw, const BlockWords& ubw, const Block& block,
                                      const BlockPlan& plan, std::size_t pc, std::size_t& next);
  void holdMotion(const BlockWords& bw);
  /// M codes in order (M98/M99 calls, the end), then the profile's program ends.
  Flow executeProgramFlow(const BlockWords& bw, std::size_t pc, std::size_t& next);
  // read_block.cpp (phase 1)
  bool readBlock(const Block& block, BlockWords& bw, BlockWords& ubw);
  /// The word into bw: the common words inline — an address letter's slot, a G code of the table
  /// into its modal group where no profile names codes — and every other word, or one of those
  /// that something is wrong with (a letter twice, two codes of a group), by readCodeWord.
  void readWord(const Word& w, BlockWords& bw) {
    if (!options_.millTurn && !w.corner) {
      if (isPlainAddress(w.letter) && !bw.has(w.letter)) {
        bw.setLetter(w.letter, &w);
        return;
      }
      if (w.letter == 'G' && machine_.codes.empty()) {
        // A motion code as the parse found it in the table (Word::motionCode); any other code here.
        if (w.motionCode != 0 && !bw.group(ModalGroup::Motion)) {
          bw.setGroup(ModalGroup::Motion, &w, codeOfMotionBits(w.motionCode));
          return;
        }
        int number = 0, fraction = 0;
        if (w.isNumber() && splitGNumber(w.value, number, fraction))
          if (const GCodeInfo* gi = findGCode(number, fraction); gi && !bw.group(gi->group)) {
            bw.setGroup(gi->group, &w, gi->code);
            return;
          }
      }
    }
    readCodeWord(w, bw);
  }
  /// A G or M code, a code or letter the profile may name, a face program's word, a corner word,
  /// or a letter the block already has (reported).
  void readCodeWord(const Word& w, BlockWords& bw);
  bool splitsBlocks() const;
  // fill_in.cpp (phase 2)
  BlockPlan fillIn(const Block& block, const BlockWords& bw, const BlockWords& ubw) const;
  // check_block.cpp (phase 3)
  /// A plain block (X Y I J R F and motion codes, one side, plain numbers: Block::plain) holds none
  /// of the words this phase refuses — a dialect's, G04's, a plane's, a direction, U — and most
  /// blocks are plain: passed inline.
  bool checkBlock(const Block& block, const BlockWords& bw, const BlockWords& ubw, const BlockPlan& plan) {
    return block.plain || checkBlockWords(block, bw, ubw, plan);
  }
  bool checkBlockWords(const Block& block, const BlockWords& bw, const BlockWords& ubw, const BlockPlan& plan);
  /// The words the dialect refuses in a block that is not plain (Block::plain has none of them).
  bool checkDialectWords(const Block& block, const BlockWords& bw, const BlockWords& ubw, bool setPosition);
  // execute.cpp (phase 4)
  /// The words the block's dialect gives no meaning, and coordinates in a G04 block, warned.
  /// Inline: most blocks hold none of them, and are past at once.
  void warnIgnoredWords(const BlockWords& bw, const BlockPlan& plan) {
    if (bw.hasAny(letterBits("AKQZTWB")) || plan.dwell) warnEachIgnoredWord(bw, plan);
  }
  void warnEachIgnoredWord(const BlockWords& bw, const BlockPlan& plan);
  bool executeSetPosition(const BlockWords& bw, const BlockWords& ubw, const Block& block);
  bool executeTaperAngle(const BlockWords& bw);
  void setHeight(std::optional<Height>& slot, double value, const char* what, std::uint32_t line);
  /// A length word in mm: micrometres without a decimal point under --integer-unit um, inches
  /// under G20.
  double length(const Word& w) const {
    double v = w.value;
    if (!w.hasPoint && options_.integerUnit == IntegerUnit::Micrometre) v *= 0.001;
    return v * (inch_ ? 25.4 : 1.0);
  }
  // motion.cpp
  /// The block's motion and the corner at its end. Inline: most blocks hold no corner word, and most
  /// profiles read no bare R as one (executeMotionWithCorner).
  bool executeMotion(const BlockWords& bw, const BlockWords& ubw, const Block& block, const BlockPlan& plan) {
    if (!bw.cornerRound && !bw.cornerChamfer && !machine_.bareCornerRadius) return executeMove(bw, ubw, block, plan);
    return executeMotionWithCorner(bw, ubw, block, plan);
  }
  bool executeMotionWithCorner(const BlockWords& bw, const BlockWords& ubw, const Block& block, const BlockPlan& plan);
  bool executeMove(const BlockWords& bw, const BlockWords& ubw, const Block& block, const BlockPlan& plan);
  /// One side's end point from its letters xl yl (absolute or incremental, in program coordinates:
  /// `shift` away from the toolpath's) and its segment from start (buildSegment). Inline: every
  /// move's lower side takes it.
  bool buildSide(const BlockWords& w, char xl, char yl, Motion motion, const Vec2& start, const Vec2& shift,
                 std::string_view side, const Block& block, const Word* motionWord, Segment& out, Vec2& end,
                 Move* record) {
    Vec2 endProgram = start + shift;  // in program coordinates; unwritten axes stay
    if (const Word* x = w[xl]) endProgram.x() = incremental_ ? endProgram.x() + length(*x) : length(*x);
    if (const Word* y = w[yl]) endProgram.y() = incremental_ ? endProgram.y() + length(*y) : length(*y);
    end = endProgram - shift;
    return buildSegment(w, motion, start, end, shift, 0.0, side, block, motionWord, out, record);
  }
  /// The line or arc from start to end with the block's I J or R; I J are turned by centreTurn
  /// degrees (a mill-turn polar frame; 0 elsewhere). False, with the error reported, when it
  /// cannot be built.
  bool buildSegment(const BlockWords& w, Motion motion, const Vec2& start, const Vec2& end, const Vec2& shift,
                    double centreTurn, std::string_view side, const Block& block, const Word* motionWord, Segment& out,
                    Move* record) {
    if ((motion == Motion::Rapid || motion == Motion::Line) && !w.hasAny(letterBits("IJR"))) {
      out = Segment::line(start, end);  // the common straight move, inline
      return true;
    }
    return buildArcSegment(w, motion, start, end, shift, centreTurn, side, block, motionWord, out, record);
  }
  /// buildSegment's arcs, and the straight moves with centre words (warned, then a line).
  bool buildArcSegment(const BlockWords& w, Motion motion, const Vec2& start, const Vec2& end, const Vec2& shift,
                       double centreTurn, std::string_view side, const Block& block, const Word* motionWord,
                       Segment& out, Move* record);
  void tallyArcCentre(const Vec2& start, const Vec2& end, const Vec2& ij, const Vec2& shift, bool closedAsUsed,
                      std::uint32_t line);
  void reportArc(const geometry::ArcBuild& build, const BlockWords& bw, const Block& block, std::string_view side);
  void push(Move&& m, Segment upper);
  // corner.cpp
  /// bw, or (with the profile's `corner_r = bare`) its copy in bare whose R rounds the corner.
  const BlockWords& cornerWords(const BlockWords& bw, BlockWords& bare) const;
  /// The corner word of a block that made a move (moved) or none: held for the next move, or refused.
  /// upper: NCVC's K, the upper plane's radius (cornerUpperRadius).
  void holdCorner(const Word& w, const Block& block, bool moved, const Word* upper);
  /// The held corner between the last move and next: both trimmed, the corner's move pushed.
  void makeCorner(Move& next, Segment& nextUpper);
  /// corner-rounded is in force and next turns a sharp corner of a taper from the last move: a
  /// corner move (a point here) goes between them. Inline: most programs round no corners.
  bool roundsProgramCorner(const Move& next) const {
    return programCorners_ == CodeEffect::CornerRounded && turnsTaperCorner(next);
  }
  /// roundsProgramCorner's test of the moves themselves.
  bool turnsTaperCorner(const Move& next) const;
  /// The held corner, if any, refused (K0240) for why.
  void refusePendingCorner(const std::string& why);
  /// NCVC's K beside a bare corner R in a taper (`G60 ... R2. K3.`): the upper plane's radius. Null
  /// when the block has none.
  const Word* cornerUpperRadius(const BlockWords& bw) const;
  /// The run of moves under one G41/G42 that the move at `index` (about to be, or just, stored)
  /// starts or extends; nothing for a move without the wire offset. Inline: most programs' moves
  /// have none.
  void noteOffsetRun(const Move& m, std::size_t index) {
    if (m.wireOffset != WireOffset::Off) extendOffsetRun(m, index);
  }
  void extendOffsetRun(const Move& m, std::size_t index);
  // upper_side.cpp
  bool buildUpper(const BlockWords& bw, const BlockWords& ubw, const Block& block, Move& move, Segment& upper);
  bool buildUpperAbsolute(const BlockWords& bw, const BlockWords& ubw, const Block& block, Segment& upper);
  bool buildUpperLinuxCnc(const BlockWords& ubw, Segment& upper);
  bool buildUpperColon(const BlockWords& ubw, const Block& block, const Move& move, Segment& upper);
  bool recordUpperRelative(const BlockWords& ubw, const Move& move, Segment& upper);
  bool recordTaper(const Block& block, const Move& move);
  // wire_offset.cpp
  void executeWireOffset(const BlockWords& bw, const Word& o);
  void recordOffsetSpans();
  // program_flow.cpp
  Flow executeM(const Word& m, const BlockWords& bw, std::size_t pc, std::size_t& next);
  Flow call(const Word& m, const BlockWords& bw, std::size_t pc, std::size_t& next);
  /// The block a subprogram number jumps to (O label, or an N label other than the calling block).
  std::optional<std::size_t> findSubprogram(long label, std::size_t callingBlock) const;
  /// Blocks one run of the subprogram starting at `target` executes, its own calls expanded
  /// (M98 P L inside it, at their L), counted from the text without running it: at most `cap`.
  std::uint64_t blocksOfCall(std::size_t target, std::uint64_t cap, std::size_t depth);
  // machine_codes.cpp
  /// The codes the machine profile knows in the block (BlockWords::machine), each in turn.
  void executeMachineCodes(const BlockWords& bw, const Block& block);
  /// cnc3's guides (M100 P L Q H, or M106 in its earlier numbering), said as `code`: recorded;
  /// false without P and Q.
  bool recordGuides(const BlockWords& bw, const Block& block, const std::string& code);
  Flow executeMacroCall(const Block& block);
  void positionUnknown(std::string cause, SourceSpan span, std::string help = {}, bool silent = false);
  /// G28/G30 with the profile's home known: a rapid through the point the axis words give, then
  /// one to the home for the axes named (all when none is), the upper plane's U V too.
  void returnHome(const BlockWords& bw, const BlockWords& ubw, const Block& block, const BlockPlan& plan);
  void skipMove(const Block& block, bool cut);
  void positionKnownAgain(const Block& block);
  void flushUnknown(const Block* knownAgain);
  bool skipPolarSection(std::size_t pc, std::size_t& next, const Word& polarWord);
  // mill_turn.cpp (a face program: InterpreterOptions::millTurn)
  /// Phase 1: true when the word is done with (noted, warned or not a face word).
  bool readFaceWord(const Word& w);
  /// Phase 4: dwell, the table homed, polar interpolation on or off, the move.
  void executeFaceBlock(const BlockWords& bw, const Block& block, const BlockPlan& plan);
  void startPolar(const Block& block);
  void endPolar();
  /// The face point the block's X Y C reach; newC the table angle after it, startRadius before.
  Vec2 faceTarget(const BlockWords& bw, double& newC, double& startRadius);
  void faceMove(const BlockWords& bw, const Block& block);
  /// An X/C cutting move as its spiral's pieces; false (nothing pushed) to draw it as its chord.
  bool pushSpiral(const Move& move, const geometry::PolarPoint& from, const geometry::PolarPoint& to,
                  const BlockWords& bw, const Vec2& target);
  void finishFace();
  // heights.cpp
  Height heightOf(const HeightWord& w) const;
  void resolveHeights();
  void resolveGuides(double lowerZ);
  // taper_offsets.cpp
  void resolveRel();
  void resolveTaperAngle();
  void resolveTaperRun(std::size_t k, std::size_t e);
  std::vector<TaperCorner> cornersOfRun(std::size_t k, std::size_t e) const;
  void makeTaperCorner(const TaperCorner& c, std::size_t runFirst, double z, bool upperPlane);
  // wire_offset.cpp, after the last block: each G41/G42 run's moves replaced by the wire's path
  void resolveWireOffsets();
  /// One piece of a run's wire path on each plane (the upper the lower one's where the program has
  /// no upper contour of its own, or in taper-angle, where the taper is taken after the offset).
  struct PairedPiece {
    geometry::WirePiece lower;
    Segment upper;
  };
  /// The run's wire path, both planes paired; nothing when it cannot be made (the error said why).
  std::optional<std::vector<PairedPiece>> offsetRun(const OffsetRun& run);
  static std::vector<PairedPiece> pairPieces(const std::vector<geometry::WirePiece>& lower,
                                             const std::vector<geometry::WirePiece>* upper);
  void reportLostRuns(const OffsetRun& run, const std::vector<geometry::LostRun>& lost);
  /// The moves and their tables being rebuilt with the wire's path.
  struct OffsetBuild {
    std::vector<MoveRow> rows;            ///< the new moves with their tables' entries
    std::vector<std::size_t> source;      ///< per new move, the old move it was made from
    std::vector<std::uint32_t> firstOut;  ///< per old move, its first new move (UINT32_MAX: none yet)
    std::size_t next = 0;                 ///< the first old move not yet copied
    bool applied = false;
    /// Appends old move `from` made into `m` (on the lower plane), `upperSegment`, for the offset `r`.
    void push(const Toolpath& tp, std::size_t from, const Move& m, const Segment& upperSegment, OffsetRole r,
              const Segment& programmedSegment);
    void copyUpTo(std::size_t end, const Toolpath& tp);
    void addRun(const OffsetRun& run, const std::vector<PairedPiece>& path, const Toolpath& tp);
  };
  /// The toolpath's moves replaced by b's, every table indexed by move or naming moves following.
  void renumberAfterOffset(OffsetBuild& b);
  void reportOffsetIssues(const geometry::OffsetChainResult& r, const std::vector<std::size_t>& moveOf,
                          const std::vector<double>& distance, const char* plane);

  SourceSpan spanOf(const Word* w, const Block& b) const { return w ? w->span() : b.span(); }
  /// The line block b starts on: the run asks for the blocks in order, so the line of the block
  /// before is tried first (SourceFile::lineOf's hint).
  std::uint32_t lineOf(const Block& b) { return src_->lineOf(b.offset, lineHint_); }
  std::uint32_t lineHint_ = 0;  // lineOf's: the line it answered last

  std::size_t executed_ = 0;                                     // blocks run so far
  std::unordered_map<std::size_t, std::uint64_t> blocksOfCall_;  // per subprogram start (memo)

  const Program& program_;
  WordReader words_;  // each block's words as the run comes to it (a plain block's as the parse kept them)
  const SourceFile* src_;
  const InterpreterOptions& options_;
  const MachineProfile& machine_;
  Diagnostics& diags_;
  Toolpath toolpath_;
  ArcCentreTally tally_;

  // Modal state (the interpreter's "settings").
  Dialect dialect_ = Dialect::Plain;
  Vec2 position_{0, 0};  // in the toolpath frame
  Vec2 shift_{0, 0};     // program coordinates = toolpath coordinates + shift (G92)
  Motion motion_ = Motion::None;
  HeldWord motionWord_;
  bool incremental_ = false;
  bool inch_ = false;
  double feed_ = 0.0;  // the feed in force, mm/min; 0: none programmed
  // What the move being built records beside it (Toolpath::centreWords, taperDegrees).
  Vec2 moveCentreWords_{0, 0};
  float moveTaper_ = 0.0f;
  WireOffset wireOffset_ = WireOffset::Off;
  geometry::ArcTolerance tolerance_{};
  std::vector<Frame> stack_;
  std::unordered_map<long, std::size_t> oLabels_, nLabels_;
  UnknownPosition unknown_;
  HeldWord pendingOffset_;             // G40/G41/G42 not yet carried out by a move
  std::optional<double> offsetValue_;  // the wire offset in force (D/H register or --offset), mm
  std::string offsetRegister_;         // the register that gave it ("H001"); empty: none named
  std::vector<OffsetRun> offsetRuns_;
  struct PendingCorner {
    double size = 0.0;                // r or c, mm; 0: corner-rounded's point (a cone's apex)
    std::optional<double> upperSize;  // NCVC's K beside R: the upper plane's radius, mm
    bool chamfer = false;
    SourceSpan span;  // the corner word
    std::uint32_t line = 0;
  };
  std::optional<PendingCorner> pendingCorner_;  // a corner word waiting for the next move
  // taper-angle: the corners made inside a taper, each made again on the other planes by its model
  // (resolveTaperAngle).
  CodeEffect taperCorner_ = CodeEffect::CornerEqual;  // the model in force (a profile's corner-* code)
  // What a taper does with the program's own corners and arcs: Harmless (sharp corners, conical
  // arcs: the default), CornerRounded or CornerCylindrical (a profile's code: Charmilles' G28/G29).
  CodeEffect programCorners_ = CodeEffect::Harmless;
  std::vector<TaperCorner> taperCorners_;  // in move order
  bool programHasV_ = false;               // some word is V (for the U Z diagnostic)

  // A mill-turn face program's axes (mill_turn.cpp). position_ is the face point.
  struct FaceAxes {
    bool polar = false;                     // inside G12.1/G112
    double radius = 0.0, y = 0.0, c = 0.0;  // outside: mm, mm, degrees (unwrapped)
    bool cKnown = false;
    double frame = 0.0;  // degrees: the polar frame's turn against the table's at C 0
    Vec2 inPolar{0, 0};  // the tool in the polar frame
    std::size_t spiralPieces = 0;
    double worstSpiral = 0.0;        // mm
    std::vector<std::string> noted;  // T, S and M codes said once
  } face_;

  // 4-axis state.
  Vec2 upperPosition_{0, 0};  // xyuv-abs, xyuv-linuxcnc, sodick-colon: where the upper contour is
  Vec2 upperShift_{0, 0};     // xyuv-abs, xyuv-linuxcnc: G92 U V
  bool notedHome_ = false;    // HomePositionTaken said
  Motion upperMotion_ = Motion::None;
  HeldWord upperMotionWord_;
  Vec2 uvOffset_{0, 0};     // xyuv-rel: upper minus lower, the modal U V
  bool colonMode_ = false;  // G141/G142 in force
  TaperPhase taperPhase_ = TaperPhase::Off;
  int taperSide_ = 1;  // +1 G51 (wire leans left of travel), -1 G52
  double taperDegrees_ = 0.0;
  std::vector<RelRecord> relRecords_;
  std::vector<TaperRecord> taperRecords_;
  std::optional<Height> fileThickness_, fileProgramZ_;
  std::optional<Height> fileGuideSpacing_, fileGuideBelow_;  // cnc3's M100 P (L) Q (H)
  bool legacyTaperCodes_ = false;                            // cnc3's earlier M106/M107 numbering is in use

  // Say it once.
  std::unordered_set<char> warnedLetters_;
  std::unordered_set<long> warnedM_;
  std::unordered_set<std::string> notedCodes_;
  bool warnedOffsetUnknown_ = false, warnedWorkOffset_ = false, warnedUz_ = false;
  std::set<std::string> registersWithoutValue_;  // warned once each (K0210)
};

}  // namespace kerf::converter::interp
