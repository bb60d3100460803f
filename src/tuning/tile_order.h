// SPDX-License-Identifier: GPL-3.0-or-later
// A sweep's random order, grouped by tiles (internal).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

#include "disktune/packing.h"
#include "disktune/random.h"

namespace disktune::detail {

/// Square tiles this many radii wide.
inline constexpr double kTileRadii = 16;

/// The disks of `order` (a shuffle) grouped by square tiles of kTileRadii radii, the
/// tiles in random order and each tile's disks in the order given. For operations that
/// reach a few radii this is as random as the shuffle, but a tile's disks and grid cells
/// stay in the cache while it is worked, where a shuffle of 10^6 disks reads memory at
/// random: void injection from the unit box's MPS at r = 0.000835 (10^6 disks) to eta
/// 0.70, 24.9 -> 15.7 s (tiles of 8 and 32 radii, in a first version: 17.2 and 17.0 s,
/// 16 radii 16.8 s; docs/tuning.md).
inline std::vector<DiskId> tiled(const Packing& packing, const std::vector<DiskId>& order,
                                 Rng& rng) {
  if (order.empty()) return order;
  Vec2 lo = packing.center(order[0]), hi = lo;
  for (const DiskId d : order) {
    const Vec2 c = packing.center(d);
    lo = {std::min(lo.x, c.x), std::min(lo.y, c.y)};
    hi = {std::max(hi.x, c.x), std::max(hi.y, c.y)};
  }
  // At most about one tile per disk (a few disks spread over a wide domain).
  double side = kTileRadii * packing.max_radius();
  const auto across = [&](double extent) { return std::floor(extent / side) + 1; };
  while (across(hi.x - lo.x) * across(hi.y - lo.y) > static_cast<double>(order.size())) side *= 2;
  const auto nx = static_cast<std::size_t>(across(hi.x - lo.x));
  const std::size_t tiles = nx * static_cast<std::size_t>(across(hi.y - lo.y));
  std::vector<std::uint32_t> rank(tiles);
  std::iota(rank.begin(), rank.end(), 0u);
  for (std::size_t i = tiles; i > 1; --i) std::swap(rank[i - 1], rank[uniform_index(rng, i)]);
  const auto tile_of = [&](DiskId d) {
    const Vec2 c = packing.center(d);
    return static_cast<std::size_t>((c.x - lo.x) / side) +
           nx * static_cast<std::size_t>((c.y - lo.y) / side);
  };
  // A counting sort by the tiles' ranks keeps the given order within a tile.
  std::vector<std::size_t> start(tiles + 1, 0);
  for (const DiskId d : order) ++start[rank[tile_of(d)] + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<DiskId> out(order.size());
  for (const DiskId d : order) out[start[rank[tile_of(d)]]++] = d;
  return out;
}

}  // namespace disktune::detail
