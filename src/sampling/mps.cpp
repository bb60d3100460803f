// SPDX-License-Identifier: GPL-3.0-or-later
// Maximal Poisson-disk sampling in two phases (after Ebeida et al., "Efficient maximal
// Poisson-disk sampling", TOG 2011, and "A simple algorithm for maximal Poisson-disk
// sampling in high dimensions", EG 2012):
//  1. darts: each level throws darts into uniformly chosen active cells (all of one
//     area), so every accepted dart is uniform over the uncovered area; then splits the
//     active cells in four and drops the children one disk covers.
//  2. voids: every cell still active is tested exactly (the uncovered part of a cell
//     has an uncovered vertex: a cell corner, an edge crossing or a circle-circle
//     corner); a cell with a void gets a center drawn from its uncovered part, which
//     covers the cell's whole base cell. Every point of the domain then lies in a cell
//     known to be covered: the sample is maximal.
#include <algorithm>
#include <chrono>

#include "../geometry/threads.h"
#include "../voids/final_check.h"
#include "dart_grid.h"
#include "disktune/sampling.h"

namespace disktune {

using detail::Cell;
using detail::CellList;
using detail::DartGrid;

namespace {

// Throws the darts of one level. Cells filled during the level stay in the list (a
// dart there simply conflicts), so the list is fixed and darts can be drawn ahead of
// use: a short pipeline prefetches each dart's neighbourhood, because this loop is
// bound by memory latency, not arithmetic.
std::size_t throw_darts(DartGrid& grid, const CellList& active, int level,
                        std::size_t throws, Rng& rng) {
  constexpr std::size_t kAhead = 16, kHalf = kAhead / 2;
  struct Dart {
    std::size_t slot;
    Vec2 z;
    Cell base;
  };
  Dart ring[kAhead];
  const Vec2 size = grid.size(level);
  auto draw = [&](std::size_t t) {  // stage 1: pick the cell, fetch its list entry
    ring[t % kAhead].slot = uniform_index(rng, active.size());
    __builtin_prefetch(&active[ring[t % kAhead].slot]);
  };
  auto aim = [&](std::size_t t) {  // stage 2: place the dart, fetch its block
    Dart& d = ring[t % kAhead];
    const Cell c = active[d.slot];
    d.z = grid.corner(c, level) + Vec2{uniform01(rng) * size.x, uniform01(rng) * size.y};
    d.base = grid.base_of(c, level);
    grid.prefetch_block(d.base);
  };
  for (std::size_t t = 0; t < std::min(throws, kHalf); ++t) draw(t);
  for (std::size_t t = 0; t < std::min(throws, kHalf); ++t) {
    aim(t);
    if (t + kHalf < throws) draw(t + kHalf);
  }
  std::size_t accepted = 0;
  for (std::size_t t = 0; t < throws; ++t) {  // stage 3: the dart lands
    const Dart d = ring[t % kAhead];
    if (t + kHalf < throws) aim(t + kHalf);
    if (t + kAhead < throws) draw(t + kAhead);
    if (grid.conflicts(d.z, d.base)) continue;
    grid.put(d.base, d.z);
    ++accepted;
  }
  return accepted;
}

}  // namespace

Packing sample_mps(const PeriodicBox& box, double r, Rng& rng, const MpsOptions& options,
                   MpsStats* stats) {
  box.validate_radius(r);
  MpsStats local;
  MpsStats& st = stats ? *stats : local;
  st = MpsStats{};

  auto clock = std::chrono::steady_clock::now();
  auto lap = [&clock](double& seconds) {
    const auto now = std::chrono::steady_clock::now();
    seconds += std::chrono::duration<double>(now - clock).count();
    clock = now;
  };
  DartGrid grid(box.frame(), r);
  CellList active;
  active.reserve(grid.centers().size());
  for (int iy = 0; iy < grid.my(); ++iy) {
    for (int ix = 0; ix < grid.mx(); ++ix) {
      active.push_back({static_cast<std::uint32_t>(ix), static_cast<std::uint32_t>(iy)});
    }
  }
  int level = 0;
  for (; level < options.levels && !active.empty(); ++level) {
    const auto throws = static_cast<std::size_t>(options.darts_per_active_cell * active.size());
    st.dart_disks += throw_darts(grid, active, level, throws, rng);
    st.darts += throws;
    lap(st.darts_seconds);
    // Keep what is still uncovered, split in four for the next level.
    const bool split = level + 1 < options.levels;
    // On every core, in chunks joined in order (the cells only read the grid): the same
    // cells whatever the thread count.
    CellList next;
    next.reserve(split ? active.size() * 2 : active.size());
    detail::ordered_chunks<std::vector<Cell>>(
        active.size(), detail::thread_count(0),
        [&](std::size_t from, std::size_t to, std::vector<Cell>& kept) {
          for (std::size_t k = from; k < to; ++k)
            grid.keep_uncovered(active[k], level, split, kept);
        },
        [&](const std::vector<Cell>& kept) { next.insert(next.end(), kept.begin(), kept.end()); });
    active.swap(next);
    lap(st.prune_seconds);
  }
  st.levels = level;
  st.void_cells = active.size();

  // Exact void elimination, visiting the cells in random order.
  const int last = std::max(level - 1, 0);  // the level of the cells in `active`
  for (std::size_t i = active.size(); i > 1; --i) {
    std::swap(active[i - 1], active[uniform_index(rng, i)]);
  }
  auto u01 = [&rng] { return uniform01(rng); };
  for (const Cell c : active) {
    const Cell base = grid.base_of(c, last);
    Vec2 z;
    if (grid.filled(base) || grid.covered_exactly(c, last, u01, z)) continue;
    grid.put(base, z);
    ++st.void_disks;
  }

  lap(st.voids_seconds);
  // Ids in cell order keep neighbours close in memory for everything downstream.
  Packing packing(box.frame(), r);
  for (const Vec2& c : grid.centers()) {
    if (c.x == c.x) packing.insert(c, r);  // not NaN: the cell holds a center
  }
  lap(st.build_seconds);
  detail::check_sample(packing);
  lap(st.check_seconds);
  return packing;
}

}  // namespace disktune
