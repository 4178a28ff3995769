// 2-axis ISO interpreter. The phase order is documented in interpreter.h.
//
// Sections: 1. G and M code tables
//           2. reading a block (phase 1)
//           3. the machine state and the executor (phases 2-4)
//           4. program flow: labels, M98/M99, limits
#include "kerf/converter/interpreter.h"

#include "kerf/geometry/arc.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <unordered_map>
#include <unordered_set>

namespace kerf::converter {
namespace {

using geometry::ArcDirection;
using geometry::Segment;
using geometry::Vec2;

std::string fmt3(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3f", v);
  if (std::string_view(buf) == "-0.000") return "0.000";
  return buf;
}

// ---- 1. code tables ---------------------------------------------------------------------------

enum class Group : std::uint8_t { Motion, NonModal, Plane, Units, Offset, Distance, WorkOffset, Count };

struct GCodeInfo {
  int tenths;  // G code x 10 (G12.1 is 121)
  Group group;
};

constexpr std::array<GCodeInfo, 24> kGCodes = {{
    {0, Group::Motion},       {10, Group::Motion},      {20, Group::Motion},      {30, Group::Motion},
    {40, Group::NonModal},    {920, Group::NonModal},   {170, Group::Plane},      {180, Group::Plane},
    {190, Group::Plane},      {200, Group::Units},      {210, Group::Units},      {700, Group::Units},
    {710, Group::Units},      {400, Group::Offset},     {410, Group::Offset},     {420, Group::Offset},
    {900, Group::Distance},   {910, Group::Distance},   {540, Group::WorkOffset}, {550, Group::WorkOffset},
    {560, Group::WorkOffset}, {570, Group::WorkOffset}, {580, Group::WorkOffset}, {590, Group::WorkOffset},
}};

const GCodeInfo* findGCode(int tenths) {
  for (const GCodeInfo& g : kGCodes)
    if (g.tenths == tenths) return &g;
  return nullptr;
}

std::string gName(int tenths) {
  char buf[16];
  if (tenths % 10 == 0)
    std::snprintf(buf, sizeof buf, "G%02d", tenths / 10);
  else
    std::snprintf(buf, sizeof buf, "G%d.%d", tenths / 10, tenths % 10);
  return buf;
}

/// "did you mean" for an unknown G code: the known codes one edit away in their digits.
std::string suggestGCode(std::string_view written) {
  std::string digits;
  for (char c : written)
    if (c >= '0' && c <= '9') digits += c;
  while (digits.size() > 1 && digits[0] == '0') digits.erase(0, 1);
  auto editDistance = [](const std::string& a, const std::string& b) {
    std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
      cur[0] = i;
      for (std::size_t j = 1; j <= b.size(); ++j)
        cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      std::swap(prev, cur);
    }
    return prev[b.size()];
  };
  std::string best;
  for (const GCodeInfo& g : kGCodes) {
    if (g.tenths % 10) continue;
    const std::string candidate = std::to_string(g.tenths / 10);
    if (editDistance(digits, candidate) == 1) {
      if (!best.empty()) best += " or ";
      best += gName(g.tenths);
    }
  }
  return best.empty() ? std::string{} : "did you mean " + best + "?";
}

// ---- 2. reading a block -------------------------------------------------------------------------

struct BlockWords {
  std::array<const Word*, 26> letter{};  // X Y I J R F P L D H ... (not G, M)
  std::array<const Word*, static_cast<std::size_t>(Group::Count)> g{};
  std::array<int, static_cast<std::size_t>(Group::Count)> gTenths{};
  std::array<const Word*, 4> m{};
  std::size_t mCount = 0;
  bool bad = false;

