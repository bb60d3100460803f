// SPDX-License-Identifier: GPL-3.0-or-later
// Items with a bounding box (triangles, edges) in a bounding-box tree (internal): the
// items near a point (SurfaceIndex::triangles_near), and for the surface sizings the
// nearest part of the mesh meeting a condition. Branch and bound: a subtree is skipped
// when its box is no nearer than the best found, so a query costs about the items
// nearer than its answer, not all items within a fixed reach (a grid of cells `reach`
// wide made the thickness sizing quadratic once the reach spanned the model: 35 s for
// 89K triangles at auto:0.2).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "disktune/vec3.h"

namespace disktune::detail {

class BoxTree {
 public:
  struct Box {
    Vec3 lo, hi;
  };

  explicit BoxTree(const std::vector<Box>& boxes) : boxes_(boxes) {
    order_.resize(boxes.size());
    for (std::uint32_t i = 0; i < order_.size(); ++i) order_[i] = i;
    if (!order_.empty()) build(0, order_.size());
    // The boxes in leaf order from now on: a leaf reads its boxes in a row.
    std::vector<Box> in_order(boxes_.size());
    for (std::size_t i = 0; i < order_.size(); ++i) in_order[i] = boxes_[order_[i]];
    boxes_ = std::move(in_order);
  }

  /// The smallest distance(item) over the items, each box at least that far from p being
  /// skipped; `distance` returns infinity for an item that does not qualify. `best` is
  /// the bound to start from (nothing farther counts) and the answer.
  template <class Distance>
  double nearest(Vec3 p, double best, Distance&& distance) const {
    if (!nodes_.empty()) search(0, p, best, distance);
    return best;
  }

  /// f(item) for each item whose box comes within R of p, in no set order.
  template <class F>
  void for_each_within(Vec3 p, double R, F&& f) const {
    if (nodes_.empty()) return;
    // Median splits keep the depth under 64 for any count that fits in memory, and a
    // walk holds at most one pending node per level.
    std::uint32_t stack[64];
    std::size_t size = 0;
    stack[size++] = 0;
    const double R2 = R * R;
    while (size > 0) {
      const Node& n = nodes_[stack[--size]];
      if (box_distance2(n.box, p) > R2) continue;
      if (n.left != 0) {
        stack[size++] = n.left, stack[size++] = n.right;
        continue;
      }
      for (std::uint32_t i = n.begin; i < n.end; ++i)
        if (box_distance2(boxes_[i], p) <= R2) f(order_[i]);
    }
  }

  /// The bounding box of some points.
  template <class Points>
  static Box box_of(const Points& points) {
    Box b{*points.begin(), *points.begin()};
    for (const Vec3 q : points) {
      b.lo = {std::min(b.lo.x, q.x), std::min(b.lo.y, q.y), std::min(b.lo.z, q.z)};
      b.hi = {std::max(b.hi.x, q.x), std::max(b.hi.y, q.y), std::max(b.hi.z, q.z)};
    }
    return b;
  }

 private:
  struct Node {
    Box box;
    std::uint32_t begin, end;     // its items: order_[begin, end)
    std::uint32_t left = 0, right = 0;  // children (0: a leaf; node 0 is the root)
  };
  static constexpr std::size_t kLeaf = 8;

  static double axis(Vec3 p, int a) { return a == 0 ? p.x : a == 1 ? p.y : p.z; }
  static double box_distance2(const Box& b, Vec3 p) {
    const double dx = std::max({b.lo.x - p.x, 0.0, p.x - b.hi.x}), dy = std::max({b.lo.y - p.y, 0.0, p.y - b.hi.y}),
                 dz = std::max({b.lo.z - p.z, 0.0, p.z - b.hi.z});
    return dx * dx + dy * dy + dz * dz;
  }
  static double box_distance(const Box& b, Vec3 p) { return std::sqrt(box_distance2(b, p)); }

  // Splits order_[begin, end) at the median of the box centers along the longest side.
  std::uint32_t build(std::size_t begin, std::size_t end) {
    Box box = boxes_[order_[begin]];
    for (std::size_t i = begin; i < end; ++i) {
      const Box& b = boxes_[order_[i]];
      box.lo = {std::min(box.lo.x, b.lo.x), std::min(box.lo.y, b.lo.y), std::min(box.lo.z, b.lo.z)};
      box.hi = {std::max(box.hi.x, b.hi.x), std::max(box.hi.y, b.hi.y), std::max(box.hi.z, b.hi.z)};
    }
    const auto k = static_cast<std::uint32_t>(nodes_.size());
    nodes_.push_back({box, static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(end)});
    if (end - begin <= kLeaf) return k;
    const Vec3 size = box.hi - box.lo;
    const int a = size.x >= size.y && size.x >= size.z ? 0 : size.y >= size.z ? 1 : 2;
    const std::size_t mid = begin + (end - begin) / 2;
    std::nth_element(order_.begin() + static_cast<std::ptrdiff_t>(begin), order_.begin() + static_cast<std::ptrdiff_t>(mid),
                     order_.begin() + static_cast<std::ptrdiff_t>(end), [&](std::uint32_t x, std::uint32_t y) {
                       return axis(boxes_[x].lo, a) + axis(boxes_[x].hi, a) < axis(boxes_[y].lo, a) + axis(boxes_[y].hi, a);
                     });
    const std::uint32_t left = build(begin, mid), right = build(mid, end);
    nodes_[k].left = left, nodes_[k].right = right;
    return k;
  }

  template <class Distance>
  void search(std::uint32_t k, Vec3 p, double& best, Distance& distance) const {
    const Node& n = nodes_[k];
    if (n.left == 0) {
      for (std::uint32_t i = n.begin; i < n.end; ++i)
        if (box_distance(boxes_[i], p) < best) best = std::min(best, distance(order_[i]));
      return;
    }
    double near_side = box_distance(nodes_[n.left].box, p), far_side = box_distance(nodes_[n.right].box, p);
    std::uint32_t first = n.left, second = n.right;
    if (far_side < near_side) std::swap(first, second), std::swap(near_side, far_side);
    if (near_side < best) search(first, p, best, distance);
    if (far_side < best) search(second, p, best, distance);
  }

  std::vector<Box> boxes_;            // by item while building, then in leaf order
  std::vector<std::uint32_t> order_;  // the item at each leaf position
  std::vector<Node> nodes_;
};

}  // namespace disktune::detail
