// SPDX-License-Identifier: GPL-3.0-or-later
// The cells of a uniform grid a segment passes through, found column by column, so a
// long segment costs the cells it crosses rather than its bounding box's.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "disktune/geometry.h"

namespace disktune::detail {

/// A uniform grid of nx x ny square cells of side h, cell (0, 0) at `origin`.
struct CellSpec {
  Vec2 origin{0, 0};
  double h = 1;
  std::int64_t nx = 1, ny = 1;

  std::int64_t column(double x) const { return clamp_index((x - origin.x) / h, nx); }
  std::int64_t row(double y) const { return clamp_index((y - origin.y) / h, ny); }

 private:
  static std::int64_t clamp_index(double t, std::int64_t n) {
    if (!(t > 0)) return 0;  // also NaN
    if (t >= static_cast<double>(n - 1)) return n - 1;
    return static_cast<std::int64_t>(t);
  }
};

/// Calls visit(column, row) for every cell that the segment ab, grown by `pad`, meets,
/// and possibly a few more: conservative, so rounding can never leave a cell out.
template <class Visit>
void for_cells_of_segment(const CellSpec& g, Vec2 a, Vec2 b, double pad, Visit&& visit) {
  if (a.x > b.x) std::swap(a, b);
  const double dx = b.x - a.x, dy = b.y - a.y;
  const std::int64_t i0 = g.column(a.x - pad), i1 = g.column(b.x + pad);
  for (std::int64_t i = i0; i <= i1; ++i) {
    // The part of the segment over column i (grown by pad), as parameters in [0, 1].
    double t0 = 0, t1 = 1;
    if (dx > 0) {
      const double left = g.origin.x + static_cast<double>(i) * g.h - pad;
      const double right = left + g.h + 2 * pad;
      t0 = std::clamp((left - a.x) / dx, 0.0, 1.0);
      t1 = std::clamp((right - a.x) / dx, 0.0, 1.0);
      if (i == i0) t0 = 0;  // the first and last columns hold the end points exactly
      if (i == i1) t1 = 1;
    }
    const double y0 = t0 == 0 ? a.y : a.y + t0 * dy;
    const double y1 = t1 == 1 ? b.y : a.y + t1 * dy;
    const std::int64_t j0 = g.row(std::min(y0, y1) - pad), j1 = g.row(std::max(y0, y1) + pad);
    for (std::int64_t j = j0; j <= j1; ++j) visit(i, j);
  }
}

/// Squared distance from p to the closed segment ab, measured from the nearer end:
/// a + (b - a) t near b loses b's digits when |a| dwarfs |b| (fuzzing found a segment
/// 10^121 long whose far end gave a distance of 0).
inline double squared_distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a, ap = p - a;
  const double len2 = squared_norm(ab);
  const double t = len2 > 0 ? std::clamp(dot(ap, ab) / len2, 0.0, 1.0) : 0.0;
  return t <= 0.5 ? squared_norm(ap - ab * t) : squared_norm((p - b) + ab * (1 - t));
}

}  // namespace disktune::detail
