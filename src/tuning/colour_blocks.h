// SPDX-License-Identifier: GPL-3.0-or-later
// Disks spread over threads by where they are (internal). Space is cut into cubes, and
// the cubes coloured by the parity of their three indices: two cubes of one colour lie a
// whole cube apart. Where a cube is wider than what one disk's operation reads and
// writes can reach, the cubes of one colour can be worked on at once, and each disk sees
// exactly what it would see were the cubes worked on one after another: the result is the
// same for any number of threads.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <tuple>
#include <vector>

#include "../geometry/threads.h"
#include "disktune/surface_packing.h"

namespace disktune::detail {

/// One list of disks per cube, per colour.
using ColourBlocks = std::array<std::vector<std::vector<DiskId>>, 8>;

/// The disks of `order` grouped by the cube of side `block` holding their center (cubes
/// with a corner at `origin`), each group in the order of `order`, the groups of a colour
/// by their cube's indices.
inline ColourBlocks colour_blocks(const SurfacePacking& packing, const std::vector<DiskId>& order,
                                  double block, Vec3 origin) {
  using Cube = std::tuple<std::int64_t, std::int64_t, std::int64_t>;
  std::map<Cube, std::vector<DiskId>> cubes;
  const auto index = [&](double v) { return SpaceGrid::cell_index(v, block); };
  for (const DiskId p : order) {
    const Vec3 c = packing.center(p) - origin;
    cubes[{index(c.x), index(c.y), index(c.z)}].push_back(p);
  }
  ColourBlocks out;
  for (auto& [cube, disks] : cubes) {
    const auto [i, j, k] = cube;
    out[(i & 1) | (j & 1) << 1 | (k & 1) << 2].push_back(std::move(disks));
  }
  return out;
}

/// work(group) for every group, on up to `threads` threads (parallel_for).
template <class Work>
void for_each_group(const std::vector<std::vector<DiskId>>& groups, unsigned threads, Work&& work) {
  parallel_for(groups.size(), threads, [&](std::size_t g, unsigned) { work(groups[g]); });
}

}  // namespace disktune::detail
