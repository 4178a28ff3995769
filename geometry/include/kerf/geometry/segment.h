// Segment: the exact geometry of one move on one plane — a straight line or a circular arc.
//
// A Segment never holds sampled points; consumers ask for points with a step or a tolerance
// (tessellation.h). All lengths in mm, angles in radians (counter-clockwise positive).
#pragma once

#include "kerf/geometry/vec.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <ranges>
#include <span>
#include <type_traits>

namespace kerf::geometry {

enum class SegmentKind : std::uint8_t { Line, Arc };

/// Direction of an arc as seen from +Z: G02 is Clockwise, G03 CounterClockwise.
enum class ArcDirection : std::uint8_t { Clockwise, CounterClockwise };

struct Segment {
  Vec2 start = Vec2::Zero();
  Vec2 end = Vec2::Zero();
  // Arc only. The circle is the one about centre through start (radius() and startAngle() are
  // computed from the two, not stored: a program holds a segment per block, and these 16 bytes
  // were a fifth of a move); the end point may sit off the circle by the tolerance the arc was
  // accepted with (see arc.h), and end is kept exactly as programmed.
  Vec2 centre = Vec2::Zero();
  double sweep = 0.0;                    ///< signed: > 0 counter-clockwise, < 0 clockwise; |sweep| <= 2 pi
  SegmentKind kind = SegmentKind::Line;  ///< last, so that Move's fields fit in the padding after it

  /// A straight line from a to b.
  static Segment line(const Vec2& a, const Vec2& b) {
    Segment s;
    s.kind = SegmentKind::Line;
    s.start = a;
    s.end = b;
    return s;
  }
  /// An arc from start to end about centre. When start and end coincide (within 1e-12 of the
  /// radius) the arc is a full circle. The sweep follows the direction.
  static Segment arc(const Vec2& start, const Vec2& end, const Vec2& centre, ArcDirection dir);

  [[nodiscard]] bool isArc() const { return kind == SegmentKind::Arc; }
  /// An arc's radius, |start - centre|, mm (0 for a line): one square root.
  [[nodiscard]] double radius() const { return isArc() ? (start - centre).norm() : 0.0; }
  /// The angle of an arc's start about its centre, radians in (-pi, pi] (0 for a line): one atan2.
  /// A loop over many points of one arc takes it once.
  [[nodiscard]] double startAngle() const { return isArc() ? angleOf(start - centre) : 0.0; }
  [[nodiscard]] ArcDirection direction() const {
    return sweep < 0 ? ArcDirection::Clockwise : ArcDirection::CounterClockwise;
  }
  /// mm. Inline: the checks and the summary ask for every move's.
  [[nodiscard]] double length() const { return isArc() ? radius() * std::abs(sweep) : (end - start).norm(); }
  /// Point at parameter t in [0, 1], proportional to length. For arcs the point lies on the
  /// circle of radius `radius`; at t = 1 it is the circle point nearest the programmed end.
  [[nodiscard]] Vec2 pointAt(double t) const;
  /// Unit tangent in the direction of travel at parameter t.
  [[nodiscard]] Vec2 tangentAt(double t) const;
  /// Tight bounding box (arcs include their axis extremes). A line's inline: every check asks for
  /// every segment's.
  [[nodiscard]] Box bounds() const {
    if (kind != SegmentKind::Arc) return {start.cwiseMin(end), start.cwiseMax(end)};
    return arcBounds();
  }
  /// bounds() of an arc.
  [[nodiscard]] Box arcBounds() const;
  /// The same path travelled the other way.
  [[nodiscard]] Segment reversed() const;
  /// Parameter t in [0, 1] (proportional to length) of the segment's point nearest p.
  [[nodiscard]] double parameterOf(const Vec2& p) const;
  /// Distance (mm) from p to the nearest point of the segment.
  [[nodiscard]] double distanceTo(const Vec2& p) const;
  /// How far an arc's end lies off its circle: |end - centre| - radius, mm (0 for a line).
  [[nodiscard]] double radiusError() const { return isArc() ? (end - centre).norm() - radius() : 0.0; }
};

/// Segments read where they are: a plain array, or one member of every record of an array (the
/// lower segment of each move), a fixed number of bytes apart. The checks read a program's cut
/// path through it, so they need no copy of it. Converts from any contiguous range of Segment.
class SegmentView {
 public:
  class iterator {
   public:
    using iterator_category = std::forward_iterator_tag;
    using value_type = Segment;
    using difference_type = std::ptrdiff_t;
    using pointer = const Segment*;
    using reference = const Segment&;
    iterator() = default;
    iterator(const std::byte* at, std::size_t stride) : at_(at), stride_(stride) {}
    reference operator*() const { return *reinterpret_cast<const Segment*>(at_); }
    pointer operator->() const { return reinterpret_cast<const Segment*>(at_); }
    iterator& operator++() {
      at_ += stride_;
      return *this;
    }
    iterator operator++(int) {
      iterator was = *this;
      at_ += stride_;
      return was;
    }
    bool operator==(const iterator& o) const { return at_ == o.at_; }

   private:
    const std::byte* at_ = nullptr;
    std::size_t stride_ = sizeof(Segment);
  };

  SegmentView() = default;
  SegmentView(std::span<const Segment> s)  // NOLINT: converts like a span
      : base_(reinterpret_cast<const std::byte*>(s.data())), size_(s.size()) {}
  template <std::ranges::contiguous_range R>
  requires std::is_same_v<std::ranges::range_value_t<R>, Segment> SegmentView(
      const R& r)  // NOLINT: converts like a span
      : SegmentView(std::span<const Segment>(std::ranges::data(r), std::ranges::size(r))) {}
  /// The member `member` of each of the records.
  template <typename Record>
  static SegmentView members(std::span<const Record> records, Segment Record::*member) {
    SegmentView v;
    if (records.empty()) return v;
    v.base_ = reinterpret_cast<const std::byte*>(&(records.front().*member));
    v.stride_ = sizeof(Record);
    v.size_ = records.size();
    return v;
  }

  [[nodiscard]] std::size_t size() const { return size_; }
  [[nodiscard]] bool empty() const { return size_ == 0; }
  const Segment& operator[](std::size_t i) const { return *reinterpret_cast<const Segment*>(base_ + i * stride_); }
  [[nodiscard]] const Segment& front() const { return (*this)[0]; }
  [[nodiscard]] const Segment& back() const { return (*this)[size_ - 1]; }
  [[nodiscard]] iterator begin() const { return {base_, stride_}; }
  [[nodiscard]] iterator end() const { return {base_ + size_ * stride_, stride_}; }

 private:
  const std::byte* base_ = nullptr;
  std::size_t stride_ = sizeof(Segment);
  std::size_t size_ = 0;
};

}  // namespace kerf::geometry
