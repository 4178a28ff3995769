// 2-axis ISO interpreter. The phase order is documented in interpreter.h.
//
// Sections: 1. G and M code tables
//           2. reading a block (phase 1)
//           3. the machine state and the executor (phases 2-4)
//           4. program flow: labels, M98/M99, limits
#include "kerf/converter/interpreter.h"

#include "kerf/converter/dialect.h"
#include "kerf/geometry/arc.h"
#include "kerf/geometry/offset.h"

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

enum class Group : std::uint8_t {
  Motion,
  NonModal,
  Plane,
  Units,
  Offset,
  Distance,
  WorkOffset,
  Taper,
  ColonMode,
  Count
};

struct GCodeInfo {
  int tenths;  // G code x 10 (G12.1 is 121)
  Group group;
};

constexpr std::array<GCodeInfo, 30> kGCodes = {{
    {0, Group::Motion},       {10, Group::Motion},      {20, Group::Motion},      {30, Group::Motion},
    {40, Group::NonModal},    {920, Group::NonModal},   {170, Group::Plane},      {180, Group::Plane},
    {190, Group::Plane},      {200, Group::Units},      {210, Group::Units},      {700, Group::Units},
    {710, Group::Units},      {400, Group::Offset},     {410, Group::Offset},     {420, Group::Offset},
    {900, Group::Distance},   {910, Group::Distance},   {540, Group::WorkOffset}, {550, Group::WorkOffset},
    {560, Group::WorkOffset}, {570, Group::WorkOffset}, {580, Group::WorkOffset}, {590, Group::WorkOffset},
    {500, Group::Taper},      {510, Group::Taper},      {520, Group::Taper},      {1400, Group::ColonMode},
    {1410, Group::ColonMode}, {1420, Group::ColonMode},
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
  double tanLeft = 0.0;  // tan(angle), > 0 leaning left of travel
  bool start = false;    // the move that starts the taper (its start stays vertical)
  bool end = false;      // the move that ends it (its end is vertical again)
};

struct Height {
  double value = 0.0;  // mm
  std::string source;
};

class Interpreter {
 public:
  Interpreter(const Program& program, const InterpreterOptions& options, Diagnostics& diags)
      : program_(program), src_(program.source), options_(options), diags_(diags) {}

  Toolpath run() {
    chooseDialect();
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
    resolveHeights();
    if (dialect_ == Dialect::XyuvRel) resolveRel();
    if (dialect_ == Dialect::TaperAngle) resolveTaperAngle();
    return std::move(toolpath_);
  }

  void chooseDialect() {
    if (options_.dialect) {
      dialect_ = *options_.dialect;
    } else {
      const DialectDetection d = detectDialect(program_);
      dialect_ = d.dialect;
      if (d.ambiguous()) {
        std::string list, help;
        for (Dialect c : d.candidates) {
          list += std::string(list.empty() ? "" : " or ") + dialectName(c);
          help += std::string(help.empty() ? "choose with " : " or ") + "--dialect " + dialectName(c);
        }
        diags_.error(Code::DialectAmbiguous, src_, d.span,
                     "the 4-axis words fit more than one dialect, " + list + ": " + d.reason, help);
      } else if (dialect_ != Dialect::Plain) {
        diags_.note(Code::DialectChosen, src_, d.span,
                    std::string("read as ") + dialectName(dialect_) + " (4-axis taper), from " + d.reason,
                    "override with --dialect");
      }
    }
    toolpath_.dialect = dialect_;
  }

  /// Heights written outside the words: Sodick TP/TN, LinuxCNC AXIS comments (mm).
  Height heightOf(const HeightWord& w) const {
    double v = w.value;
    if (!w.hasPoint && options_.integerUnit == IntegerUnit::Micrometre) v *= 0.001;
    static constexpr const char* kNames[] = {"TP", "TN", "(AXIS,XY_Z_POS)", "(AXIS,UV_Z_POS)"};
    return {v, std::string(kNames[static_cast<int>(w.kind)]) + " on line " + std::to_string(w.line)};
  }

  /// The planes: command line first, then the program (FORMATS.md §2; docs/taper.md lists the
  /// order and the assumptions).
  void resolveHeights() {
    std::optional<Height> xyZ, uvZ, tp, tn;
    for (const HeightWord& w : program_.heights) {
      switch (w.kind) {
        case HeightWord::Kind::SodickProgramPlane: tp = heightOf(w); break;
        case HeightWord::Kind::SodickLowerPlane: tn = heightOf(w); break;
        case HeightWord::Kind::LinuxCncXyPlane: xyZ = heightOf(w); break;
        case HeightWord::Kind::LinuxCncUvPlane: uvZ = heightOf(w); break;
      }
    }
    Height lower{0.0, "the lower plane at z = 0"};
    if (options_.lowerZ)
      lower = {*options_.lowerZ, "--lower-z"};
    else if (xyZ)
      lower = *xyZ;
    // Sodick: TP is the programmed contour's plane, TN the lower plane, both from the same datum.
    std::optional<double> sodickProgram;
    if (tp) sodickProgram = tp->value - (tn ? tn->value : 0.0);
    std::optional<Height> upper;
    if (options_.upperZ)
      upper = Height{*options_.upperZ, "--upper-z"};
    else if (options_.thickness)
      upper = Height{lower.value + *options_.thickness, "--thickness"};
    else if (uvZ)
      upper = uvZ;
    else if (fileThickness_)
      upper = Height{lower.value + fileThickness_->value, fileThickness_->source};
    else if (sodickProgram && *sodickProgram > 0)
      upper = Height{lower.value + *sodickProgram, tp->source + " (the program plane taken as the upper plane)"};
    PlaneHeights& h = toolpath_.heights;
    h.planes.lower = lower.value;
    h.programZ = options_.programZ ? *options_.programZ
                 : fileProgramZ_   ? lower.value + fileProgramZ_->value
                 : sodickProgram   ? lower.value + *sodickProgram
                                   : lower.value;
    const SourceSpan where = program_.blocks.empty() ? SourceSpan::wholeFile() : program_.blocks.front().span();
    if (upper && upper->value > lower.value) {
      h.planes.upper = upper->value;
      h.known = true;
      h.source = "lower z " + fmt3(lower.value) + " (" + lower.source + "), upper z " + fmt3(upper->value) + " (" +
                 upper->source + ")";
    } else if (upper) {
      diags_.error(Code::HeightsMissing, src_, where,
                   "the upper plane (z " + fmt3(upper->value) + ", " + upper->source +
                       ") is not above the lower plane (z " + fmt3(lower.value) + ", " + lower.source + ")");
    } else if (dialect_ != Dialect::Plain) {
      diags_.error(Code::HeightsMissing, src_, where,
                   std::string("this ") + dialectName(dialect_) +
                       " program gives no heights for its planes, and a taper needs them",
                   "give --thickness H or --upper-z Z (in the program: M101 P, G92 I, TP/TN or (AXIS,UV_Z_POS,z))");
    }
  }

  void reportOffsetIssues(const geometry::OffsetChainResult& r, const std::vector<std::size_t>& moveOf,
                          const std::vector<double>& distance, const char* plane) {
    for (const geometry::OffsetIssue& issue : r.issues) {
      const std::size_t mi = moveOf[issue.index];
      const Move& m = toolpath_.moves[mi];
      std::string message;
      switch (issue.problem) {
        case geometry::OffsetProblem::Collapsed:
          message = std::string("the taper offset of ") + fmt3(std::abs(distance[issue.index])) + " mm on the " +
                    plane + " plane is larger than this arc's radius " + fmt3(m.lower.radius) +
                    " mm: there the arc shrinks to a sharp corner";
          break;
        case geometry::OffsetProblem::Reversed:
          message = std::string("the taper offset of ") + fmt3(std::abs(distance[issue.index])) + " mm on the " +
                    plane + " plane swallows this move: between its corners it would run backwards";
          break;
        case geometry::OffsetProblem::NoCorner:
          message = std::string("on the ") + plane +
                    " plane the offsets of this move and the next never meet (parallel, with different angles)";
          break;
      }
      Diagnostic d;
      d.severity = issue.problem == geometry::OffsetProblem::Collapsed ? Severity::Warning : Severity::Error;
      d.code = Code::OffsetCollapses;
      d.source = src_;
      d.span = m.span;
      d.message = std::move(message);
      d.move = mi;
      d.point = geometry::Vec3(m.lower.start.x(), m.lower.start.y(), toolpath_.heights.programZ);
      diags_.report(std::move(d));
    }
  }

  /// taper-angle: each run of leaning moves becomes an offset chain on each plane.
  void resolveTaperAngle() {
    if (!toolpath_.heights.known) return;  // the upper contour stays vertical; an error says why
    const double zl = toolpath_.heights.planes.lower, zu = toolpath_.heights.planes.upper;
    const double zp = toolpath_.heights.programZ;
    std::size_t k = 0;
    while (k < taperRecords_.size()) {
      std::size_t e = k + 1;
      while (e < taperRecords_.size() && taperRecords_[e].index == taperRecords_[e - 1].index + 1 &&
             !taperRecords_[e].start && !taperRecords_[e - 1].end)
        ++e;
      std::vector<Segment> chain;
      std::vector<double> up, down;
      std::vector<std::size_t> moveOf;
      for (std::size_t q = k; q < e; ++q) {
        chain.push_back(toolpath_.moves[taperRecords_[q].index].lower);
        up.push_back(taperRecords_[q].tanLeft * (zu - zp));
        down.push_back(taperRecords_[q].tanLeft * (zl - zp));
        moveOf.push_back(taperRecords_[q].index);
      }
      geometry::OffsetChainOptions opts;
      opts.anchorStart = taperRecords_[k].start;
      opts.anchorEnd = taperRecords_[e - 1].end;
      const geometry::OffsetChainResult upper = geometry::offsetChain(chain, up, opts);
      reportOffsetIssues(upper, moveOf, up, "upper");
      for (std::size_t q = 0; q < chain.size(); ++q) toolpath_.upper[moveOf[q]] = upper.segments[q];
      if (zp != zl) {
        const geometry::OffsetChainResult lower = geometry::offsetChain(chain, down, opts);
        reportOffsetIssues(lower, moveOf, down, "lower");
        for (std::size_t q = 0; q < chain.size(); ++q) toolpath_.moves[moveOf[q]].lower = lower.segments[q];
      }
      k = e;
    }
  }

  /// xyuv-rel: the programmed contour and the U V offsets give both planes. With the program
  /// plane on the lower plane (the default) the heights are not needed.
  void resolveRel() {
    const PlaneHeights& h = toolpath_.heights;
    double f = 0.0;  // lower = programmed - f * offset, upper = programmed + (1 - f) * offset
    if (h.programZ != h.planes.lower) {
      if (!h.known) return;
      f = (h.programZ - h.planes.lower) / h.planes.height();
    }
    const double g = 1.0 - f;
    for (const RelRecord& r : relRecords_) {
      Move& m = toolpath_.moves[r.index];
      const Segment p = m.lower;
      const Vec2 us = p.start + g * r.offsetStart, ue = p.end + g * r.offsetEnd;
      const Vec2 ls = p.start - f * r.offsetStart, le = p.end - f * r.offsetEnd;
      if (!p.isArc()) {
        toolpath_.upper[r.index] = Segment::line(us, ue);
        m.lower = Segment::line(ls, le);
        continue;
      }
      const geometry::ArcBuild upper =
          geometry::arcFromCentre(us, ue, p.centre + g * r.centreShift, p.direction(), r.tolerance);
      if (upper.status != geometry::ArcStatus::Ok) {
        diags_.error(Code::ArcEndOffCircle, src_, m.span,
                     "the upper arc (from U V and K L) ends " + fmt3(std::abs(upper.radiusError)) +
                         " mm off the circle through its start",
                     "K L give the vector from the lower arc's centre to the upper arc's centre");
        toolpath_.upper[r.index] = Segment::line(us, ue);
      } else {
        toolpath_.upper[r.index] = upper.arc;
      }
      if (f != 0.0) {
        const geometry::ArcBuild lower =
            geometry::arcFromCentre(ls, le, p.centre - f * r.centreShift, p.direction(), r.tolerance);
        if (lower.status == geometry::ArcStatus::Ok) m.lower = lower.arc;
      }
    }
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

  static bool isMotionG(const Word& w) { return w.value >= 0 && w.value <= 3 && w.value == std::floor(w.value); }
  static bool isUpperLetter(char c) {
    return c == 'X' || c == 'Y' || c == 'U' || c == 'V' || c == 'I' || c == 'J' || c == 'R' || c == 'K' || c == 'L';
  }
  [[nodiscard]] bool splitsBlocks() const {
    return dialect_ == Dialect::XyuvAbs || dialect_ == Dialect::XyuvRel || dialect_ == Dialect::SodickColon;
  }

  void readWord(const Word& w, BlockWords& bw) {
    if (w.letter == 'G') {
      const int tenths = static_cast<int>(std::lround(w.value * 10));
      if (std::abs(w.value * 10 - tenths) > 1e-6 || w.value < 0) {
        diags_.error(Code::UnknownGCode, src_, w.span(), "G code must be a whole number or have one decimal");
        bw.bad = true;
        return;
      }
      const GCodeInfo* info = findGCode(tenths);
      if (!info) {
        const std::string_view raw = src_->text().substr(w.offset, w.length);
        if (tenths == 121 || tenths == 131) {
          diags_.error(Code::UnknownGCode, src_, w.span(),
                       gName(tenths) + " (polar coordinate interpolation) is not supported yet");
        } else {
          diags_.error(Code::UnknownGCode, src_, w.span(), "unknown G code " + std::string(raw), suggestGCode(raw));
        }
        bw.bad = true;
        return;
      }
      const auto gi = static_cast<std::size_t>(info->group);
      if (bw.g[gi]) {
        diags_.error(
            Code::ModalGroupConflict, src_, w.span(),
            gName(tenths) + " and " + gName(bw.gTenths[gi]) + " are in the same group and cannot share a block");
        bw.bad = true;
        return;
      }
      bw.g[gi] = &w;
      bw.gTenths[gi] = tenths;
      return;
    }
    if (w.letter == 'M') {
      if (bw.mCount == bw.m.size()) {
        diags_.error(Code::TooManyMCodes, src_, w.span(),
                     "more than " + std::to_string(bw.m.size()) + " M codes in one block");
        bw.bad = true;
        return;
      }
      bw.m[bw.mCount++] = &w;
      return;
    }
    const auto li = static_cast<std::size_t>(w.letter - 'A');
    if (bw.letter[li]) {
      diags_.error(Code::RepeatedWord, src_, w.span(),
                   std::string("word '") + w.letter + "' appears twice on the same side of the block");
      bw.bad = true;
      return;
    }
    bw.letter[li] = &w;
  }

  /// Phase 1. In a two-sided dialect the upper side's coordinates and motion word go to ubw;
  /// every other word (F, M, modal G codes) belongs to the block as a whole.
  bool readBlock(const Block& block, BlockWords& bw, BlockWords& ubw) {
    const bool split = splitsBlocks();
    const auto words = program_.wordsOf(block);
    for (std::size_t k = 0; k < words.size(); ++k) {
      const Word& w = words[k];
      const bool upperSide =
          split && k >= block.upperFrom && (isUpperLetter(w.letter) || (w.letter == 'G' && isMotionG(w)));
      readWord(w, upperSide ? ubw : bw);
    }
    return !bw.bad && !ubw.bad;
  }

  /// Words that belong to another dialect than the one in force. Reports and returns false.
  bool checkDialectWords(const Block& block, const BlockWords& bw, const BlockWords& ubw, bool setPosition) {
    const std::string as = std::string(" (this program is read as ") + dialectName(dialect_) + ")";
    const std::string choose = "choose the dialect with --dialect";
    auto refuse = [&](const Word* w, const std::string& message, const std::string& help = {}) {
      diags_.error(Code::WordNotInDialect, src_, w ? w->span() : block.span(), message + as, help);
      return false;
    };
    const bool upperContourWords = dialect_ == Dialect::XyuvAbs || dialect_ == Dialect::XyuvRel;
    for (const BlockWords* side : {&bw, &ubw}) {
      if (!upperContourWords && !setPosition && (side->has('U') || side->has('V')))
        return refuse(side->has('U') ? (*side)['U'] : (*side)['V'], "U/V give the upper contour of a 4-axis program",
                      dialect_ == Dialect::SodickColon ? "in sodick-colon the upper contour follows ':' as X Y"
                                                       : choose + " xyuv-abs or xyuv-rel");
    }
    if (block.colon && dialect_ != Dialect::SodickColon)
      return refuse(nullptr, "':' separates the lower and upper contours of a Sodick 4-axis program",
                    choose + " sodick-colon");
    if (const Word* t = bw.group(Group::Taper); t && dialect_ != Dialect::TaperAngle)
      return refuse(t, gName(bw.code(Group::Taper)) + " is a taper-angle command", choose + " taper-angle");
    if (const Word* c = bw.group(Group::ColonMode); c && dialect_ != Dialect::SodickColon)
      return refuse(c, gName(bw.code(Group::ColonMode)) + " is a Sodick 4-axis command", choose + " sodick-colon");
    if (dialect_ == Dialect::XyuvAbs) {
      for (char c : {'X', 'Y', 'K', 'L'})
        if (ubw.has(c))
          return refuse(ubw[c], std::string("'") + c + "' on the upper side: xyuv-abs gives the upper contour as U V",
                        "put X Y before the U V words");
    }
    if (dialect_ == Dialect::XyuvRel) {
      for (char c : {'X', 'Y', 'I', 'J', 'R'})
        if (ubw.has(c))
          return refuse(ubw[c], std::string("'") + c +
                                    "' after U V: xyuv-rel gives the upper arc by K L (lower centre to upper centre)");
      if (const Word* g = ubw.group(Group::Motion))
        return refuse(g, "a second motion word: in xyuv-rel both sides share the block's motion");
    }
    if (dialect_ == Dialect::SodickColon) {
      for (char c : {'K', 'L'})
        if (ubw.has(c)) return refuse(ubw[c], std::string("'") + c + "' has no meaning after ':'");
    }
    return true;
  }

  Flow executeBlock(std::size_t pc, std::size_t& next) {
    const Block& block = program_.blocks[pc];
    BlockWords bw, ubw;
    if (!readBlock(block, bw, ubw)) return Flow::Continue;
    const std::uint32_t blockIndex = static_cast<std::uint32_t>(pc);
    const bool setPosition = bw.group(Group::NonModal) && bw.code(Group::NonModal) == 920;
    if (!checkDialectWords(block, bw, ubw, setPosition)) return Flow::Continue;

    // Words that do nothing in this dialect.
    bool heightM = false;
    for (std::size_t k = 0; k < bw.mCount; ++k) heightM |= std::lround(bw.m[k]->value) == 100;
    for (char c : {'A', 'K', 'Q', 'Z', 'T'}) {
      if (!bw.has(c) || (c == 'Z' && setPosition) || (c == 'Q' && heightM)) continue;
      if ((c == 'A' || c == 'T') && dialect_ == Dialect::TaperAngle) continue;
      if (warnedLetters_.insert(c).second)
        diags_.warning(Code::WordIgnored, src_, bw[c]->span(),
                       std::string("word '") + c + "' has no meaning in a " + dialectName(dialect_) +
                           " wire program and is ignored");
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
    // Taper angle (G50/G51/G52 with A or T) and the Sodick different-shape mode (G140-G142).
    if (dialect_ == Dialect::TaperAngle && !executeTaperAngle(bw)) return Flow::Continue;
    if (bw.group(Group::ColonMode)) colonMode_ = bw.code(Group::ColonMode) != 1400;
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
    if (setPosition && !executeSetPosition(bw, ubw, block)) return Flow::Continue;
    // Motion
    if (const Word* mw = bw.group(Group::Motion)) {
      motion_ = motionOf(bw.code(Group::Motion));
      motionWord_ = mw;
    }
    if (!dwell && !setPosition) {
      if (!executeMotion(bw, ubw, block, blockIndex)) return Flow::Continue;
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

  static Motion motionOf(int tenths) {
    switch (tenths) {
      case 0: return Motion::Rapid;
      case 10: return Motion::Line;
      case 20: return Motion::Clockwise;
      default: return Motion::CounterClockwise;
    }
  }

  /// G92: the current position in program coordinates; in 4-axis dialects U V too, and NCVC's
  /// plane heights (I thickness, J program plane).
  bool executeSetPosition(const BlockWords& bw, const BlockWords& ubw, const Block& block) {
    const bool upperWords = ubw.has('U') || ubw.has('V') || bw.has('U') || bw.has('V');
    const bool heights = bw.has('I') || bw.has('J');
    if (!bw.has('X') && !bw.has('Y') && !upperWords && !bw.has('Z') && !heights) {
      diags_.error(Code::SetPositionWithoutAxis, src_, bw.group(Group::NonModal)->span(),
                   "G92 needs the coordinates of the current position (X, Y)");
      return false;
    }
    if (const Word* i = bw['I']) setHeight(fileThickness_, length(*i), "G92 I", block.line);
    if (const Word* j = bw['J']) setHeight(fileProgramZ_, length(*j), "G92 J", block.line);
    Vec2 programmed = position_ + shift_;
    if (const Word* x = bw['X']) programmed.x() = length(*x);
    if (const Word* y = bw['Y']) programmed.y() = length(*y);
    const bool first = toolpath_.moves.empty();
    if (first) {
      position_ = programmed;  // before any motion G92 places the start: no shift needed
      shift_ = Vec2::Zero();
      toolpath_.start = position_;
    } else {
      shift_ = programmed - position_;
    }
    const Word* u = ubw.has('U') ? ubw['U'] : bw['U'];
    const Word* v = ubw.has('V') ? ubw['V'] : bw['V'];
    if (dialect_ == Dialect::XyuvAbs) {
      Vec2 upperProgrammed = upperPosition_ + upperShift_;
      if (u) upperProgrammed.x() = length(*u);
      if (v) upperProgrammed.y() = length(*v);
      if (first) {
        upperPosition_ = (u || v) ? upperProgrammed : position_;
        upperShift_ = Vec2::Zero();
      } else {
        upperShift_ = upperProgrammed - upperPosition_;
      }
    } else if (dialect_ == Dialect::XyuvRel) {
      if (u) uvOffset_.x() = length(*u);
      if (v) uvOffset_.y() = length(*v);
    } else if (first) {
      upperPosition_ = position_;
    }
    return true;
  }

  void setHeight(std::optional<Height>& slot, double value, const char* what, std::uint32_t line) {
    slot = Height{value, std::string(what) + " on line " + std::to_string(line)};
  }

  /// G50/G51/G52 and the angle words. False (reported) for an angle NCVC refuses.
  bool executeTaperAngle(const BlockWords& bw) {
    const Word* angle = bw.has('A') ? bw['A'] : bw['T'];
    if (bw.has('A') && bw.has('T')) {
      diags_.error(Code::WordIgnored, src_, bw['T']->span(), "give the taper angle once, as A or as T");
      return false;
    }
    if (angle) {
      if (std::abs(angle->value) > 45.0) {
        diags_.error(
            Code::TaperAngleTooLarge, src_, angle->span(),
            "taper angle " + fmt3(angle->value) + " degrees is beyond 45 degrees, the limit NC controls accept");
        return false;
      }
      taperDegrees_ = angle->value;
    }
    if (bw.group(Group::Taper)) {
      const int code = bw.code(Group::Taper);
      if (code == 500) {
        taperPhase_ = taperPhase_ == TaperPhase::Starting ? TaperPhase::Off
                      : taperPhase_ == TaperPhase::On     ? TaperPhase::Ending
                                                          : taperPhase_;
      } else {
        taperSide_ = code == 510 ? 1 : -1;
        if (taperPhase_ == TaperPhase::Off || taperPhase_ == TaperPhase::Ending) taperPhase_ = TaperPhase::Starting;
      }
    }
    return true;
  }

  /// Builds one side's segment from start with the words letters x, y (end point), I J or R.
  /// Returns false after reporting why it cannot. end is set in every case.
  bool buildSide(const BlockWords& w, char xl, char yl, Motion motion, const Vec2& start, const Vec2& shift,
                 const std::string& side, const Block& block, const Word* motionWord, Segment& out, Vec2& end,
                 Move* record) {
    const bool hasCentre = w.has('I') || w.has('J');
    const bool hasRadius = w.has('R');
    Vec2 endProgram = start + shift;  // in program coordinates; unwritten axes stay
    if (const Word* x = w[xl]) endProgram.x() = incremental_ ? endProgram.x() + length(*x) : length(*x);
    if (const Word* y = w[yl]) endProgram.y() = incremental_ ? endProgram.y() + length(*y) : length(*y);
    end = endProgram - shift;
    if (motion == Motion::Rapid || motion == Motion::Line) {
      if (hasCentre || hasRadius) {
        const Word* c = hasRadius ? w['R'] : w.has('I') ? w['I'] : w['J'];
        diags_.warning(Code::WordIgnored, src_, c->span(),
                       std::string("'") + c->letter + "' has no meaning on a straight move and is ignored");
      }
      out = Segment::line(start, end);
      return true;
    }
    const ArcDirection dir = motion == Motion::Clockwise ? ArcDirection::Clockwise : ArcDirection::CounterClockwise;
    if (hasRadius && hasCentre) {
      diags_.error(Code::RadiusAndCentre, src_, w['R']->span(), side + "arc has both R and I/J: give one of them");
      return false;
    }
    if (!hasRadius && !hasCentre) {
      diags_.error(Code::ArcWithoutCentre, src_,
                   motionWord && motionWord->offset >= block.offset ? motionWord->span() : block.span(),
                   side + "arc needs its centre (I J) or its radius (R)",
                   side.empty() ? std::string{} : "in xyuv-abs and sodick-colon the upper arc has its own I J or R");
      return false;
    }
    geometry::ArcBuild build;
    if (hasRadius) {
      const double r = length(*w['R']);
      if (record) {
        record->centreForm = CentreForm::Radius;
        record->programmedRadius = r;
      }
      build = geometry::arcFromRadius(start, end, r, dir, tolerance_);
    } else {
      Vec2 ij(0, 0);
      if (const Word* i = w['I']) ij.x() = length(*i);
      if (const Word* j = w['J']) ij.y() = length(*j);
      Vec2 centre;
      CentreForm form = CentreForm::Incremental;
      switch (options_.arcCentre) {
        case ArcCentreMode::Incremental: centre = start + ij; break;
        case ArcCentreMode::Reversed:
          centre = start - ij;
          form = CentreForm::Reversed;
          break;
        case ArcCentreMode::Absolute:
          centre = ij - shift;
          form = CentreForm::Absolute;
          break;
      }
      if (record) {
        record->programmedCentreWords = ij;
        record->centreForm = form;
      }
      build = geometry::arcFromCentre(start, end, centre, dir, tolerance_);
    }
    if (build.status != geometry::ArcStatus::Ok) {
      reportArc(build, w, block, side);
      return false;
    }
    out = build.arc;
    if (record) record->radiusError = build.radiusError;
    return true;
  }

  /// Returns false when the block's motion failed (the diagnostic is reported).
  bool executeMotion(const BlockWords& bw, const BlockWords& ubw, const Block& block, std::uint32_t blockIndex) {
    const bool hasEnd = bw.has('X') || bw.has('Y');
    const bool lowerWords = hasEnd || bw.has('I') || bw.has('J') || bw.has('R');
    const bool upperWords = ubw.has('U') || ubw.has('V') || ubw.has('X') || ubw.has('Y') || ubw.has('I') ||
                            ubw.has('J') || ubw.has('R') || ubw.has('K') || ubw.has('L');
    if (!lowerWords && !upperWords) return true;  // modal words only
    if (motion_ == Motion::None) {
      const Word* w = bw.has('X')   ? bw['X']
                      : bw.has('Y') ? bw['Y']
                      : bw.has('I') ? bw['I']
                      : bw.has('J') ? bw['J']
                      : bw.has('R') ? bw['R']
                                    : nullptr;
      diags_.error(Code::NoMotionMode, src_, w ? w->span() : block.span(), "coordinates without a motion command",
                   "start the block (or an earlier one) with G00, G01, G02 or G03");
      return false;
    }
    Move move;
    move.block = blockIndex;
    move.line = block.line;
    move.span = block.span();
    move.feed = feed_;
    move.wireOffset = wireOffset_;
    move.callDepth = static_cast<std::uint16_t>(stack_.size());

    const Vec2 start = position_;
    Vec2 end = start;
    Segment lower;
    if (!buildSide(bw, 'X', 'Y', motion_, start, shift_, "", block, motionWord_, lower, end, &move)) {
      position_ = end;
      return false;
    }
    const bool straight = motion_ == Motion::Rapid || motion_ == Motion::Line;
    if (straight && !hasEnd && !upperWords) return true;  // I J R alone on a line: warned, no move
    move.kind = motion_ == Motion::Rapid ? MoveKind::Rapid : straight ? MoveKind::Line : MoveKind::Arc;
    move.lower = lower;

    Segment upper = lower;
    if (!buildUpper(bw, ubw, block, move, upper)) {
      position_ = end;
      return false;
    }
    if (move.kind == MoveKind::Line && lower.length() <= 1e-9 && upper.length() <= 1e-9)
      diags_.warning(Code::ZeroLengthMove, src_, block.span(), "move has zero length");
    push(std::move(move), upper);
    position_ = end;
    return true;
  }

  static Segment translated(Segment s, const Vec2& d) {
    s.start += d;
    s.end += d;
    s.centre += d;
    return s;
  }

  /// The upper side of the move, by dialect. False after reporting an error.
  bool buildUpper(const BlockWords& bw, const BlockWords& ubw, const Block& block, Move& move, Segment& upper) {
    switch (dialect_) {
      case Dialect::Plain:
      case Dialect::TwoFile: return true;
      case Dialect::XyuvAbs: {
        if (const Word* g = ubw.group(Group::Motion)) {
          upperMotion_ = motionOf(ubw.code(Group::Motion));
          upperMotionWord_ = g;
        } else if (bw.group(Group::Motion) || upperMotion_ == Motion::None) {
          upperMotion_ = motion_;
          upperMotionWord_ = motionWord_;
        }
        const bool moves = ubw.has('U') || ubw.has('V') || ubw.has('I') || ubw.has('J') || ubw.has('R');
        if (!moves) {  // the upper guide stays where it is
          upper = Segment::line(upperPosition_, upperPosition_);
          return true;
        }
        Vec2 end;
        const bool ok = buildSide(ubw, 'U', 'V', upperMotion_, upperPosition_, upperShift_, "upper ", block,
                                  upperMotionWord_, upper, end, nullptr);
        upperPosition_ = end;
        return ok;
      }
      case Dialect::SodickColon: {
        if (!block.colon) {
          if (colonMode_) {
            diags_.error(Code::BlockCountMismatch, src_, block.span(),
                         "this move has no upper contour: inside G141/G142 every move gives it after ':'");
            return false;
          }
          upper = translated(move.lower, upperPosition_ - move.lower.start);  // the wire keeps its lean
          upperPosition_ = upper.end;
          return true;
        }
        if (const Word* g = ubw.group(Group::Motion)) {
          upperMotion_ = motionOf(ubw.code(Group::Motion));
          upperMotionWord_ = g;
        } else if (upperMotion_ == Motion::None) {
          upperMotion_ = motion_;
          upperMotionWord_ = motionWord_;
        }
        Vec2 end;
        const bool ok = buildSide(ubw, 'X', 'Y', upperMotion_, upperPosition_, shift_, "upper ", block,
                                  upperMotionWord_, upper, end, nullptr);
        upperPosition_ = end;
        return ok;
      }
      case Dialect::XyuvRel: {
        RelRecord r;
        r.index = toolpath_.moves.size();
        r.offsetStart = uvOffset_;
        if (const Word* u = ubw['U']) uvOffset_.x() = incremental_ ? uvOffset_.x() + length(*u) : length(*u);
        if (const Word* v = ubw['V']) uvOffset_.y() = incremental_ ? uvOffset_.y() + length(*v) : length(*v);
        r.offsetEnd = uvOffset_;
        if (const Word* k = ubw['K']) r.centreShift.x() = length(*k);
        if (const Word* l = ubw['L']) r.centreShift.y() = length(*l);
        if (!move.lower.isArc() && (ubw.has('K') || ubw.has('L'))) {
          const Word* w = ubw.has('K') ? ubw['K'] : ubw['L'];
          diags_.warning(Code::WordIgnored, src_, w->span(),
                         std::string("'") + w->letter + "' gives the upper arc's centre and means nothing on a line");
        }
        r.tolerance = tolerance_;
        relRecords_.push_back(r);
        upper = translated(move.lower, r.offsetStart);  // placeholder until the heights are known
        return true;
      }
      case Dialect::TaperAngle: {
        TaperRecord t;
        t.index = toolpath_.moves.size();
        t.tanLeft = taperSide_ * std::tan(taperDegrees_ * geometry::kPi / 180.0);
        switch (taperPhase_) {
          case TaperPhase::Off: return true;
          case TaperPhase::Starting:
            t.start = true;
            taperPhase_ = TaperPhase::On;
            if (move.lower.isArc()) {
              diags_.error(Code::TaperOnArc, src_, block.span(),
                           "the taper starts on an arc: the wire cannot lean while it follows a circle",
                           "start the taper (G51/G52) on a straight move, as NC controls require");
              return false;
            }
            break;
          case TaperPhase::On: break;
          case TaperPhase::Ending:
            t.end = true;
            taperPhase_ = TaperPhase::Off;
            if (move.lower.isArc()) {
              diags_.error(Code::TaperOnArc, src_, block.span(),
                           "the taper ends (G50) on an arc: the wire cannot straighten while it follows a circle",
                           "cancel the taper before a straight move");
              return false;
            }
            break;
        }
        move.taperDegrees = static_cast<float>(taperSide_ * taperDegrees_);
        taperRecords_.push_back(t);
        return true;
      }
    }
    return true;
  }

  void reportArc(const geometry::ArcBuild& build, const BlockWords& bw, const Block& block, const std::string& side) {
    const double unit = inch_ ? 25.4 : 1.0;
    const char* u = inch_ ? " in" : " mm";
    switch (build.status) {
      case geometry::ArcStatus::RadiusTooSmall:
        diags_.error(Code::RadiusTooSmall, src_, bw['R']->span(),
                     side + "arc radius " + fmt3(std::abs(length(*bw['R'])) / unit) +
                         " is shorter than half the chord " + fmt3(build.halfChord / unit) + u);
        break;
      case geometry::ArcStatus::FullCircleWithRadius:
        diags_.error(Code::FullCircleWithRadius, src_, bw['R']->span(),
                     side + "arc ends where it starts, and R cannot describe a full circle",
                     "give the centre with I J");
        break;
      case geometry::ArcStatus::ZeroRadius:
        diags_.error(Code::ZeroRadius, src_,
                     spanOf(bw.has('R')   ? bw['R']
                            : bw.has('I') ? bw['I']
                                          : bw['J'],
                            block),
                     side + "arc radius is zero");
        break;
      case geometry::ArcStatus::EndOffCircle:
        diags_.error(Code::ArcEndOffCircle, src_, spanOf(bw.has('I') ? bw['I'] : bw['J'], block),
                     side + "arc end point is " + fmt3(std::abs(build.radiusError) / unit) + u +
                         " off the circle through the start (limit " + fmt3(tolerance_.centreAbsolute / unit) + u + ")",
                     options_.arcCentre == ArcCentreMode::Incremental
                         ? "if the post writes I J as start minus centre or as absolute centres, use --arc-centre "
                           "reversed|absolute"
                         : std::string{});
        break;
      case geometry::ArcStatus::Ok: break;
    }
  }

  void push(Move&& m, const Segment& upper) {
    toolpath_.moves.push_back(std::move(m));
    if (dialect_ != Dialect::Plain) toolpath_.upper.push_back(upper);
  }

  // ---- 4. program flow ----------------------------------------------------------------------------
  Flow executeM(const Word& m, const BlockWords& bw, std::size_t pc, std::size_t& next) {
    const long code = std::lround(m.value);
    switch (code) {
      case 0:
      case 1: return Flow::Continue;  // program stop / optional stop: the wire path goes on
      case 2:
      case 30: toolpath_.endedProperly = true; return Flow::Stop;
      case 98: return call(m, bw, pc, next);
      case 100:  // papayaved/cnc3: P guide distance, Q lower guide to workpiece bottom (not needed here)
        return Flow::Continue;
      case 101:  // papayaved/cnc3: P workpiece thickness
        if (const Word* p = bw['P']) {
          setHeight(fileThickness_, length(*p), "M101 P", program_.blocks[pc].line);
        } else {
          diags_.warning(Code::WordIgnored, src_, m.span(), "M101 sets the workpiece thickness with P, and has none");
        }
        return Flow::Continue;
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
  Dialect dialect_ = Dialect::Plain;
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

  // 4-axis state.
  Vec2 upperPosition_{0, 0};  // xyuv-abs, sodick-colon: where the upper contour is
  Vec2 upperShift_{0, 0};     // xyuv-abs: G92 U V
  Motion upperMotion_ = Motion::None;
  const Word* upperMotionWord_ = nullptr;
  Vec2 uvOffset_{0, 0};     // xyuv-rel: upper minus lower, the modal U V
  bool colonMode_ = false;  // G141/G142 in force
  TaperPhase taperPhase_ = TaperPhase::Off;
  int taperSide_ = 1;  // +1 G51 (wire leans left of travel), -1 G52
  double taperDegrees_ = 0.0;
  std::vector<RelRecord> relRecords_;
  std::vector<TaperRecord> taperRecords_;
  std::optional<Height> fileThickness_, fileProgramZ_;

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
