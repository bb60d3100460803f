// SPDX-License-Identifier: GPL-3.0-or-later
// Items with a bounding box (triangles, edges) in a hashed 3D grid (internal), for the
// surface sizings that look for nearby parts of the mesh.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

#include "disktune/vec3.h"

namespace disktune::detail {

/// Items in cells at least `reach` wide, each in every cell its bounding box meets: every
/// item within reach of p is in the 27 cells around p's. Cells are no smaller than an
/// eighth of the widest box, which bounds the cells one item takes.
class BoxCells {
 public:
  struct Box {
    Vec3 lo, hi;
  };
  BoxCells(const std::vector<Box>& boxes, double reach) : cell_(reach) {
    for (const Box& b : boxes)
      for (int axis = 0; axis < 3; ++axis) cell_ = std::max(cell_, (coordinate(b.hi, axis) - coordinate(b.lo, axis)) / 8);
    for (std::uint32_t item = 0; item < boxes.size(); ++item) {
      std::array<std::int64_t, 3> lo{}, hi{};
      for (int axis = 0; axis < 3; ++axis) {
        lo[axis] = index(coordinate(boxes[item].lo, axis));
        hi[axis] = index(coordinate(boxes[item].hi, axis));
      }
      for (std::int64_t i = lo[0]; i <= hi[0]; ++i)
        for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
          for (std::int64_t k = lo[2]; k <= hi[2]; ++k) cells_[{i, j, k}].push_back(item);
    }
  }
  /// f(item) for each item in the cells around p (an item in several cells: several times).
  template <class F>
  void around(Vec3 p, F&& f) const {
    const std::int64_t ci = index(p.x), cj = index(p.y), ck = index(p.z);
    for (std::int64_t i = ci - 1; i <= ci + 1; ++i)
      for (std::int64_t j = cj - 1; j <= cj + 1; ++j)
        for (std::int64_t k = ck - 1; k <= ck + 1; ++k) {
          const auto it = cells_.find({i, j, k});
          if (it != cells_.end())
            for (const std::uint32_t item : it->second) f(item);
        }
  }

  /// The bounding box of some points.
  template <class Points>
  static Box box_of(const Points& points) {
    Box b{*points.begin(), *points.begin()};
    for (const Vec3 p : points) {
      b.lo = {std::min(b.lo.x, p.x), std::min(b.lo.y, p.y), std::min(b.lo.z, p.z)};
      b.hi = {std::max(b.hi.x, p.x), std::max(b.hi.y, p.y), std::max(b.hi.z, p.z)};
    }
    return b;
  }

 private:
  static double coordinate(Vec3 p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }
  std::int64_t index(double v) const { return static_cast<std::int64_t>(std::floor(v / cell_)); }
  double cell_;
  std::map<std::array<std::int64_t, 3>, std::vector<std::uint32_t>> cells_;
};

}  // namespace disktune::detail