  [[nodiscard]] const Word* operator[](char c) const { return letter[static_cast<std::size_t>(c - 'A')]; }
  [[nodiscard]] bool has(char c) const { return (*this)[c] != nullptr; }
  [[nodiscard]] const Word* group(Group gr) const { return g[static_cast<std::size_t>(gr)]; }
  [[nodiscard]] int code(Group gr) const { return gTenths[static_cast<std::size_t>(gr)]; }
};

// ---- 3. state and executor ----------------------------------------------------------------------

enum class Motion : std::uint8_t { None, Rapid, Line, Clockwise, CounterClockwise };

struct Frame {
  std::size_t returnTo = 0;  // block index to continue at after the last repeat
  std::size_t start = 0;     // first block of the subprogram
  long remaining = 1;        // repeats left including the current one
  std::size_t callBlock = 0;
};

class Interpreter {
 public:
  Interpreter(const Program& program, const InterpreterOptions& options, Diagnostics& diags)
      : program_(program), src_(program.source), options_(options), diags_(diags) {}

  Toolpath run() {
    indexLabels();
    // Most blocks of a wire program are moves: reserving avoids copying them while growing.
    toolpath_.moves.reserve(std::min(program_.blocks.size(), options_.maxMoves));
    for (const Setting& s : program_.settings) toolpath_.settings.push_back(s);
    warnIntegerUnit();
    std::size_t pc = 0;
    std::size_t executed = 0;
    const std::size_t n = program_.blocks.size();
    while (pc < n) {
      if (++executed > options_.maxExecutedBlocks) {
        diags_.error(Code::ExecutionLimit, src_, program_.blocks[pc].span(),
                     "stopped after " + std::to_string(options_.maxExecutedBlocks) +
                         " executed blocks: the subprogram calls repeat without end or far too often");
        break;
      }
      const Block& block = program_.blocks[pc];
      std::size_t next = pc + 1;
      if (!(block.blockDelete && options_.blockDelete) && !block.hasError) {
        const Flow flow = executeBlock(pc, next);
        if (flow == Flow::Stop) break;
      }
      if (toolpath_.moves.size() > options_.maxMoves) {
        diags_.error(Code::ExecutionLimit, src_, block.span(),
                     "stopped after " + std::to_string(options_.maxMoves) + " moves (the limit of one run)");
        break;
      }
      if (next >= n && !stack_.empty()) {
        diags_.warning(Code::MissingProgramEnd, src_, program_.blocks[stack_.back().callBlock].span(),
                       "subprogram called here runs to the end of the file without M99");
        next = stack_.back().returnTo;
        stack_.pop_back();
      }
      pc = next;
    }
    if (!toolpath_.endedProperly && !diags_.hasErrors() && n > 0)
      diags_.warning(Code::MissingProgramEnd, src_, program_.blocks.back().span(), "program ends without M02 or M30");
    return std::move(toolpath_);
  }

 private:
  enum class Flow : std::uint8_t { Continue, Stop };

  // -- helpers --
  SourceSpan spanOf(const Word* w, const Block& b) const { return w ? w->span() : b.span(); }

  double length(const Word& w) const {
    double v = w.value;
    if (!w.hasPoint && options_.integerUnit == IntegerUnit::Micrometre) v *= 0.001;
    return v * (inch_ ? 25.4 : 1.0);
  }

  void warnIntegerUnit() {
    if (options_.integerUnit == IntegerUnit::Millimetre && !program_.anyDecimalPoint &&
        program_.largestInteger > 1000 && !program_.words.empty()) {
      const Word& w = program_.words[program_.largestIntegerWord];
      diags_.warning(Code::IntegerUnitSuspect, src_, w.span(),
                     "no coordinate has a decimal point and this one is " + fmt3(w.value) +
                         " mm: the file may be written in micrometres",
                     "if so, run with --integer-unit um");
    }
  }

  void indexLabels() {
    // O numbers anywhere; N numbers count as labels too (Sodick puts `N0001 ... M99` after M02).
    for (std::size_t i = 0; i < program_.blocks.size(); ++i) {
      for (const Word& w : program_.wordsOf(program_.blocks[i])) {
        if (w.letter != 'O' && w.letter != 'N') continue;
        const long key = std::lround(w.value);
        auto& map = w.letter == 'O' ? oLabels_ : nLabels_;
        if (auto it = map.find(key); it != map.end()) {
          if (w.letter == 'O')
            diags_.warning(Code::DuplicateLabel, src_, w.span(),
                           "program number O" + std::to_string(key) + " appears again; calls go to the first");
          continue;
        }
        map.emplace(key, i);
      }
    }
  }

