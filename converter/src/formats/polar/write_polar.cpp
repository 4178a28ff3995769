// Polar X/C output for mill-turn lathes without a Y axis (seed 002, docs/polar.md).
//
// A converter changes only what it converts. An ISO source is written line by line: a block that
// moves the face point has its face words (X Y C, I J R, the motion code, G12.1/G13.1, G90/G91)
// replaced by X/C points, in their place; every other word (N, Z, W, F, S, M, T, comments, the
// program number) stays as written, and a block that moves nothing is copied (less G12.1/G13.1,
// which explicit X/C needs no more). No move is added. Where a block runs more than once (a
// subprogram call, a repeat), the moves are written out in the order they run, each with its
// block's other words (note K0809). A source with no blocks (3B, a drawing) gives its moves alone.
#include "kerf/converter/formats/polar/write_polar.h"

#include "kerf/converter/nc/number_format.h"
#include "kerf/converter/nc/program.h"
#include "kerf/geometry/polar.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace kerf::converter {

namespace {

/// No polar file is built longer than this (points): a tolerance far too fine is refused.
constexpr std::size_t kMaxPolarPoints = 20'000'000;

using geometry::PolarPoint;

bool isG(const Word& w, double value) { return w.letter == 'G' && w.isNumber() && std::abs(w.value - value) < 1e-9; }
bool isPolarModeWord(const Word& w) { return isG(w, 12.1) || isG(w, 13.1) || isG(w, 112) || isG(w, 113); }
bool isMotionWord(const Word& w) { return isG(w, 0) || isG(w, 1) || isG(w, 2) || isG(w, 3); }

/// The words an X/C point replaces in a block that moves: the face point, the arc, the motion,
/// the polar mode and the distance mode (the points are absolute).
bool isConverted(const Word& w) {
  return w.letter == 'X' || w.letter == 'Y' || w.letter == 'C' || w.letter == 'I' || w.letter == 'J' ||
         w.letter == 'R' || isMotionWord(w) || isPolarModeWord(w) || isG(w, 90) || isG(w, 91);
}

/// Words that start, end or jump in a program: left out where calls and repeats are written out.
bool isFlowWord(const Word& w) {
  return w.letter == 'O' || w.letter == 'P' || w.letter == 'L' ||
         (w.letter == 'M' && (std::abs(w.value - 98) < 1e-9 || std::abs(w.value - 99) < 1e-9 ||
                              std::abs(w.value - 30) < 1e-9 || std::abs(w.value - 2) < 1e-9));
}

/// The writer's running state: the table's C (unwrapped), the motion mode the output is in, the
/// feed written, the counts.
struct PolarState {
  explicit PolarState(const PolarWriteOptions& r) : request(r) {}
  const PolarWriteOptions& request;
  int decimals = 3;
  double xScale = 2.0;  ///< diameter: twice the radius
  double grid = 1000.0;
  double toUnit = 1.0;  ///< mm to the program's length unit (1/25.4 under G20)
  PolarPoint at;
  int mode = -1;  ///< the motion mode the output is in: 0 rapid, 1 feed, -1 not known
  double feed = 0.0;
  std::size_t points = 0;
  double worst = 0.0;

