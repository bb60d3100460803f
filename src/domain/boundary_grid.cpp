// SPDX-License-Identifier: GPL-3.0-or-later
// Inside or outside is the parity of boundary crossings along a path from a point whose
// answer is known. Known points: each grid vertex, moved up by an infinitesimal e and
// right by d >> e, whose parity comes from one sweep of its row line leftward from the
// grid's right edge (outside). A point p in cell (i, j) walks right along its row to the
// cell's right edge, then along that edge to the cell's lower-right vertex; both legs
// stay in the cell, so only the cell's own segments are tested. The infinitesimals make
// every tie (a vertex on a leg, a segment through a grid vertex) go one consistent way,
// and the half-open rules below implement them.
#include "boundary_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace disktune::detail {
namespace {

// Does ab cross the line y = q.y + e? (A vertex on the line lies below it.)
bool crosses_row(Vec2 a, Vec2 b, double y) { return (a.y > y) != (b.y > y); }

// For ab crossing the row of q: is the crossing right of q (+d)? A crossing at q.x lies
// left of q.x + d.
bool crossing_right_of(Vec2 a, Vec2 b, Vec2 q) {
  if (a.y > b.y) std::swap(a, b);
  return cross(b - a, q - a) > 0;  // q left of the upward segment
}

// Does ab cross the line x = q.x + d?
bool crosses_column(Vec2 a, Vec2 b, double x) { return (a.x > x) != (b.x > x); }

// For ab crossing the column of q: is the crossing above q (+e)? Through q exactly, the
// crossing at q.x + d is above q.y + e when ab rises (d >> e).
bool crossing_above(Vec2 a, Vec2 b, Vec2 q) {
  if (a.x > b.x) std::swap(a, b);
  const double o = cross(b - a, q - a);  // negative: q below the rightward segment
  return o < 0 || (o == 0 && b.y > a.y);
}

}  // namespace

BoundaryGrid::BoundaryGrid(const std::vector<std::vector<Vec2>>& loops, Vec2 lo, Vec2 hi)
    : lo_(lo), hi_(hi) {
  for (const auto& loop : loops) {
    for (std::size_t i = 0; i < loop.size(); ++i) {
      seg_a_.push_back(loop[i]);
      seg_b_.push_back(loop[(i + 1) % loop.size()]);
    }
  }
  const double w = hi.x - lo.x, h = hi.y - lo.y;
  const double target = std::max(4.0 * static_cast<double>(seg_a_.size()), 64.0);
  spec_.origin = lo;
  spec_.h = std::max(std::sqrt(w * h / target), std::max(w, h) / target);  // thin boxes too
  // A spare column and row: the grid's right and top edges lie clear of the boundary.
  spec_.nx = static_cast<std::int64_t>(w / spec_.h) + 2;
  spec_.ny = static_cast<std::int64_t>(h / spec_.h) + 2;
  tol_ = 1e-12 * std::max(w, h);
  list_segments(1e-6 * spec_.h + 2 * tol_);
  find_parities();
  measure_free_rings();
}

// Padded rasterization, twice (count, then fill), into compressed rows.
void BoundaryGrid::list_segments(double pad) {
  const std::size_t cells = static_cast<std::size_t>(spec_.nx * spec_.ny);
  start_.assign(cells + 1, 0);
  for (std::size_t s = 0; s < seg_a_.size(); ++s) {
    for_cells_of_segment(spec_, seg_a_[s], seg_b_[s], pad,
                         [&](std::int64_t i, std::int64_t j) { ++start_[cell(i, j) + 1]; });
  }
  for (std::size_t c = 0; c < cells; ++c) start_[c + 1] += start_[c];
  ids_.resize(start_[cells]);
  std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
  for (std::size_t s = 0; s < seg_a_.size(); ++s) {
    for_cells_of_segment(spec_, seg_a_[s], seg_b_[s], pad, [&](std::int64_t i, std::int64_t j) {
      ids_[fill[cell(i, j)]++] = static_cast<std::uint32_t>(s);
    });
  }
}

