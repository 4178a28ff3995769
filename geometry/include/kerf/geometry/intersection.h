// Exact intersection of lines and arcs, and self-intersection of a path.
//
// Exact means on the segments' true geometry (lines and circular arcs), not their
// tessellation; coincidence is decided with a distance tolerance in mm.
#pragma once

#include "kerf/geometry/segment.h"

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace kerf::geometry {

struct SegmentIntersection {
  int count = 0;         ///< 0, 1 or 2 points (an overlap reports its two ends, one where they coincide)
  bool overlap = false;  ///< the segments share a stretch longer than the tolerance
  /// The first count are the points; the others are zero. Two arcs of one circle that share the
  /// whole of it have one end: the stretch closes on itself.
  Vec2 points[2] = {Vec2::Zero(), Vec2::Zero()};
};

/// Intersection of two segments within tol (mm).
SegmentIntersection intersect(const Segment& a, const Segment& b, double tol);

enum class ContactKind : std::uint8_t {
  Crossing,  ///< interiors meet
  Touch,     ///< an end point of one lies on the other (not a shared vertex)
  Overlap,   ///< a shared stretch; for neighbours, the path folds back on itself
};

struct Contact {
  std::size_t first = 0;   ///< index of the earlier segment
  std::size_t second = 0;  ///< index of the later segment
  ContactKind kind = ContactKind::Crossing;
  bool adjacent = false;  ///< the two are consecutive in the path (or last/first of a closed one)
  bool opposite = false;  ///< Overlap only: the two run in opposite directions (a retrace)
  Vec2 point = Vec2::Zero();
};

/// How findSelfIntersections looks for contacts (see there).
enum class SweepMethod : std::uint8_t {
  Auto,      ///< the box sweep within a linear budget of work, then the decision sweep
  Boxes,     ///< the box sweep alone, however long it takes
  Decision,  ///< the decision sweep first (the tests compare it with Boxes)
  Dropping,  ///< the decision sweep, then the dropping sweeps on any path that meets itself (tests)
};

struct SelfIntersectionOptions {
  double tolerance = 1e-6;        ///< mm
  bool closed = false;            ///< the last segment is a neighbour of the first
  std::size_t maxContacts = 256;  ///< stop collecting after this many
  SweepMethod method = SweepMethod::Auto;
  /// Also the first loop the path closes, as analyseClosure finds it (contour.h), from the pairs
  /// the box sweep meets: an end that comes back within the tolerance to an earlier start makes
  /// their boxes overlap.
  bool findLoop = false;
};

struct SelfIntersectionResult {
  std::vector<Contact> contacts;   ///< sorted by (first, second)
  std::size_t candidatePairs = 0;  ///< pairs whose boxes overlapped (tested exactly)
  bool truncated = false;          ///< maxContacts was reached
  /// With findLoop: true when the box sweep met every pair of segments (it went through, none was
  /// cut short at maxContacts and no segment was skipped as zero-length), and then the first loop:
  /// analyseClosure's loopFrom and loopTo, unset when the path closes none. False: the caller asks
  /// analyseClosure.
  bool loopKnown = false;
  std::optional<std::size_t> loopFrom, loopTo;
};

/// Every place where the path meets itself other than at shared vertices: two segments that meet
/// only end point to end point (a vertex visited twice, as lead-in and lead-out do, or two arcs
/// that close a circle) are not contacts. Zero-length segments are skipped.
///
/// Method: boxes sorted by x and swept, with exact tests for the pairs whose boxes overlap —
/// O(n log n + c) for c overlapping pairs, the fastest on the shapes wire programs have — within a
/// budget of work linear in n. Past it (long spikes, whose boxes all overlap), Shamos and Hoey's
/// sweep over x-monotone pieces decides whether any pair meets, testing only neighbours along the
/// sweep line: O(n log n) on any shape. A path that meets itself then has its contacts listed by
/// sweeps that drop, at each contact found, one of its two segments (listing that one's contacts
/// by a pass over every box): O(maxContacts n log n) at worst (docs/geometry.md).
SelfIntersectionResult findSelfIntersections(SegmentView path, const SelfIntersectionOptions& options = {});

}  // namespace kerf::geometry
