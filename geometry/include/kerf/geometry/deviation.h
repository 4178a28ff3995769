// How far one set of plane lines and arcs lies from another: a drawing's elements against the edge
// a program cuts (issue 43, docs/drawing.md), both ways, certified, not sampled.
//
// The set is held as lines: each of its arcs as chords that stay within `chordDeviation` of it, so
// the distance to the chords is the distance to the set within that much. The distance to one line
// segment is a convex function of the point, so over a piece of a line it is largest at the
// piece's ends, and over a piece of an arc (inside the triangle of its end points and the meeting
// point of its end tangents) at one of those three points. farthestFrom halves the element's pieces
// until that bound, taken against the chord nearest the piece's middle, is within the precision of
// the farthest distance found: coincident geometry ends at once (the bound is 0), a gap or a corner
// after a few dozen halvings.
#pragma once

#include "kerf/geometry/segment.h"

#include <cstddef>
#include <vector>

namespace kerf::geometry {

/// A set of lines and arcs prepared for distance queries: its arcs as chords, and a uniform grid
/// of the chords' bounding boxes, so that a query looks at the cells around the point first and
/// stops when no nearer chord can remain.
class DeviationSet {
 public:
  /// Arcs as chords within chordDeviation mm of them (at most maxChords in all; more: ok() is false).
  DeviationSet(SegmentView segments, double chordDeviation = 5e-5, std::size_t maxChords = 4'000'000);

  struct Chord {
    Vec2 a, b;
    std::size_t owner = 0;  ///< the set's segment it stands for
  };
  struct Hit {
    double distance = 0.0;  ///< to the chord
    std::size_t chord = 0;
  };
  /// The chord nearest p (infinite distance when the set is empty).
  [[nodiscard]] Hit nearest(const Vec2& p) const;
  [[nodiscard]] double distanceTo(const Vec2& p, std::size_t chord) const;
  /// The distance from p to the set's segment that the chord stands for (exact for an arc).
  [[nodiscard]] double ownerDistance(const Vec2& p, std::size_t chord) const {
    return segments_[chords_[chord].owner].distanceTo(p);
  }
  [[nodiscard]] const Chord& chord(std::size_t k) const { return chords_[k]; }
  /// The set's segment a chord stands for.
  [[nodiscard]] const Segment& owner(std::size_t chord) const { return segments_[chords_[chord].owner]; }
  [[nodiscard]] bool empty() const { return chords_.empty(); }
  [[nodiscard]] bool ok() const { return ok_; }
  [[nodiscard]] double chordDeviation() const { return chordDeviation_; }

 private:
  [[nodiscard]] std::size_t cellOf(double v, double lo, std::size_t n) const;
  std::vector<Segment> segments_;
  std::vector<Chord> chords_;
  double chordDeviation_ = 0.0;
  bool ok_ = true;
  Box box_;
  std::size_t nx_ = 1, ny_ = 1;
  double cell_ = 1.0;
  std::vector<std::vector<std::size_t>> cells_;
};

struct Farthest {
  double distance = 0.0;    ///< mm: the largest distance from a point of the segment to the set
  Vec2 at = Vec2::Zero();   ///< that point
  std::size_t nearest = 0;  ///< the set's segment nearest it
};

/// The farthest point of `s` from the set: its distance is within precision + the set's chord
/// deviation of the true largest distance (see the file comment); each distance reported is exact
/// to the segment whose chord was nearest (so an arc of the set against itself is 0 apart).
Farthest farthestFrom(const Segment& s, const DeviationSet& set, double precision = 1e-4);

}  // namespace kerf::geometry
