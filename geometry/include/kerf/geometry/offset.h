// Exact offsets of chains of lines and arcs, with named corner joins: sharp for taper contours
// (offsetChain), arcs for the wire offset with interference removed (wireOffset).
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

// ---- The wire offset (G41/G42, kerf cam; seed 003, CAWEP §3) ----------------------------------
//
// The path of the wire's centre at distance |d| from a contour (d > 0: left of travel):
//   1. every element is offset exactly (an arc whose radius the offset would make negative turns
//      into the reversed arc about the same centre, as the exact offset curve does);
//   2. at every corner the offsets are joined by an arc of radius |d| about the corner: at a convex
//      corner (seen from the wire) that arc is the wire rolling round it (clockwise for a left
//      offset, counter-clockwise for a right one); at a concave corner the offsets are trimmed at
//      their intersection, or, where they do not meet, joined by the short reversed arc that the
//      next step removes;
//   3. interference: the raw path is split at every point where it meets itself (all pairs of
//      pieces, not only neighbours: a box tree finds the candidates) and a piece is kept only if
//      its middle is at least |d| from the whole contour. The kept pieces are linked into loops.
// Elements whose offset vanishes completely (a slot narrower than the wire, an inside fillet
// smaller than it) are reported as lost runs, with how much material the wire leaves there.

/// One element of the wire path.
struct WirePiece {
  Segment segment;
  std::size_t element = 0;  ///< the contour element it offsets (a corner arc: the element before it)
  bool corner = false;      ///< a transition arc about a convex corner
};

/// Consecutive contour elements the wire path cannot follow at all.
struct LostRun {
  std::size_t first = 0;      ///< first element of the run
  std::size_t count = 0;      ///< elements in the run (wrapping past the end of a closed contour)
  Vec2 where = Vec2::Zero();  ///< a point of the contour in the run (the one the wire is farthest from)
  double uncut = 0.0;         ///< mm: how far that point is from what the wire cuts (distance - |d|)
  bool fillet = false;        ///< a single concave arc smaller than the offset: an inside corner radius
};

struct WireOffsetOptions {
  bool closed = true;                 ///< the contour is a loop
  double tolerance = 1e-6;            ///< mm: ends closer than this meet; distances within it count as equal
  std::size_t maxPieces = 4'000'000;  ///< raw pieces plus split points; above it the offset is refused
  /// Exact tests (a pair of raw pieces whose boxes overlap, a distance from a piece's middle to an
  /// element near it) past which the offset is refused (tooMuchWork); 0: 8 per raw piece plus
  /// 20 million (one to two seconds). Long pieces side by side whose boxes all overlap (a star of thin
  /// spikes) make the box tree's candidates grow as the square of their number.
  std::size_t maxTests = 0;
};

struct WireOffsetResult {
  /// Closed contour: the loops of the wire path (usually one; a contour pinched narrower than the
  /// wire splits into several, a part smaller than the wire into none). Open contour: the paths,
  /// in order along it (usually one).
  std::vector<std::vector<WirePiece>> paths;
  std::vector<LostRun> lost;
  std::size_t rawPieces = 0;    ///< offsets and joins before interference removal
  std::size_t splitPoints = 0;  ///< where the raw path met itself
  bool refused = false;         ///< maxPieces exceeded: nothing was computed
  bool tooMuchWork = false;     ///< maxTests exceeded: nothing was computed (refused is set too)
  std::size_t tests = 0;        ///< exact tests made (WireOffsetOptions::maxTests)
};

/// The wire-centre path at distance |d| from contour (d > 0: left of travel). The contour must be
/// connected (each element starting where the previous ends).
WireOffsetResult wireOffset(std::span<const Segment> contour, double d, const WireOffsetOptions& options = {});

/// The winding number of a closed path about p (> 0: counter-clockwise round it), on the exact
/// lines and arcs: signed crossings of the ray from p towards +x.
int windingNumber(std::span<const Segment> path, const Vec2& p);

/// For each probe i, how many of the closed paths `loops` wind round it (windingNumber != 0), the
/// loop self[i] left out: a contour's nesting depth when probe i is a point of loop self[i]. Only
/// the loops whose boxes meet the ray from a probe are asked (a box tree): the same counts as
/// asking every loop, in O(n log n + k) for the k boxes the rays meet, not O(loops x probes).
std::vector<int> loopsAround(std::span<const std::span<const Segment>> loops, std::span<const Vec2> probes,
                             std::span<const std::size_t> self);

/// The part of s between parameters t0 < t1 (proportional to length, as Segment::pointAt).
Segment subSegment(const Segment& s, double t0, double t1);

}  // namespace kerf::geometry