  bool readBlock(const Block& block, BlockWords& bw) {
    for (const Word& w : program_.wordsOf(block)) {
      if (w.letter == 'G') {
        const int tenths = static_cast<int>(std::lround(w.value * 10));
        if (std::abs(w.value * 10 - tenths) > 1e-6 || w.value < 0) {
          diags_.error(Code::UnknownGCode, src_, w.span(), "G code must be a whole number or have one decimal");
          bw.bad = true;
          continue;
        }
        const GCodeInfo* info = findGCode(tenths);
        if (!info) {
          const std::string_view raw = src_->text().substr(w.offset, w.length);
          if (tenths == 121 || tenths == 131) {
            diags_.error(Code::UnknownGCode, src_, w.span(),
                         gName(tenths) + " (polar coordinate interpolation) is not supported yet");
          } else if (tenths == 500 || tenths == 510 || tenths == 520 || (tenths >= 1400 && tenths <= 1420)) {
            diags_.error(Code::TaperWordsNotSupported, src_, w.span(),
                         gName(tenths) + " is a taper command: 4-axis taper programs are not read by this version");
          } else {
            diags_.error(Code::UnknownGCode, src_, w.span(), "unknown G code " + std::string(raw), suggestGCode(raw));
          }
          bw.bad = true;
          continue;
        }
        const auto gi = static_cast<std::size_t>(info->group);
        if (bw.g[gi]) {
          diags_.error(
              Code::ModalGroupConflict, src_, w.span(),
              gName(tenths) + " and " + gName(bw.gTenths[gi]) + " are in the same group and cannot share a block");
          bw.bad = true;
          continue;
        }
        bw.g[gi] = &w;
        bw.gTenths[gi] = tenths;
        continue;
      }
      if (w.letter == 'M') {
        if (bw.mCount == bw.m.size()) {
          diags_.error(Code::TooManyMCodes, src_, w.span(),
                       "more than " + std::to_string(bw.m.size()) + " M codes in one block");
          bw.bad = true;
          continue;
        }
        bw.m[bw.mCount++] = &w;
        continue;
      }
      bw.letter[static_cast<std::size_t>(w.letter - 'A')] = &w;
    }
    return !bw.bad;
  }

