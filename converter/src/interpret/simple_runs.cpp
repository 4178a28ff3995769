// Long runs of simple blocks on every core: the same moves, in the same order, as the block loop.
//
// A simple block is plain (Block::plain: X Y I J R F and G00-G03, all numbers, one side), not
// refused by the parser, and not skipped by '/'. In a plain-dialect program that runs straight
// through, what such a block does depends on the state before it only through the position and
// the motion in force; everything else it reads (distance mode, units, shift, feed, wire offset)
// only blocks that are not simple can change. So a run of them is cut into one stretch per
// worker. A stretch learns the position and motion at its start from the blocks before it: the
// last X, the last Y and the last motion code before it give them exactly (in absolute mode the
// position is the written value minus the shift, then carried through the blocks without that
// axis the way the block loop carries it); with none of them, or in incremental mode, it carries
// the state from the start of the run.
//
// A stretch writes each block's move to the block's own slot. Anything that would say something
// (a diagnostic, a feed that changes, an arc that does not close) gives the whole window back to
// the block loop, which says it; so does a limit the window could reach. The windows' results are
// then the block loop's, bit for bit (tests/converter/interpreter_parallel_test.cpp compares them).
#include "interpreter_impl.h"

#include "kerf/geometry/memory.h"
#include "kerf/geometry/parallel.h"

