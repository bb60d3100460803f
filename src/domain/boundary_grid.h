// SPDX-License-Identifier: GPL-3.0-or-later
// The background grid behind PlanarDomain's point queries: a dense uniform grid over
// the bounding box, about four cells per segment, each cell listing the segments that
// pass near it. A cell that lists none is wholly inside or outside the domain.
#pragma once

#include <cstdint>
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
  double distance(Vec2 p) const;

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
