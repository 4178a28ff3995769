#include "kerf/converter/check/summary.h"

#include "kerf/geometry/contour.h"
#include "kerf/geometry/parallel.h"

#include <algorithm>
#include <atomic>

namespace kerf::converter {

CutPath cutPath(const Toolpath& toolpath) {
  CutPath path;
  path.segments.reserve(toolpath.moves.size());
  path.moveIndex.reserve(toolpath.moves.size());
  for (std::size_t i = 0; i < toolpath.moves.size(); ++i) {
    if (!toolpath.moves[i].isCut()) continue;
    path.segments.push_back(toolpath.moves[i].lower);
    path.moveIndex.push_back(i);
  }
  return path;
}

CutView cutView(const Toolpath& toolpath) {
  CutView view;
  const MoveList& moves = toolpath.moves;
  std::size_t first = 0, last = moves.size();
  while (first < last && !moves[first].isCut()) ++first;
  while (last > first && !moves[last - 1].isCut()) --last;
  // Whether a rapid lies between the cuts: a pass over all the moves, bound by memory, so on
  // every core.
  std::atomic<bool> rapid{false};
  geometry::parallelFor(last - first, 1 << 15, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = first + begin; i < first + end; ++i)
      if (!moves[i].isCut()) {
        rapid.store(true, std::memory_order_relaxed);
        return;
      }
  });
  if (!rapid.load()) {  // no rapid between the cuts
    view.segments =
        geometry::SegmentView::members(std::span<const Move>(moves).subspan(first, last - first), &Move::lower);
    view.moveIndex = MoveIndex(static_cast<std::uint32_t>(first), last - first);
    return view;
  }
  for (std::size_t i = first; i < last; ++i)
    if (moves[i].isCut()) view.table.push_back(static_cast<std::uint32_t>(i));
  view.copy.reserve(view.table.size());
  for (const std::uint32_t i : view.table) view.copy.push_back(moves[i].lower);
  view.segments = view.copy;
  view.moveIndex = view.table;
  return view;
}

SurfaceMeasures measureSurface(const Toolpath& toolpath) {
  SurfaceMeasures m;
  if (!toolpath.isTaper() || !toolpath.heights.known) return m;
  const std::size_t n = toolpath.moves.size();
  m.patches.resize(n);
  m.areas.resize(n, 0.0);
  const geometry::Planes& planes = toolpath.heights.planes;
  // Each move's measures are its own: on every core (a few microseconds a move).
  geometry::parallelFor(n, 2048, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      if (!toolpath.moves[i].isCut()) continue;
      m.patches[i] = geometry::measurePatch(toolpath.moves[i].lower, toolpath.upper[i], planes);
      m.areas[i] = geometry::patchArea(toolpath.moves[i].lower, toolpath.upper[i], planes);
    }
  });
  return m;
}

namespace {

/// An arc's share of a box that already holds its ends (and every other end of its stretch):
/// box.add(s.bounds()) without the arc's angles where its whole circle lies inside the box (most
/// arcs of a long program, once the box holds all of the stretch's ends): its extremes, points of
/// that circle, would not move it. The same box, bit for bit: an extreme is (c.x +- r, c.y + 0) or
/// (c.x, c.y +- r), and a box is a least and a greatest corner, which the order of adds does not
/// change.
void addArcExtremes(geometry::Box& box, const geometry::Segment& s) {
  const geometry::Vec2& c = s.centre;
  const double r = s.radius();
  if (c.x() + r <= box.max.x() && c.x() - r >= box.min.x() && c.y() + r <= box.max.y() && c.y() - r >= box.min.y())
    return;
  box.add(s.bounds());
}

/// The wire of each cut move extended to the guides: their paths' boxes (17 positions a move, the
/// ends exact) and the largest U/V between them (the patch measures' offsets, scaled).
GuideTravel guideTravel(const Toolpath& toolpath, const SurfaceMeasures& m) {
  GuideTravel g;
  const geometry::Planes& planes = toolpath.heights.planes;
  const geometry::Planes& guides = *toolpath.heights.guides;
  const double a = (guides.lower - planes.lower) / planes.height();
  const double b = (guides.upper - planes.lower) / planes.height();
  const double spread = guides.height() / planes.height();
  constexpr int kPositions = 16;
  for (std::size_t i = 0; i < toolpath.moves.size(); ++i) {
    const Move& move = toolpath.moves[i];
    if (!move.isCut()) continue;
    const geometry::Segment& lo = move.lower;
    const geometry::Segment& up = toolpath.upper[i];
    for (int k = 0; k <= kPositions; ++k) {
      const double t = static_cast<double>(k) / kPositions;
      const geometry::Vec2 l = k == kPositions ? lo.end : lo.pointAt(t);
      const geometry::Vec2 u = k == kPositions ? up.end : up.pointAt(t);
      g.lower.add(l + a * (u - l));
      g.upper.add(l + b * (u - l));
    }
    const geometry::PatchMeasures& p = m.patches[i];
    if (p.maxOffsetX.value * spread > g.uvX) {
      g.uvX = p.maxOffsetX.value * spread;
      g.uvXMove = i;
      g.uvXLine = move.line;
    }
    if (p.maxOffsetY.value * spread > g.uvY) {
      g.uvY = p.maxOffsetY.value * spread;
      g.uvYMove = i;
      g.uvYLine = move.line;
    }
  }
  return g;
}

TaperSummary summarizeTaper(const Toolpath& toolpath, const SurfaceMeasures& m) {
  TaperSummary t;
  t.dialect = toolpath.dialect;
  t.heights = toolpath.heights;
  bool first = true;
  for (std::size_t i = 0; i < toolpath.moves.size(); ++i) {
    const Move& move = toolpath.moves[i];
    if (!move.isCut()) continue;
    ++t.patches;
    t.lowerLength += move.lower.length();
    t.upperLength += toolpath.upper[i].length();
    t.area += m.areas[i];
    const geometry::PatchMeasures& p = m.patches[i];
    if (first || p.maxSlope.value > t.maxSlopeDegrees / geometry::kDegreesPerRadian) {
      t.maxSlopeDegrees = p.maxSlope.value * geometry::kDegreesPerRadian;
      t.maxSlopeMove = i;
      t.maxSlopeLine = move.line;
    }
    if (first || p.minSlope.value < t.minSlopeDegrees / geometry::kDegreesPerRadian) {
      t.minSlopeDegrees = p.minSlope.value * geometry::kDegreesPerRadian;
      t.minSlopeMove = i;
      t.minSlopeLine = move.line;
    }
    first = false;
  }
  if (toolpath.heights.guides && toolpath.heights.known) t.guides = guideTravel(toolpath, m);
  return t;
}

}  // namespace