namespace kerf::converter::interp {
namespace {

/// The words of a simple block, each letter at most once.
struct SimpleWords {
  const Word* g = nullptr;
  const Word* x = nullptr;
  const Word* y = nullptr;
  const Word* i = nullptr;
  const Word* j = nullptr;
  const Word* r = nullptr;
  const Word* f = nullptr;
  [[nodiscard]] bool lowerWords() const { return x || y || i || j || r; }
};

/// False when a letter comes twice (the block loop reports it).
bool readSimple(std::span<const Word> words, SimpleWords& s) {
  for (const Word& w : words) {
    const Word** slot = nullptr;
    switch (w.letter) {
      case 'G': slot = &s.g; break;
      case 'X': slot = &s.x; break;
      case 'Y': slot = &s.y; break;
      case 'I': slot = &s.i; break;
      case 'J': slot = &s.j; break;
      case 'R': slot = &s.r; break;
      case 'F': slot = &s.f; break;
      default: return false;
    }
    if (*slot) return false;
    *slot = &w;
  }
  return true;
}

}  // namespace

bool Interpreter::simpleBlock(const Block& b) const {
  return b.plain && !b.hasError && !(b.blockDelete && options_.blockDelete) && b.kind == BlockKind::Words;
}

bool Interpreter::parallelRunAllowed(bool straight) const {
  return options_.parallelRun > 0 && straight && dialect_ == Dialect::Plain && plainPath_ && !unknown_.active &&
         !pendingOffset_.get() && stack_.empty() && !toolpath_.moves.empty();
}

/// The end of the block, as buildSide computes it (program coordinates, then the toolpath frame).
Vec2 Interpreter::simpleEnd(const Word* x, const Word* y, const Vec2& start) const {
  // The two coordinates apart, then the point: written one at a time into the point and read
  // back whole, they stalled the read (a store cannot forward to a wider load), 84% of this
  // function's time. The same operations, so the same doubles.
  const Vec2 from = start + shift_;
  const double ex = x ? (incremental_ ? from.x() + length(*x) : length(*x)) : from.x();
  const double ey = y ? (incremental_ ? from.y() + length(*y) : length(*y)) : from.y();
  return Vec2(ex, ey) - shift_;
}

bool Interpreter::runSimpleStretch(std::size_t runStart, std::size_t begin, std::size_t end, Move* out,
                                   Vec2* centreWords, std::uint8_t* made, SimpleStretch& result) const {
  // The state at `begin`: from the last blocks before it that give X, Y and the motion.
  std::size_t from = runStart;
  if (!incremental_ && begin > runStart) {
    bool x = false, y = false, g = false;
    for (std::size_t b = begin; b-- > runStart && !(x && y && g);) {
      SimpleWords s;
      if (!readSimple(program_.wordsOf(program_.blocks[b]), s)) return false;
      x = x || s.x;
      y = y || s.y;
      g = g || s.g;
      if (x && y && g) from = b;
    }
  }
  Vec2 position = position_;
  Motion motion = motion_;
  for (std::size_t b = from; b < begin; ++b) {
    SimpleWords s;
    if (!readSimple(program_.wordsOf(program_.blocks[b]), s)) return false;
    if (s.g) motion = motionOf(static_cast<GCode>(static_cast<int>(s.g->value)));
    if (s.lowerWords()) position = simpleEnd(s.x, s.y, position);
  }

  const double feed = toolpath_.feeds.empty() ? 0.0 : toolpath_.feeds.back();
  const auto callDepth = static_cast<std::uint8_t>(std::min<std::size_t>(stack_.size(), 255));
  for (std::size_t b = begin; b < end; ++b) {
    const Block& block = program_.blocks[b];
    SimpleWords s;
    if (!readSimple(program_.wordsOf(block), s)) return false;
    if (s.f) {  // only the feed in force again: a new one is numbered in order by the block loop
      const double f = s.f->value * (inch_ ? 25.4 : 1.0);
      if (!(s.f->value > 0) || feedIndex_ == 0 || feedIndex_ != toolpath_.feeds.size() || f != feed) return false;
    }
    if (s.g) {
      motion = motionOf(static_cast<GCode>(static_cast<int>(s.g->value)));
      result.motionWord = s.g;
    }
    if (!s.lowerWords()) continue;  // the motion or the feed alone
    if (motion == Motion::None) return false;
    const Vec2 start = position;
    const Vec2 stop = simpleEnd(s.x, s.y, start);
    Move& move = out[b - begin];
    move = Move{};
    move.line = block.line;
    move.span = block.span();
    move.feedIndex = feedIndex_;
    move.wireOffset = wireOffset_;
    move.callDepth = callDepth;
    Vec2 written(0, 0);  // Toolpath::centreWords
    if (motion == Motion::Rapid || motion == Motion::Line) {
      if (s.i || s.j || s.r) return false;  // warned by the block loop
      move.kind = motion == Motion::Rapid ? MoveKind::Rapid : MoveKind::Line;
      move.lower = Segment::line(start, stop);
      if (move.kind == MoveKind::Line && move.lower.length() <= 1e-9) return false;  // warned
    } else {
      const geometry::ArcDirection dir =
          motion == Motion::Clockwise ? geometry::ArcDirection::Clockwise : geometry::ArcDirection::CounterClockwise;
      const bool centre = s.i || s.j;
      if (centre == (s.r != nullptr)) return false;  // both, or neither: refused by the block loop
      geometry::ArcBuild build;
      if (s.r) {
        move.centreForm = CentreForm::Radius;
        written = Vec2(length(*s.r), 0);
        build = geometry::arcFromRadius(start, stop, length(*s.r), dir, tolerance_, false);
      } else {
        Vec2 ij(0, 0);
        if (s.i) ij.x() = length(*s.i);
        if (s.j) ij.y() = length(*s.j);
        written = ij;
        Vec2 c;
        switch (options_.arcCentre) {
          case ArcCentreMode::Incremental:
            c = start + ij;
            move.centreForm = CentreForm::Incremental;
            break;
          case ArcCentreMode::Reversed:
            c = start - ij;
            move.centreForm = CentreForm::Reversed;
            break;
          case ArcCentreMode::Absolute:
            c = ij - shift_;
            move.centreForm = CentreForm::Absolute;
            break;
        }
        build = geometry::arcFromCentre(start, stop, c, dir, tolerance_, false);
        // What tallyArcCentre counts (the convention in force closed it, or the window is given back).
        ++result.tally.arcs;
        const Vec2 centres[3] = {start + ij, start - ij, ij - shift_};
        for (int k = 0; k < 3; ++k)
          if (geometry::arcFromCentre(start, stop, centres[k], dir, tolerance_, false).status ==
              geometry::ArcStatus::Ok)
            ++result.tally.closes[k];
      }
      if (build.status != geometry::ArcStatus::Ok) return false;
      move.kind = MoveKind::Arc;
      move.lower = build.arc;
      if (move.lower.anglesPending()) move.lower.completeAngles();
    }
    if (centreWords) centreWords[b - begin] = written;
    made[b - begin] = 1;
    position = stop;
  }
  result.position = position;
  result.motion = motion;
  return true;
}

bool Interpreter::runSimpleWindow(std::size_t begin, std::size_t end) {
  const std::size_t n = end - begin;
  const std::size_t base = toolpath_.moves.size();
  // Four stretches a core, taken by whichever core is free (parallelForBalanced): a core shared
  // with other work no longer holds the window up with a fixed half of it.
  const std::size_t stretches = std::max<std::size_t>(
      1,
      std::min<std::size_t>(options_.parallelStretches ? options_.parallelStretches : 4 * geometry::workerCount(), n));
  std::vector<SimpleStretch> results(stretches);
  std::vector<std::uint8_t> made(n, 0);
  toolpath_.moves.resize(base + n);
  Move* out = toolpath_.moves.data() + base;
  // The moves from here to the end of the reserve are written before they are read: pages the
  // parse gave back (releaseParsedBefore) take the place of fresh ones, from here on, so that the
  // page a window ends in is one too (geometry/memory.h).
  geometry::adoptPages(out, toolpath_.moves.data() + toolpath_.moves.capacity());
  std::vector<Vec2>& words = toolpath_.centreWords;
  const bool record = options_.recordCentreWords;
  if (record) words.resize(base + n);
  auto bound = [&](std::size_t k) { return begin + n * k / stretches; };
  geometry::parallelForBalanced(stretches, 1, [&](std::size_t kb, std::size_t ke) {
    for (std::size_t k = kb; k < ke; ++k) {
      const std::size_t at = bound(k) - begin;
      results[k].ok = runSimpleStretch(begin, bound(k), bound(k + 1), out + at,
                                       record ? words.data() + base + at : nullptr, made.data() + at, results[k]);
    }
  });
  if (!std::all_of(results.begin(), results.end(), [](const SimpleStretch& r) { return r.ok; })) {
    toolpath_.moves.resize(base);
    if (record) words.resize(base);
    return false;
  }
  // Blocks that only set the motion or the feed made no move: close the gaps, in order.
  std::size_t kept = base;
  for (std::size_t k = 0; k < n; ++k)
    if (made[k]) {
      if (kept != base + k) {
        toolpath_.moves[kept] = toolpath_.moves[base + k];
        if (record) words[kept] = words[base + k];
      }
      ++kept;
    }
  toolpath_.moves.resize(kept);
  if (record) words.resize(kept);
  if (!windowMoves_.empty() && windowMoves_.back().second == base)
    windowMoves_.back().second = kept;
  else
    windowMoves_.emplace_back(base, kept);
  for (const SimpleStretch& r : results) {
    tally_.arcs += r.tally.arcs;
    for (int k = 0; k < 3; ++k) tally_.closes[k] += r.tally.closes[k];
    if (r.motionWord) motionWord_.hold(r.motionWord);
  }
  position_ = results.back().position;
  motion_ = results.back().motion;
  // Every move of the window has the offset in force (runSimpleStretch): with none, no move
  // starts or extends a run, and the pass over them (a serial millisecond on a long program) is
  // not made.
  if (wireOffset_ != WireOffset::Off)
    for (std::size_t i = base; i < kept; ++i) noteOffsetRun(toolpath_.moves[i], i);
  executed_ += n;
  blocksInWindows_ += n;
  return true;
}

}  // namespace kerf::converter::interp
