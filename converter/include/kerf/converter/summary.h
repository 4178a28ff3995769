// Numbers about a program: what `kerf check` prints after the diagnostics.
#pragma once

#include "kerf/converter/toolpath.h"
#include "kerf/geometry/tessellation.h"

#include <cstddef>
#include <vector>

namespace kerf::converter {

/// The cut segments in order (rapids left out), and for each the index of its Move.
struct CutPath {
  std::vector<geometry::Segment> segments;
  std::vector<std::size_t> moveIndex;
};
CutPath cutPath(const Toolpath& toolpath);

struct Summary {
  std::size_t blocks = 0;
  std::size_t moves = 0;
  std::size_t cutMoves = 0;
  std::size_t rapidMoves = 0;
  std::size_t lines = 0;
  std::size_t arcs = 0;
  double cutLength = 0.0;    ///< mm
  double rapidLength = 0.0;  ///< mm
  geometry::Box bounds;      ///< of the cut path
  geometry::Sampling sampling;
  geometry::PathSampleStats points;  ///< the cut path sampled at `sampling`
};

Summary summarize(const Program& program, const Toolpath& toolpath, const geometry::Sampling& sampling);

}  // namespace kerf::converter