  Flow executeBlock(std::size_t pc, std::size_t& next) {
    const Block& block = program_.blocks[pc];
    BlockWords bw;
    if (!readBlock(block, bw)) return Flow::Continue;
    const std::uint32_t blockIndex = static_cast<std::uint32_t>(pc);

    // Words that belong to other dialects or do nothing in a 2-axis wire program.
    const bool setPosition = bw.group(Group::NonModal) && bw.code(Group::NonModal) == 920;
    if (!setPosition && (bw.has('U') || bw.has('V'))) {
      const Word* w = bw.has('U') ? bw['U'] : bw['V'];
      diags_.error(Code::TaperWordsNotSupported, src_, w->span(),
                   "U/V give the upper contour of a 4-axis taper program, which this version does not read");
      return Flow::Continue;
    }
    for (char c : {'A', 'K', 'Q', 'Z'}) {
      if (!bw.has(c) || (c == 'Z' && setPosition)) continue;
      if (warnedLetters_.insert(c).second)
        diags_.warning(Code::WordIgnored, src_, bw[c]->span(),
                       std::string("word '") + c + "' has no meaning in a 2-axis wire program and is ignored");
    }

    // F
    if (const Word* f = bw['F']) {
      if (f->value <= 0)
        diags_.warning(Code::BadFeed, src_, f->span(), "feed F must be positive");
      else
        feed_ = f->value * (inch_ ? 25.4 : 1.0);
    }
    // G04 dwell: P in ms or X in s. X here is a time, not a coordinate.
    const bool dwell = bw.group(Group::NonModal) && bw.code(Group::NonModal) == 40;
    if (dwell && !bw.has('P') && !bw.has('X')) {
      diags_.error(Code::DwellWithoutTime, src_, bw.group(Group::NonModal)->span(),
                   "G04 needs a time: P (milliseconds) or X (seconds)");
      return Flow::Continue;
    }
    // Plane
    if (const Word* p = bw.group(Group::Plane)) {
      if (bw.code(Group::Plane) != 170) {
        diags_.error(
            Code::PlaneNotSupported, src_, p->span(),
            gName(bw.code(Group::Plane)) + " selects a plane a wire machine cannot cut in; only G17 (XY) is allowed");
        return Flow::Continue;
      }
    }
    // Units
    if (bw.group(Group::Units)) {
      const int u = bw.code(Group::Units);
      inch_ = (u == 200 || u == 700);
      toolpath_.programUnit = inch_ ? LengthUnit::Inch : LengthUnit::Millimetre;
      tolerance_ = inch_ ? geometry::ArcTolerance::forInch() : geometry::ArcTolerance{};
    }
    // Wire offset with D/H register
    if (const Word* o = bw.group(Group::Offset)) executeWireOffset(bw, *o);
    // Distance mode
    if (bw.group(Group::Distance)) incremental_ = bw.code(Group::Distance) == 910;
    // Work offset: select only; the values live in the controller.
    if (const Word* w = bw.group(Group::WorkOffset)) {
      if (!warnedWorkOffset_) {
        warnedWorkOffset_ = true;
        diags_.warning(Code::WorkOffsetIgnored, src_, w->span(),
                       gName(bw.code(Group::WorkOffset)) +
                           " selects a work offset stored in the controller; Kerf takes it as zero");
      }
    }
    // G92 set position
    if (setPosition) {
      if (!bw.has('X') && !bw.has('Y') && !bw.has('U') && !bw.has('V') && !bw.has('Z')) {
        diags_.error(Code::SetPositionWithoutAxis, src_, bw.group(Group::NonModal)->span(),
                     "G92 needs the coordinates of the current position (X, Y)");
        return Flow::Continue;
      }
      Vec2 programmed = position_ + shift_;
      if (const Word* x = bw['X']) programmed.x() = length(*x);
      if (const Word* y = bw['Y']) programmed.y() = length(*y);
      if (toolpath_.moves.empty()) {
        position_ = programmed;  // before any motion G92 places the start: no shift needed
        shift_ = Vec2::Zero();
        toolpath_.start = position_;
      } else {
        shift_ = programmed - position_;
      }
    }
    // Motion
    if (const Word* mw = bw.group(Group::Motion)) {
      switch (bw.code(Group::Motion)) {
        case 0: motion_ = Motion::Rapid; break;
        case 10: motion_ = Motion::Line; break;
        case 20: motion_ = Motion::Clockwise; break;
        default: motion_ = Motion::CounterClockwise; break;
      }
      motionWord_ = mw;
    }
    if (!dwell && !setPosition) {
      if (!executeMotion(bw, block, blockIndex)) return Flow::Continue;
    } else if (!setPosition && (bw.has('Y') || bw.has('I') || bw.has('J') || bw.has('R'))) {
      const Word* w = bw.has('Y') ? bw['Y'] : bw.has('I') ? bw['I'] : bw.has('J') ? bw['J'] : bw['R'];
      diags_.warning(Code::WordIgnored, src_, w->span(), "coordinates in a G04 block are ignored");
    }
    // Program flow
    for (std::size_t k = 0; k < bw.mCount; ++k) {
      const Flow f = executeM(*bw.m[k], bw, pc, next);
      if (f == Flow::Stop) return f;
    }
    return Flow::Continue;
  }

