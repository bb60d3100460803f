// SPDX-License-Identifier: GPL-3.0-or-later
// Disks of a periodic box kept in arrays sorted cell by cell (internal): the soft disks
// and squeeze injection's pushes both keep them so, relative to the box's origin, with
// the index each disk was given by.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "../geometry/threads.h"
#include "disktune/geometry.h"

namespace disktune::detail {

/// v wrapped into [0, length).
inline double wrap_into(double v, double length) {
  v -= std::floor(v / length) * length;
  return v >= length ? 0 : v;
}

/// Wraps every x into [0, W) x [0, H) and finds its cell of nx x ny (cell[i], row by row),
/// on up to `threads` threads; start gets nx ny + 1 entries, where each cell's disks begin
/// once sorted by cell.
inline void count_by_cell(std::vector<Vec2>& x, Vec2 extent, int nx, int ny, std::vector<int>& cell,
                          std::vector<int>& start, unsigned threads = 1) {
  constexpr std::size_t kChunk = 1 << 16;
  cell.resize(x.size());
  // Four divisions a disk: the most of a sort at a million disks, so spread out.
  parallel_for((x.size() + kChunk - 1) / kChunk, threads, [&](std::size_t chunk, unsigned) {
    for (std::size_t i = chunk * kChunk, end = std::min(x.size(), i + kChunk); i < end; ++i) {
      x[i] = {wrap_into(x[i].x, extent.x), wrap_into(x[i].y, extent.y)};
      const int cx = std::min(nx - 1, static_cast<int>(x[i].x / extent.x * nx));
      const int cy = std::min(ny - 1, static_cast<int>(x[i].y / extent.y * ny));
      cell[i] = cy * nx + cx;
    }
  });
  start.assign(static_cast<std::size_t>(nx) * ny + 1, 0);
  for (const int c : cell) ++start[c + 1];
  for (std::size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
}

/// Disks stored in another order (x[i] was given as disk given[i]) put back in the order
/// given, wrapped into [0, extent).
inline std::vector<Vec2> in_given_order(const std::vector<Vec2>& x, const std::vector<int>& given,
                                        Vec2 extent) {
  std::vector<Vec2> out(x.size());
  for (std::size_t i = 0; i < x.size(); ++i)
    out[given[i]] = {wrap_into(x[i].x, extent.x), wrap_into(x[i].y, extent.y)};
  return out;
}

}  // namespace disktune::detail
