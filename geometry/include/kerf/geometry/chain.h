// Chaining: loose lines and arcs (a drawing's entities, in any order and direction) into contours
// (docs/geometry.md, FORMATS §8).
//
// Ends closer than the tolerance are one node. Each contour is walked from an open end first (so
// an open chain comes out whole, end to end), then the remaining loops; at a node where more than
// two elements meet, the walk takes the unused element that turns least. An element walked
// against its drawn direction is reversed. A full circle is a closed contour on its own.
#pragma once

#include "kerf/geometry/segment.h"

#include <cstddef>
#include <span>
#include <vector>

namespace kerf::geometry {

struct ChainOptions {
  double tolerance = 0.001;  ///< mm: ends this close are joined
};

struct Chain {
  std::vector<std::size_t> elements;  ///< indices into the input, in walking order
  std::vector<bool> reversed;         ///< per element: walked against its own direction
  std::vector<Segment> path;          ///< the elements as walked, each start snapped to the previous end
  bool closed = false;
  double gap = 0.0;       ///< open chains: the distance from the last end back to the first start
  bool branched = false;  ///< the walk passed a node where more than two elements meet
};

/// Chains `segments` (zero-length lines are dropped). The contours come out in the order of their
/// first element in the input.
std::vector<Chain> chainSegments(std::span<const Segment> segments, const ChainOptions& options = {});

/// For every chain, how many closed chains wind round it (0 for open ones and outermost ones): a
/// contour's nesting depth, from a point of its first element (geometry/offset.h loopsAround).
std::vector<int> nestingDepths(std::span<const Chain> chains);

/// The signed area a closed path encloses (> 0 counter-clockwise), arcs included exactly.
double signedArea(std::span<const Segment> path);
/// One element's share of signedArea: the triangle it makes with the origin plus, for an arc, the
/// circular segment beyond its chord. Summed along a path that closes, it is the path's area.
double areaTerm(const Segment& s);

}  // namespace kerf::geometry
