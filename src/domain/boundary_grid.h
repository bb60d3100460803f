// SPDX-License-Identifier: GPL-3.0-or-later
// The background grid behind PlanarDomain's point queries: a dense uniform grid over
// the bounding box, about four cells per segment, each cell listing the segments that
// pass near it. A cell that lists none is wholly inside or outside the domain.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "disktune/geometry.h"
#include "segment_raster.h"

namespace disktune::detail {

class BoundaryGrid {
 public:
  /// `loops` must already be valid (see validate_loops); lo and hi bound them.
  BoundaryGrid(const std::vector<std::vector<Vec2>>& loops, Vec2 lo, Vec2 hi);

  /// Closed domain test: a point within a relative 1e-12 of the box size of a segment
  /// is inside. Expected O(1).
  bool contains(Vec2 p) const;
  /// Distance to the nearest segment, searching rings of cells outward.
  double distance(Vec2 p) const {
    return distance(p, std::numeric_limits<double>::infinity(), [](std::size_t) { return false; });
  }
  /// The same over the segments `skip(s)` does not reject (s numbers them as the loops
  /// list them, PlanarDomain::segments' order), and at most `limit`: the search stops
  /// once no segment nearer than that can be left. Rings of cells around p's cell,
  /// nearest first; a point outside the grid searches from its clamped cell (distances
  /// to the grid's cells only grow as the point leaves it).
  template <class Skip>
  double distance(Vec2 p, double limit, Skip&& skip) const {
    if (!(std::isfinite(p.x) && std::isfinite(p.y))) return std::numeric_limits<double>::quiet_NaN();
    const std::int64_t ci = spec_.column(p.x), cj = spec_.row(p.y);
    double best2 = limit * limit;
    auto visit = [&](std::int64_t i, std::int64_t j) {
      if (i < 0 || i >= spec_.nx || j < 0 || j >= spec_.ny) return;
      const std::size_t c = cell(i, j);
      for (std::uint32_t k = start_[c]; k < start_[c + 1]; ++k) {
        const std::uint32_t s = ids_[k];
        if (!skip(std::size_t{s})) best2 = std::min(best2, squared_distance_to_segment(p, seg_a_[s], seg_b_[s]));
      }
    };
    const std::int64_t last = std::max({ci, spec_.nx - 1 - ci, cj, spec_.ny - 1 - cj});
    for (std::int64_t r = free_rings_[cell(ci, cj)]; r <= last; ++r) {
      const double reach = static_cast<double>(r - 1) * spec_.h;  // nearest a ring-r cell can be
      if (r > 0 && best2 <= reach * reach) break;
      if (r == 0) {
        visit(ci, cj);
        continue;
      }
      for (std::int64_t d = -r; d <= r; ++d) {
        visit(ci + d, cj - r), visit(ci + d, cj + r);
        if (d != -r && d != r) visit(ci - r, cj + d), visit(ci + r, cj + d);
      }
    }
    return std::sqrt(best2);
  }

 private:
  std::size_t cell(std::int64_t i, std::int64_t j) const {
    return static_cast<std::size_t>(j * spec_.nx + i);
  }
  std::size_t corner(std::int64_t i, std::int64_t j) const {
    return static_cast<std::size_t>(j * (spec_.nx + 1) + i);
  }
  double edge_x(std::int64_t i) const { return spec_.origin.x + static_cast<double>(i) * spec_.h; }
  double edge_y(std::int64_t j) const { return spec_.origin.y + static_cast<double>(j) * spec_.h; }
  void list_segments(double pad);
  void find_parities();
  void measure_free_rings();

  CellSpec spec_;
  Vec2 lo_, hi_;
  double tol_ = 0;
  std::vector<Vec2> seg_a_, seg_b_;
  std::vector<std::uint32_t> start_, ids_;  // cell c lists ids_[start_[c] .. start_[c + 1])
  std::vector<std::int8_t> corner_inside_;  // parity just above-right of each grid vertex
  std::vector<std::int8_t> state_;          // 1 inside, 0 outside, -1 crossed
  std::vector<std::int32_t> free_rings_;    // Chebyshev distance to the nearest crossed cell
};

}  // namespace disktune::detail