  void executeWireOffset(const BlockWords& bw, const Word& o) {
    const int code = bw.code(Group::Offset);
    wireOffset_ = code == 400 ? WireOffset::Off : code == 410 ? WireOffset::Left : WireOffset::Right;
    if (code == 400) return;
    const Word* reg = bw.has('D') ? bw['D'] : bw['H'];
    std::string what;
    if (reg) {
      char name[16];
      std::snprintf(name, sizeof name, "%c%03ld", reg->letter, std::lround(reg->value));
      what = std::string(name);
      const auto it = std::find_if(toolpath_.settings.begin(), toolpath_.settings.end(),
                                   [&](const Setting& s) { return s.name == name; });
      if (it != toolpath_.settings.end()) what += " = " + it->value;
    } else if (options_.wireOffset) {
      what = "--offset " + fmt3(*options_.wireOffset) + " mm";
    } else {
      if (!warnedOffsetUnknown_) {
        warnedOffsetUnknown_ = true;
        diags_.warning(Code::WireOffsetUnknown, src_, o.span(),
                       gName(code) + " without D or H: the offset is set at the machine",
                       "give it with --offset MM to record it");
      }
      return;
    }
    if (!warnedOffset_) {
      warnedOffset_ = true;
      diags_.warning(Code::WireOffsetNotApplied, src_, o.span(),
                     "wire offset " + gName(code) + " (" + what +
                         ") is read but not applied yet: geometry and pictures show the programmed contour");
    }
  }

  /// Returns false when the block's motion failed (the diagnostic is reported).
  bool executeMotion(const BlockWords& bw, const Block& block, std::uint32_t blockIndex) {
    const bool hasEnd = bw.has('X') || bw.has('Y');
    const bool hasCentre = bw.has('I') || bw.has('J');
    const bool hasRadius = bw.has('R');
    if (!hasEnd && !hasCentre && !hasRadius) return true;  // modal words only
    if (motion_ == Motion::None) {
      const Word* w = bw.has('X')   ? bw['X']
                      : bw.has('Y') ? bw['Y']
                      : bw.has('I') ? bw['I']
                      : bw.has('J') ? bw['J']
                                    : bw['R'];
      diags_.error(Code::NoMotionMode, src_, w->span(), "coordinates without a motion command",
                   "start the block (or an earlier one) with G00, G01, G02 or G03");
      return false;
    }
    const Vec2 start = position_;
    Vec2 endProgram = position_ + shift_;  // in program coordinates; unwritten axes stay
    if (const Word* x = bw['X']) endProgram.x() = incremental_ ? endProgram.x() + length(*x) : length(*x);
    if (const Word* y = bw['Y']) endProgram.y() = incremental_ ? endProgram.y() + length(*y) : length(*y);
    const Vec2 end = endProgram - shift_;

    Move move;
    move.block = blockIndex;
    move.line = block.line;
    move.span = block.span();
    move.feed = feed_;
    move.wireOffset = wireOffset_;
    move.callDepth = static_cast<std::uint16_t>(stack_.size());

    if (motion_ == Motion::Rapid || motion_ == Motion::Line) {
      if (hasCentre || hasRadius) {
        const Word* w = hasRadius ? bw['R'] : bw.has('I') ? bw['I'] : bw['J'];
        diags_.warning(Code::WordIgnored, src_, w->span(),
                       std::string("'") + w->letter + "' has no meaning on a straight move and is ignored");
      }
      if (!hasEnd) return true;
      move.kind = motion_ == Motion::Rapid ? MoveKind::Rapid : MoveKind::Line;
      move.lower = Segment::line(start, end);
      if (move.kind == MoveKind::Line && (end - start).norm() <= 1e-9) {
        diags_.warning(Code::ZeroLengthMove, src_, block.span(), "move has zero length");
      }
      push(std::move(move));
      position_ = end;
      return true;
    }

    // Arcs
    const ArcDirection dir = motion_ == Motion::Clockwise ? ArcDirection::Clockwise : ArcDirection::CounterClockwise;
    if (hasRadius && hasCentre) {
      diags_.error(Code::RadiusAndCentre, src_, bw['R']->span(), "arc has both R and I/J: give one of them");
      position_ = end;
      return false;
    }
    if (!hasRadius && !hasCentre) {
      diags_.error(Code::ArcWithoutCentre, src_,
                   motionWord_ && motionWord_->offset >= block.offset ? motionWord_->span() : block.span(),
                   "arc needs its centre (I J) or its radius (R)");
      position_ = end;
      return false;
    }
    geometry::ArcBuild build;
    move.kind = MoveKind::Arc;
    if (hasRadius) {
      const double r = length(*bw['R']);
      move.centreForm = CentreForm::Radius;
      move.programmedRadius = r;
      build = geometry::arcFromRadius(start, end, r, dir, tolerance_);
    } else {
      Vec2 ij(0, 0);
      if (const Word* i = bw['I']) ij.x() = length(*i);
      if (const Word* j = bw['J']) ij.y() = length(*j);
      move.programmedCentreWords = ij;
      Vec2 centre;
      switch (options_.arcCentre) {
        case ArcCentreMode::Incremental:
          centre = start + ij;
          move.centreForm = CentreForm::Incremental;
          break;
        case ArcCentreMode::Reversed:
          centre = start - ij;
          move.centreForm = CentreForm::Reversed;
          break;
        case ArcCentreMode::Absolute:
          centre = ij - shift_;
          move.centreForm = CentreForm::Absolute;
          break;
      }
      build = geometry::arcFromCentre(start, end, centre, dir, tolerance_);
    }
    if (build.status != geometry::ArcStatus::Ok) {
      reportArc(build, bw, block);
      position_ = end;
      return false;
    }
    move.lower = build.arc;
    move.radiusError = build.radiusError;
    push(std::move(move));
    position_ = end;
    return true;
  }

