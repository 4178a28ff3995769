#include "kerf/converter/summary.h"

#include "kerf/geometry/contour.h"

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

Summary summarize(const Program& program, const Toolpath& toolpath, const geometry::Sampling& sampling) {
  Summary s;
  s.blocks = program.blocks.size();
  s.moves = toolpath.moves.size();
  for (const Move& m : toolpath.moves) {
    if (!m.isCut()) {
      ++s.rapidMoves;
      s.rapidLength += m.lower.length();
      continue;
    }
    ++s.cutMoves;
    if (m.kind == MoveKind::Arc)
      ++s.arcs;
    else
      ++s.lines;
    s.cutLength += m.lower.length();
    s.bounds.add(m.lower.bounds());
  }
  s.sampling = sampling;
  const CutPath path = cutPath(toolpath);
  s.points = geometry::samplePath(path.segments, sampling, nullptr);
  return s;
}

}  // namespace kerf::converter