  /// A diameter is twice the radius rounded to the decimals, as seed 002's post writes it (every X
  /// of its O31 listing is even in the last digit: 64.404 = 2 x 32.202, where 2 x 32.20248 rounds
  /// to 64.405), so the X written is exactly twice a radius on the grid.
  [[nodiscard]] std::string point(const PolarPoint& q) const {
    return "X" + formatFixed(std::nearbyint(q.radius * toUnit * grid) / grid * xScale, decimals) + " C" +
           formatFixed(q.c, decimals);
  }
  /// "G00 " or "G01 " when the output's mode changes to `want`; "" when it is in it.
  std::string motion(int want) {
    if (mode == want) return {};
    mode = want;
    return want == 0 ? "G00 " : "G01 ";
  }
};

/// The points of move i as lines (the first carries the motion code where the mode changes), or
/// nullopt with an error.
/// `rest` (a block's text less its converted words) with `middle` written where the first of them
/// stood (`insertAt`), a blank on either side.
std::string joinAt(const std::string& rest, std::size_t insertAt, const std::string& middle) {
  std::string head = rest.substr(0, std::min(insertAt, rest.size()));
  const std::string tail = insertAt < rest.size() ? rest.substr(insertAt) : std::string{};
  if (!head.empty() && head.back() != ' ' && head.back() != '\t') head += ' ';
  return head + middle + (tail.empty() ? "" : " " + tail);
}

std::optional<std::vector<std::string>> movePoints(const Toolpath& toolpath, std::size_t i, PolarState& st,
                                                   bool writeFeed, const SourceFile* source, Diagnostics& diags) {
  const Move& m = toolpath.moves[i];
  std::vector<std::string> lines;
  if (m.kind == MoveKind::Rapid) {
    st.at = geometry::toPolar(m.lower.end, st.at.c);
    lines.push_back(st.motion(0) + st.point(st.at));
    ++st.points;
    return lines;
  }
  const double tol = st.request.tolerance;
  const geometry::PolarSubdivision sub = geometry::subdivideForPolar(
      m.lower, st.at.c, tol, kMaxPolarPoints - std::min(st.points, kMaxPolarPoints), std::max(tol, 1e-6));
  if (sub.throughCentre) {
    diags.error(Code::PolarThroughCentre, source, m.span,
                "this move passes through the centre of the face, where C is undefined: the table would have to "
                "turn 180 degrees at once",
                "move the part's centre off the path, or split the path so it goes around the centre");
    return std::nullopt;
  }
  if (sub.overBudget) {
    diags.error(Code::CapacityTooSmall, source, m.span,
                "the tolerance " + formatFixed(tol, 6) + " mm needs more than " + std::to_string(kMaxPolarPoints) +
                    " X/C points",
                "use a coarser --tolerance");
    return std::nullopt;
  }
  st.worst = std::max(st.worst, sub.maxDeviation);
  if (sub.leadTurn) {  // at the centre: turn the table to the direction the move leaves in
    lines.push_back(st.motion(1) + st.point(sub.lead));
    ++st.points;
  }
  for (const PolarPoint& q : sub.points) {
    std::string line = st.motion(1) + st.point(q);
    if (const double mf = toolpath.feedOf(i); writeFeed && mf > 0 && mf != st.feed) {
      line += " F" + formatFixed(mf * st.toUnit, 3);
      st.feed = mf;
    }
    lines.push_back(std::move(line));
  }
  st.points += sub.points.size();
  if (!sub.points.empty()) st.at = sub.points.back();
  return lines;
}

/// The source's blocks and, for each block that moves, its moves (consecutive in the toolpath).
struct SourceMoves {
  Program program;
  std::vector<std::pair<std::size_t, std::size_t>> movesOf;  ///< per block: [first, last) move
  bool straight = true;  ///< each block runs at most once, in source order, in the main program
  std::size_t skip = 0;  ///< source bytes already in the output (a leading '%' line)
  std::unordered_map<std::uint32_t, std::size_t> blockAt;  ///< a block's index by its text's offset
};

SourceMoves mapMoves(const Toolpath& toolpath, const SourceFile& source, const ParseOptions& options) {
  SourceMoves s;
  Diagnostics scratch(16);  // the pipeline has reported the source's findings
  s.program = parseProgram(source, scratch, options);
  s.movesOf.assign(s.program.blocks.size(), {0, 0});
  for (std::size_t b = 0; b < s.program.blocks.size(); ++b) s.blockAt.emplace(s.program.blocks[b].offset, b);
  std::size_t lastBlock = 0;
  for (std::size_t i = 0; i < toolpath.moves.size(); ++i) {
    const Move& m = toolpath.moves[i];
    const auto it = s.blockAt.find(m.span.offset);
    if (it == s.blockAt.end() || m.callDepth > 0) {
      s.straight = false;
      continue;
    }
    auto& range = s.movesOf[it->second];
    if (range.second == i && range.second > range.first) {
      ++range.second;  // the block's next piece
    } else if (range.first == range.second && (i == 0 || it->second >= lastBlock)) {
      range = {i, i + 1};
    } else {
      s.straight = false;  // the block runs again, or the program jumped back
    }
    lastBlock = it->second;
  }
  return s;
}

/// The text of block b with the words `drop` picks removed (each with the blanks after it); the
/// offset of the first removed word in the result is `insertAt` (npos: none removed).
template <class Drop>
std::string blockTextWithout(const Program& program, WordReader& reader, const Block& b, Drop drop,
                             std::size_t& insertAt) {
  const std::string_view text = program.source->text();
  std::string out;
  insertAt = std::string::npos;
  std::size_t from = b.offset;
  for (const Word& w : reader.words(b)) {
    if (!drop(w)) continue;
    out.append(text.substr(from, w.offset - from));
    if (insertAt == std::string::npos) insertAt = out.size();
    from = std::size_t{w.offset} + w.length;
    while (from < std::size_t{b.offset} + b.length && (text[from] == ' ' || text[from] == '\t')) ++from;
  }
  out.append(text.substr(from, std::size_t{b.offset} + b.length - from));
  while (!out.empty() && (out.back() == ' ' || out.back() == '\t')) out.pop_back();
  return out;
}

/// The modal state the source is in, from the words it has run so far (the output follows it
/// where it copies a block, and is absolute where it writes points).
struct SourceModes {
  bool incremental = false;  ///< the source under G91
  bool outputIncremental = false;
  bool inch = false;
  /// The block's words: `copied` when the output holds them as written (its mode words then
  /// set the output's modes too).
  void read(std::span<const Word> words, bool copied, PolarState& st) {
    for (const Word& w : words) {
      if (isG(w, 90) || isG(w, 91)) {
        incremental = isG(w, 91);
        if (copied) outputIncremental = incremental;
      }
      if (isG(w, 20) || isG(w, 70)) inch = true;
      if (isG(w, 21) || isG(w, 71)) inch = false;
      if (copied && isMotionWord(w)) st.mode = isG(w, 0) ? 0 : 1;  // G02/G03 leave the output in feed
      if (copied && isG(w, 28) &&
          std::any_of(words.begin(), words.end(), [](const Word& c) { return c.letter == 'C'; }))
        st.at.c = 0.0;  // G28 C0.: the table at its reference
    }
    st.toUnit = inch ? 1.0 / 25.4 : 1.0;
  }
};

/// A G92 with face words: it sets where the face point is.
bool setsFacePoint(std::span<const Word> words) {
  const bool g92 = std::any_of(words.begin(), words.end(), [](const Word& w) { return isG(w, 92); });
  return g92 && std::any_of(words.begin(), words.end(),
                            [](const Word& w) { return w.letter == 'X' || w.letter == 'Y' || w.letter == 'C'; });
}

/// Where the first move after block b starts (in the toolpath's frame): the point a G92 there set.
std::optional<geometry::Vec2> nextStart(const Toolpath& toolpath, const SourceMoves& s, std::size_t b) {
  for (std::size_t k = b + 1; k < s.movesOf.size(); ++k)
    if (s.movesOf[k].first < s.movesOf[k].second) return toolpath.moves[s.movesOf[k].first].lower.start;
  return std::nullopt;
}

/// Every line of the source in place, the blocks that move with their words converted.
bool writeInPlace(const Toolpath& toolpath, const SourceMoves& s, PolarState& st, std::string& text,
                  const SourceFile* source, Diagnostics& diags) {
  const Program& program = s.program;
  WordReader reader(program);
  SourceModes modes;
  const std::string_view all = source->text();
  std::size_t copied = s.skip;  // the source text up to here is in the output
  for (std::size_t b = 0; b < program.blocks.size(); ++b) {
    const Block& block = program.blocks[b];
    text.append(all.substr(copied, block.offset - copied));
    copied = std::size_t{block.offset} + block.length;
    const auto [first, last] = s.movesOf[b];
    std::size_t insertAt = 0;
    if (block.kind != BlockKind::Words) {
      text.append(all.substr(block.offset, block.length));
      continue;
    }
    const std::span<const Word> words = reader.words(block);
    const std::vector<Word> kept(words.begin(), words.end());
    if (first == last && setsFacePoint(kept)) {  // G92 X Y: the same point as X/C
      if (const std::optional<geometry::Vec2> p = nextStart(toolpath, s, b)) {
        std::string rest = blockTextWithout(program, reader, block, isConverted, insertAt);
        st.at = geometry::toPolar(*p, st.at.c);
        text += joinAt(rest, insertAt, st.point(st.at));
        modes.read(kept, false, st);
        continue;
      }
    }
    if (first == last) {  // moves nothing: copied, less the polar mode
      std::string line = blockTextWithout(program, reader, block, isPolarModeWord, insertAt);
      const bool axisWords = std::any_of(kept.begin(), kept.end(), [](const Word& w) {
        return w.letter == 'Z' || w.letter == 'W' || w.letter == 'X' || w.letter == 'C';
      });
      const bool ownMode =
          std::any_of(kept.begin(), kept.end(), [](const Word& w) { return isG(w, 90) || isG(w, 91); });
      if (axisWords && !ownMode && modes.incremental != modes.outputIncremental) {
        line = (modes.incremental ? "G91 " : "G90 ") + line;  // the copied axes mean what they meant
        modes.outputIncremental = modes.incremental;
      }
      modes.read(kept, true, st);
      const bool onlyPolarMode =
          line.empty() || std::all_of(line.begin(), line.end(), [](char c) { return c == ' ' || c == '\t'; });
      if (onlyPolarMode && std::any_of(kept.begin(), kept.end(), isPolarModeWord)) {
        // A line of G12.1 alone goes with its line break.
        if (copied < all.size() && all[copied] == '\r') ++copied;
        if (copied < all.size() && all[copied] == '\n') ++copied;
        continue;
      }
      text += line;
      continue;
    }
    modes.read(kept, false, st);
    const std::string rest = blockTextWithout(program, reader, block, isConverted, insertAt);
    std::string absolute;
    if (modes.outputIncremental) {
      absolute = "G90 ";  // the points are absolute
      modes.outputIncremental = false;
    }
    bool firstLine = true;
    for (std::size_t i = first; i < last; ++i) {
      std::optional<std::vector<std::string>> lines = movePoints(toolpath, i, st, false, source, diags);
      if (!lines) return false;
      for (std::string& l : *lines) {
        if (!firstLine) text += "\n";
        text += firstLine ? joinAt(rest, insertAt, absolute + l) : l;
        firstLine = false;
      }
    }
    if (firstLine) text += rest;  // every piece vanished: the rest of the block stays
  }
  text.append(all.substr(copied));
  if (!text.empty() && text.back() != '\n') text += "\n";
  return true;
}

/// The moves in the order they run, each block's other words on its first point (calls and
/// repeats written out; F written where the feed changes, in the program's unit); `s` null: the
/// moves alone.
bool writeInOrder(const Toolpath& toolpath, const SourceMoves* s, PolarState& st, std::string& text,
                  const SourceFile* source, Diagnostics& diags) {
  if (toolpath.programUnit == LengthUnit::Inch) st.toUnit = 1.0 / 25.4;  // the kept words' unit
  // The blocks that move nothing are not written here: the units, the distance mode and where the
  // path starts, said once as a wire program says them (a position set, not a move).
  text += std::string(st.toUnit == 1.0 ? "G21" : "G20") + " G90\nG92 " + st.point(st.at) + "\n";
  std::optional<WordReader> reader;
  if (s) reader.emplace(s->program);
  for (std::size_t i = 0; i < toolpath.moves.size(); ++i) {
    const Move& m = toolpath.moves[i];
    std::string rest;
    std::size_t insertAt = 0;
    const bool firstOfBlock = i == 0 || toolpath.moves[i - 1].span.offset != m.span.offset;
    const auto it =
        s ? s->blockAt.find(m.span.offset) : std::unordered_map<std::uint32_t, std::size_t>::const_iterator{};
    if (s && firstOfBlock && it != s->blockAt.end())
      rest = blockTextWithout(
          s->program, *reader, s->program.blocks[it->second],
          [](const Word& w) { return isConverted(w) || isFlowWord(w) || w.letter == 'F'; }, insertAt);
    std::optional<std::vector<std::string>> lines = movePoints(toolpath, i, st, true, source, diags);
    if (!lines) return false;
    for (std::size_t k = 0; k < lines->size(); ++k)
      text += (k == 0 ? joinAt(rest, insertAt, (*lines)[k]) : (*lines)[k]) + "\n";
  }
  text += "M30\n";
  return true;
}

}  // namespace

