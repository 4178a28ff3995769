// Exact offset of a chain of lines and arcs (taper contours now, the wire offset G41/G42 later).
//
// Each element is moved sideways by its own signed distance (> 0: to the left of the direction of
// travel): a line stays a line, an arc stays concentric with its radius grown or shrunk. Where two
// offset elements do not meet, the corner is sharp: both are extended (lines as infinite lines,
// arcs as full circles) to the intersection nearest the original joint, the rule NC controls use
// for sharp taper corners (docs/taper.md). Where they already meet (a tangent joint with equal
// distances) that common point is the corner.
#pragma once

#include "kerf/geometry/segment.h"

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace kerf::geometry {

/// The element moved by d (left positive), not trimmed. Nothing when an arc's radius would be
/// <= 0 (the offset collapses it).
std::optional<Segment> offsetSegment(const Segment& s, double d);

enum class OffsetProblem : std::uint8_t {
  Collapsed,  ///< an arc whose radius the offset makes zero or negative: it becomes a point
  Reversed,   ///< trimming at the corners turns the element round: the offset swallows it
  NoCorner,   ///< the two offset elements never meet (parallel lines with different distances)
};

struct OffsetIssue {
  std::size_t index = 0;  ///< element (for NoCorner: the first of the two at the corner)
  OffsetProblem problem = OffsetProblem::Collapsed;
};

struct OffsetChainOptions {
  /// The chain's first point is not moved: the first element runs from the original start to its
  /// offset end (how a taper or a cutter compensation starts up on a line).
  bool anchorStart = false;
  /// The chain's last point is not moved (how it is cancelled).
  bool anchorEnd = false;
  /// The chain is a loop: the last element's end meets the first's start at a corner too.
  bool closed = false;
  double tolerance = 1e-9;  ///< mm: offset ends closer than this already meet
};

struct OffsetChainResult {
  std::vector<Segment> segments;  ///< one per input element, in order, each joined to the next
  std::vector<OffsetIssue> issues;
};

/// Offsets every element of chain by distances[i] and joins them at sharp corners. A collapsed
/// arc shrinks to a point where its neighbours' offsets meet (the rounded corner of a punch
/// becomes a sharp corner on the other plane) and is reported; the result still pairs 1:1 with
/// the input.
OffsetChainResult offsetChain(std::span<const Segment> chain, std::span<const double> distances,
                              const OffsetChainOptions& options = {});

}  // namespace kerf::geometry