  void reportArc(const geometry::ArcBuild& build, const BlockWords& bw, const Block& block) {
    const double unit = inch_ ? 25.4 : 1.0;
    const char* u = inch_ ? " in" : " mm";
    switch (build.status) {
      case geometry::ArcStatus::RadiusTooSmall:
        diags_.error(Code::RadiusTooSmall, src_, bw['R']->span(),
                     "arc radius " + fmt3(std::abs(length(*bw['R'])) / unit) + " is shorter than half the chord " +
                         fmt3(build.halfChord / unit) + u);
        break;
      case geometry::ArcStatus::FullCircleWithRadius:
        diags_.error(Code::FullCircleWithRadius, src_, bw['R']->span(),
                     "arc ends where it starts, and R cannot describe a full circle", "give the centre with I J");
        break;
      case geometry::ArcStatus::ZeroRadius:
        diags_.error(Code::ZeroRadius, src_,
                     spanOf(bw.has('R')   ? bw['R']
                            : bw.has('I') ? bw['I']
                                          : bw['J'],
                            block),
                     "arc radius is zero");
        break;
      case geometry::ArcStatus::EndOffCircle:
        diags_.error(Code::ArcEndOffCircle, src_, spanOf(bw.has('I') ? bw['I'] : bw['J'], block),
                     "arc end point is " + fmt3(std::abs(build.radiusError) / unit) + u +
                         " off the circle through the start (limit " + fmt3(tolerance_.centreAbsolute / unit) + u + ")",
                     options_.arcCentre == ArcCentreMode::Incremental
                         ? "if the post writes I J as start minus centre or as absolute centres, use --arc-centre "
                           "reversed|absolute"
                         : std::string{});
        break;
      case geometry::ArcStatus::Ok: break;
    }
  }

  void push(Move&& m) { toolpath_.moves.push_back(std::move(m)); }

