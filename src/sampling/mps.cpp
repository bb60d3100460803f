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
#include <cstdint>
#include <vector>

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
// dart there simply conflicts), so the list is fixed. The darts go in blocks: their
// random numbers drawn in order on one thread (in the order the numbers have always been
// drawn in, so samples stay as they were); then, on every core, each dart placed in its
// cell and tested against the centers put before the block, most failing there (centers
// are only added within a level, so a dart that conflicts then conflicts at its turn
// too); the rest land in order, tested again: the same centers for any thread count.
// The loops are bound by memory latency, so each fetches ahead what it will read.
std::size_t throw_darts(DartGrid& grid, const CellList& active, int level, std::size_t throws,
                        Rng& rng, unsigned threads) {
  struct Dart {
    std::size_t slot;
    double u, v;  // where in its cell, as fractions of the cell's sides
    Vec2 z;
    Cell base;
  };
  // Each dart's cell is drawn eight darts ahead of its place in the cell.
  constexpr std::size_t kAhead = 8;
  std::size_t slots[kAhead];
  for (std::size_t t = 0; t < std::min(throws, kAhead); ++t)
    slots[t] = uniform_index(rng, active.size());
  const Vec2 size = grid.size(level);
  constexpr std::size_t kBlock = std::size_t{1} << 16, kChunk = std::size_t{1} << 12;
  std::vector<Dart> block;
  std::vector<char> open;
  std::vector<std::uint32_t> left;
  std::size_t accepted = 0;
  for (std::size_t first = 0; first < throws; first += kBlock) {
    const std::size_t n = std::min(kBlock, throws - first);
    block.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t t = first + k;
      Dart& d = block[k];
      d.slot = slots[t % kAhead];
      d.u = uniform01(rng);
      d.v = uniform01(rng);
      if (t + kAhead < throws) slots[t % kAhead] = uniform_index(rng, active.size());
    }
    open.assign(n, 0);
    detail::parallel_for((n + kChunk - 1) / kChunk, threads, [&](std::size_t chunk, unsigned) {
      const std::size_t lo = chunk * kChunk, hi = std::min(n, lo + kChunk);
      for (std::size_t k = lo; k < hi; ++k) {
        if (k + 32 < hi) __builtin_prefetch(&active[block[k + 32].slot]);
        Dart& d = block[k];
        const Cell c = active[d.slot];
        d.z = grid.corner(c, level) + Vec2{d.u * size.x, d.v * size.y};
        d.base = grid.base_of(c, level);
      }
      for (std::size_t k = lo; k < hi; ++k) {
        if (k + 16 < hi) grid.prefetch_block(block[k + 16].base);
        open[k] = !grid.conflicts(block[k].z, block[k].base);
      }
    });
    left.clear();
    for (std::size_t k = 0; k < n; ++k)
      if (open[k]) left.push_back(static_cast<std::uint32_t>(k));
    for (std::size_t i = 0; i < left.size(); ++i) {  // the darts land
      if (i + 8 < left.size()) grid.prefetch_block(block[left[i + 8]].base);
      const Dart& d = block[left[i]];
      if (grid.conflicts(d.z, d.base)) continue;
      grid.put(d.base, d.z);
      ++accepted;
    }
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
    st.dart_disks += throw_darts(grid, active, level, throws, rng, detail::thread_count(0));
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