// Each row line y = edge_y(j) swept leftward: a crossing between two grid vertices lies
// on the bottom edge of the cell between them, so that cell lists it.
void BoundaryGrid::find_parities() {
  corner_inside_.assign(static_cast<std::size_t>((spec_.nx + 1) * spec_.ny), 0);
  state_.assign(static_cast<std::size_t>(spec_.nx * spec_.ny), -1);
  for (std::int64_t j = 0; j < spec_.ny; ++j) {
    const double y = edge_y(j);
    for (std::int64_t i = spec_.nx - 1; i >= 0; --i) {
      const std::size_t c = cell(i, j);
      bool inside = corner_inside_[corner(i + 1, j)];
      for (std::uint32_t k = start_[c]; k < start_[c + 1]; ++k) {
        const Vec2 a = seg_a_[ids_[k]], b = seg_b_[ids_[k]];
        if (crosses_row(a, b, y) && crossing_right_of(a, b, {edge_x(i), y}) &&
            !crossing_right_of(a, b, {edge_x(i + 1), y})) {
          inside = !inside;
        }
      }
      corner_inside_[corner(i, j)] = inside;
      if (start_[c] == start_[c + 1]) state_[c] = corner_inside_[corner(i + 1, j)];
    }
  }
}

// Two chamfer passes give the exact Chebyshev distance: distance queries skip the rings
// of cells known to hold no segment.
void BoundaryGrid::measure_free_rings() {
  free_rings_.assign(state_.size(), std::numeric_limits<std::int32_t>::max() / 2);
  for (std::size_t c = 0; c < state_.size(); ++c) {
    if (state_[c] < 0) free_rings_[c] = 0;
  }
  auto relax = [&](std::int64_t i, std::int64_t j, std::int64_t di, std::int64_t dj) {
    const std::int64_t u = i + di, v = j + dj;
    if (u < 0 || u >= spec_.nx || v < 0 || v >= spec_.ny) return;
    std::int32_t& here = free_rings_[cell(i, j)];
    here = std::min(here, free_rings_[cell(u, v)] + 1);
  };
  for (std::int64_t j = 0; j < spec_.ny; ++j) {
    for (std::int64_t i = 0; i < spec_.nx; ++i) {
      relax(i, j, -1, 0), relax(i, j, -1, -1), relax(i, j, 0, -1), relax(i, j, 1, -1);
    }
  }
  for (std::int64_t j = spec_.ny - 1; j >= 0; --j) {
    for (std::int64_t i = spec_.nx - 1; i >= 0; --i) {
      relax(i, j, 1, 0), relax(i, j, 1, 1), relax(i, j, 0, 1), relax(i, j, -1, 1);
    }
  }
}

bool BoundaryGrid::contains(Vec2 p) const {
  if (!(p.x >= lo_.x - tol_ && p.x <= hi_.x + tol_ && p.y >= lo_.y - tol_ && p.y <= hi_.y + tol_)) {
    return false;  // also NaN
  }
  const std::int64_t i = spec_.column(p.x), j = spec_.row(p.y);
  const std::size_t c = cell(i, j);
  if (state_[c] >= 0) return state_[c] == 1;
  // Walk from p right to the cell's right edge, then along it to the lower-right vertex.
  const Vec2 side{edge_x(i + 1), p.y}, vertex{edge_x(i + 1), edge_y(j)};
  bool inside = corner_inside_[corner(i + 1, j)];
  for (std::uint32_t k = start_[c]; k < start_[c + 1]; ++k) {
    const Vec2 a = seg_a_[ids_[k]], b = seg_b_[ids_[k]];
    if (squared_distance_to_segment(p, a, b) <= tol_ * tol_) return true;  // on the boundary
    if (crosses_row(a, b, p.y) && crossing_right_of(a, b, p) != crossing_right_of(a, b, side)) {
      inside = !inside;
    }
    if (crosses_column(a, b, side.x) &&
        crossing_above(a, b, vertex) != crossing_above(a, b, side)) {
      inside = !inside;
    }
  }
  return inside;
}
}  // namespace disktune::detail