  // ---- 4. program flow ----------------------------------------------------------------------------
  Flow executeM(const Word& m, const BlockWords& bw, std::size_t pc, std::size_t& next) {
    const long code = std::lround(m.value);
    switch (code) {
      case 0:
      case 1: return Flow::Continue;  // program stop / optional stop: the wire path goes on
      case 2:
      case 30: toolpath_.endedProperly = true; return Flow::Stop;
      case 98: return call(m, bw, pc, next);
      case 99:
        if (stack_.empty()) {
          diags_.warning(Code::ReturnOutsideSubprogram, src_, m.span(), "M99 in the main program ends it here");
          toolpath_.endedProperly = true;
          return Flow::Stop;
        }
        if (--stack_.back().remaining > 0) {
          next = stack_.back().start;
        } else {
          next = stack_.back().returnTo;
          stack_.pop_back();
        }
        return Flow::Continue;
      default:
        if (warnedM_.insert(code).second)
          diags_.warning(
              Code::UnknownMCode, src_, m.span(),
              "M" + std::to_string(code) + " is a machine function Kerf does not know; it has no effect on the path");
        return Flow::Continue;
    }
  }

  Flow call(const Word& m, const BlockWords& bw, std::size_t pc, std::size_t& next) {
    const Word* p = bw['P'];
    if (!p) {
      diags_.error(Code::CallWithoutProgram, src_, m.span(), "M98 needs the subprogram number in P");
      return Flow::Continue;
    }
    const long label = std::lround(p->value);
    long repeats = 1;
    if (const Word* l = bw['L']) {
      repeats = std::lround(l->value);
      if (repeats < 1 || repeats > 9999 || std::abs(l->value - static_cast<double>(repeats)) > 1e-9) {
        diags_.error(Code::BadRepeatCount, src_, l->span(), "repeat count L must be a whole number from 1 to 9999");
        return Flow::Continue;
      }
    }
    std::size_t target = 0;
    if (auto it = oLabels_.find(label); it != oLabels_.end()) {
      target = it->second;
    } else if (auto jt = nLabels_.find(label); jt != nLabels_.end() && jt->second != pc) {
      target = jt->second;
    } else {
      std::string help;
      long best = -1;
      for (const auto& [k, v] : oLabels_)
        if (best < 0 || std::abs(k - label) < std::abs(best - label)) best = k;
      if (best >= 0) help = "the nearest program number is O" + std::to_string(best);
      diags_.error(Code::SubprogramNotFound, src_, p->span(),
                   "no subprogram O" + std::to_string(label) + " or N" + std::to_string(label) + " in this file", help);
      return Flow::Continue;
    }
    if (stack_.size() >= options_.maxCallDepth) {
      diags_.error(
          Code::CallTooDeep, src_, m.span(),
          "subprogram calls nest deeper than " + std::to_string(options_.maxCallDepth) + " levels (recursion?)");
      return Flow::Stop;
    }
    stack_.push_back({pc + 1, target, repeats, pc});
    next = target;
    return Flow::Continue;
  }

  const Program& program_;
  const SourceFile* src_;
  const InterpreterOptions& options_;
  Diagnostics& diags_;
  Toolpath toolpath_;

  // Modal state (the interpreter's "settings").
  Vec2 position_{0, 0};  // in the toolpath frame
  Vec2 shift_{0, 0};     // program coordinates = toolpath coordinates + shift (G92)
  Motion motion_ = Motion::None;
  const Word* motionWord_ = nullptr;
  bool incremental_ = false;
  bool inch_ = false;
  double feed_ = 0.0;
  WireOffset wireOffset_ = WireOffset::Off;
  geometry::ArcTolerance tolerance_{};
  std::vector<Frame> stack_;
  std::unordered_map<long, std::size_t> oLabels_, nLabels_;

  // Say it once.
  std::unordered_set<char> warnedLetters_;
  std::unordered_set<long> warnedM_;
  bool warnedOffset_ = false, warnedOffsetUnknown_ = false, warnedWorkOffset_ = false;
};

}  // namespace

Toolpath interpret(const Program& program, const InterpreterOptions& options, Diagnostics& diags) {
  return Interpreter(program, options, diags).run();
}

}  // namespace kerf::converter
