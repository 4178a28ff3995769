// Private: a static bounding-box tree over a set of items (segments), for "which items come within
// r of this point" and "which items' boxes overlap this box" in O(log n + k) on ordinary shapes.
//
// Built once by median splits along the longer side of each node's box: O(n log n). Leaves hold up
// to four items. Used by the wire offset (offset.cpp) for its pair tests and distance queries.
#pragma once

#include "kerf/geometry/vec.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace kerf::geometry::detail {

class BoxTree {
 public:
  explicit BoxTree(std::vector<Box> boxes) : boxes_(std::move(boxes)) {
    order_.reserve(boxes_.size());
    for (std::size_t i = 0; i < boxes_.size(); ++i) order_.push_back(static_cast<std::uint32_t>(i));
    if (!order_.empty()) build(0, order_.size());
  }

  /// Calls f(item) for every item whose box comes within r of the box b (each item once).
  template <class F>
  void visitOverlapping(const Box& b, double r, F&& f) const {
    if (nodes_.empty()) return;
    std::uint32_t stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& n = nodes_[stack[--top]];
      if (!n.box.overlaps(b, r)) continue;
      if (n.count > 0) {
        for (std::uint32_t k = 0; k < n.count; ++k) {
          const std::uint32_t item = order_[n.first + k];
          if (boxes_[item].overlaps(b, r)) f(static_cast<std::size_t>(item));
        }
        continue;
      }
      if (top + 2 > 128) {  // cannot happen with median splits (depth <= log2 n), kept as a guard
        for (std::uint32_t k = 0; k < boxes_.size(); ++k)
          if (boxes_[k].overlaps(b, r)) f(static_cast<std::size_t>(k));
        return;
      }
      stack[top++] = n.left;
      stack[top++] = n.left + 1;
    }
  }

  [[nodiscard]] std::size_t size() const { return boxes_.size(); }

 private:
  struct Node {
    Box box;
    std::uint32_t left = 0;   ///< inner node: index of the left child (the right one follows it)
    std::uint32_t first = 0;  ///< leaf: first entry in order_
    std::uint32_t count = 0;  ///< leaf: number of items (0 for an inner node)
  };

  void build(std::size_t first, std::size_t last) {
    // Iterative over an explicit work list so that deep trees cannot overflow the call stack.
    struct Work {
      std::uint32_t node;
      std::size_t first, last;
    };
    nodes_.push_back({});
    std::vector<Work> work{{0, first, last}};
    while (!work.empty()) {
      const Work w = work.back();
      work.pop_back();
      Box box, centres;
      for (std::size_t k = w.first; k < w.last; ++k) {
        box.add(boxes_[order_[k]]);
        centres.add(0.5 * (boxes_[order_[k]].min + boxes_[order_[k]].max));
      }
      nodes_[w.node].box = box;
      if (w.last - w.first <= 4) {
        nodes_[w.node].first = static_cast<std::uint32_t>(w.first);
        nodes_[w.node].count = static_cast<std::uint32_t>(w.last - w.first);
        continue;
      }
      const int axis = (centres.max.x() - centres.min.x()) >= (centres.max.y() - centres.min.y()) ? 0 : 1;
      const std::size_t mid = w.first + (w.last - w.first) / 2;
      std::nth_element(order_.begin() + static_cast<std::ptrdiff_t>(w.first),
                       order_.begin() + static_cast<std::ptrdiff_t>(mid),
                       order_.begin() + static_cast<std::ptrdiff_t>(w.last), [&](std::uint32_t a, std::uint32_t b) {
                         return boxes_[a].min[axis] + boxes_[a].max[axis] < boxes_[b].min[axis] + boxes_[b].max[axis];
                       });
      const auto left = static_cast<std::uint32_t>(nodes_.size());
      nodes_[w.node].left = left;
      nodes_.push_back({});
      nodes_.push_back({});
      work.push_back({left, w.first, mid});
      work.push_back({left + 1, mid, w.last});
    }
  }

  std::vector<Box> boxes_;
  std::vector<std::uint32_t> order_;
  std::vector<Node> nodes_;
};

}  // namespace kerf::geometry::detail