std::optional<EmitOutput> writePolar(const Toolpath& toolpath, const SourceFile* source,
                                     const PolarWriteOptions& request, Diagnostics& diags) {
  if (toolpath.moves.empty()) {
    diags.error(Code::NothingToWrite, source, SourceSpan::wholeFile(), "nothing to write: the program has no move");
    return std::nullopt;
  }
  PolarState st(request);
  // Inch programs are written in inches (the words kept are), to 5 decimals: 0.25 µm, as fine as
  // the 3 decimals of a millimetre program.
  st.decimals = request.decimals.value_or(toolpath.programUnit == LengthUnit::Inch ? 5 : 3);
  st.xScale = request.polarX == PolarX::Diameter ? 2.0 : 1.0;
  st.grid = std::pow(10.0, st.decimals);
  st.at = geometry::toPolar(toolpath.moves.front().lower.start, 0.0);
  std::optional<SourceMoves> blocks;
  if (source && request.sourceBlocks) blocks = mapMoves(toolpath, *source, *request.sourceBlocks);
  std::string text = "(written by Kerf: polar X/C from " + (source ? source->name() : std::string("a program")) +
                     "; X " + (request.polarX == PolarX::Diameter ? "diameter" : "radius") +
                     ", C degrees unwrapped; the spiral between points within " + formatFixed(request.tolerance, 4) +
                     " mm)\n";
  bool ok = false;
  if (blocks && blocks->straight) {
    // The output's first line is the source's '%' where it has one (a tape's start), then ours.
    const std::string_view all = source->text();
    std::string body;
    if (!all.empty() && all.front() == '%') {
      const std::size_t eol = all.find('\n');
      const std::size_t from = eol == std::string_view::npos ? all.size() : eol + 1;
      text = std::string(all.substr(0, from)) + (eol == std::string_view::npos ? "\n" : "") + text;
      blocks->skip = from;
    }
    ok = writeInPlace(toolpath, *blocks, st, text, source, diags);
  } else {
    if (blocks)
      diags.note(Code::OutputExpanded, source, SourceSpan::wholeFile(),
                 "the program calls or repeats blocks: the X/C program has its moves written out in the order they "
                 "run, each with its block's other words");
    ok = writeInOrder(toolpath, blocks ? &*blocks : nullptr, st, text, source, diags);
  }
  if (!ok) return std::nullopt;
  EmitOutput out;
  out.text = std::move(text);
  out.what = std::to_string(st.points) + " X/C points";
  out.detail = "; tolerance " + formatFixed(request.tolerance, 6) + " mm, largest deviation of the machine's spiral " +
               formatFixed(st.worst, 6) + " mm";
  return out;
}

}  // namespace kerf::converter