// The cut moves sampled where they lie, among the rapids: no copy of the path. In stretches of a
// fixed length whose figures are added in order: the sums do not depend on the number of threads
// (a program of one stretch adds them move by move, as one thread would).
struct SummaryMaker::Stretch {
  explicit Stretch(const geometry::Sampling& sampling) : sampler(sampling, nullptr) {}
  std::size_t cutMoves = 0, rapidMoves = 0, lines = 0, arcs = 0, upperLines = 0, upperArcs = 0;
  double cutLength = 0.0, rapidLength = 0.0;
  geometry::Box bounds;
  geometry::PathSampler sampler;
};

namespace {
constexpr std::size_t kStretch = 4096;
}  // namespace

SummaryMaker::SummaryMaker(const Toolpath& toolpath, const geometry::Sampling& sampling)
    : toolpath_(toolpath),
      sampling_(sampling),
      stretches_((toolpath.moves.size() + kStretch - 1) / kStretch, Stretch(sampling)) {}

SummaryMaker::~SummaryMaker() = default;

std::size_t SummaryMaker::pieces() const { return stretches_.size(); }

void SummaryMaker::makePiece(std::size_t k) {
  Stretch& part = stretches_[k];
  const bool taper = toolpath_.isTaper();
  const std::size_t n = toolpath_.moves.size();
  for (std::size_t i = k * kStretch; i < std::min(n, (k + 1) * kStretch); ++i) {
    const Move& m = toolpath_.moves[i];
    if (!m.isCut()) {
      ++part.rapidMoves;
      part.rapidLength += m.lower.length();
      continue;
    }
    ++part.cutMoves;
    if (m.kind == MoveKind::Arc)
      ++part.arcs;
    else
      ++part.lines;
    if (taper) ++(toolpath_.upper[i].isArc() ? part.upperArcs : part.upperLines);
    part.bounds.add(m.lower.start);
    part.bounds.add(m.lower.end);
    part.cutLength += part.sampler.add(m.lower);
  }
  // The arcs' extremes once the box holds every end of the stretch (addArcExtremes).
  for (std::size_t i = k * kStretch; i < std::min(n, (k + 1) * kStretch); ++i)
    if (const Move& m = toolpath_.moves[i]; m.isCut() && m.lower.isArc()) addArcExtremes(part.bounds, m.lower);
}

Summary SummaryMaker::finish(const SurfaceMeasures* measures) const {
  const Toolpath& toolpath = toolpath_;
  Summary s;
  s.format = toolpath.format;
  s.reading = toolpath.reading;
  s.dialect = toolpath.dialect;
  s.blocks = toolpath.blocks;
  s.moves = toolpath.moves.size();
  s.taperProgram = toolpath.isTaper();
  geometry::PathSampler sampler(sampling_, nullptr);
  for (const Stretch& part : stretches_) {
    s.cutMoves += part.cutMoves;
    s.rapidMoves += part.rapidMoves;
    s.lines += part.lines;
    s.arcs += part.arcs;
    s.upperLines += part.upperLines;
    s.upperArcs += part.upperArcs;
    s.cutLength += part.cutLength;
    s.rapidLength += part.rapidLength;
    s.bounds.add(part.bounds);
    sampler.append(part.sampler);
  }
  s.sampling = sampling_;
  s.points = sampler.stats();
  if (toolpath.isTaper() && toolpath.heights.known) {
    if (measures && measures->patches.size() == toolpath.moves.size()) {
      s.taper = summarizeTaper(toolpath, *measures);
    } else {
      s.taper = summarizeTaper(toolpath, measureSurface(toolpath));
    }
  }
  return s;
}

Summary summarize(const Toolpath& toolpath, const geometry::Sampling& sampling, const SurfaceMeasures* measures) {
  SummaryMaker maker(toolpath, sampling);
  geometry::parallelFor(maker.pieces(), 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) maker.makePiece(k);
  });
  return maker.finish(measures);
}

}  // namespace kerf::converter
