// SPDX-License-Identifier: GPL-3.0-or-later
// Disks spread over threads by where they are (internal). Space is cut into cubes, and
// the cubes coloured by the parity of their three indices: two cubes of one colour lie a
// whole cube apart. Where a cube is wider than what one disk's operation reads and
// writes can reach, the cubes of one colour can be worked on at once, and each disk sees
// exactly what it would see were the cubes worked on one after another: the result is the
// same for any number of threads.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

#include "../geometry/threads.h"
#include "disktune/surface_packing.h"

namespace disktune::detail {

/// The disks grouped by cube: group k of colour c is disks[groups[c][k].first,
/// groups[c][k].second). Two allocations a sweep, where a list per cube made hundreds
/// (colour_blocks' instructions in a remesh of fandisk at 10^4 disks 70.7 -> 55.3 M;
/// it is some 6 % of relaxation's on one core, serial on two).
struct ColourBlocks {
  std::vector<DiskId> disks;
  std::array<std::vector<std::pair<std::uint32_t, std::uint32_t>>, 8> groups;
};

/// The disks of `order` (live ones, each once) grouped by the cube of side `block`
/// holding their center (cubes with a corner at `origin`), each group in the order of
/// `order`, the groups of a colour largest first (ties by their cube's indices): the
/// threads take them in that order, so the last to be taken are small and no thread
/// waits long for another at the colour's end.
inline ColourBlocks colour_blocks(const SurfacePacking& packing, const std::vector<DiskId>& order,
                                  double block, Vec3 origin) {
  using Cube = std::tuple<std::int64_t, std::int64_t, std::int64_t>;
  struct CubeHash {
    std::size_t operator()(const Cube& c) const {
      const auto [i, j, k] = c;
      return static_cast<std::size_t>((static_cast<std::uint64_t>(i) * 0x9E3779B97F4A7C15ULL) ^
                                      (static_cast<std::uint64_t>(j) * 0xC2B2AE3D27D4EB4FULL) ^
                                      (static_cast<std::uint64_t>(k) * 0x165667B19E3779F9ULL));
    }
  };
  // The groups numbered as their cubes first appear (a hash table: a sorted map's lookups
  // were 8 % of relaxation's time on two cores). Each disk's group is found in the order
  // of ids, where a run of disks shares a cube (order_by_place numbers them along a
  // curve through space) and only a new cube is looked up: the lookups for every disk in
  // a random order were 6-10 % of relaxation's time on two cores (remesh of the elephant
  // at 10^4 vertices).
  std::unordered_map<Cube, std::uint32_t, CubeHash> group_of;
  group_of.reserve(order.size() / 4 + 16);
  std::vector<Cube> cubes;
  std::vector<std::uint32_t> size;
  std::vector<std::uint32_t> group(packing.id_bound());
  std::vector<char> listed(packing.id_bound(), 0);  // in `order`: all live disks, or some
  for (const DiskId p : order) listed[p] = 1;
  const auto index = [&](double v) { return SpaceGrid::cell_index(v, block); };
  std::uint32_t last = 0;
  for (DiskId p = 0; p < packing.id_bound(); ++p) {
    if (!listed[p]) continue;
    const Vec3 c = packing.center(p) - origin;
    const Cube cube{index(c.x), index(c.y), index(c.z)};
    if (cubes.empty() || cube != cubes[last]) {
      const auto [at, fresh] = group_of.try_emplace(cube, static_cast<std::uint32_t>(cubes.size()));
      if (fresh) cubes.push_back(cube), size.push_back(0);
      last = at->second;
    }
    group[p] = last;
    ++size[last];
  }
  std::vector<std::uint32_t> by_size(cubes.size());
  for (std::uint32_t g = 0; g < by_size.size(); ++g) by_size[g] = g;
  std::sort(by_size.begin(), by_size.end(), [&](std::uint32_t a, std::uint32_t b) {
    return size[a] != size[b] ? size[a] > size[b] : cubes[a] < cubes[b];
  });
  // Each group's place in `disks`, colour by colour, then the disks put there in order.
  ColourBlocks out;
  out.disks.resize(order.size());
  std::vector<std::uint32_t> next(cubes.size());
  std::uint32_t begin = 0;
  for (int colour = 0; colour < 8; ++colour)
    for (const std::uint32_t g : by_size) {
      const auto [i, j, k] = cubes[g];
      if (((i & 1) | (j & 1) << 1 | (k & 1) << 2) != colour) continue;
      out.groups[colour].emplace_back(begin, begin + size[g]);
      next[g] = begin;
      begin += size[g];
    }
  for (const DiskId p : order) out.disks[next[group[p]]++] = p;
  return out;
}

/// work(first, last) for every group of colour `colour` (its disks [first, last)), on up
/// to `threads` threads (parallel_for).
template <class Work>
void for_each_group(const ColourBlocks& blocks, int colour, unsigned threads, Work&& work) {
  const auto& groups = blocks.groups[colour];
  parallel_for(groups.size(), threads, [&](std::size_t g, unsigned) {
    work(blocks.disks.data() + groups[g].first, blocks.disks.data() + groups[g].second);
  });
}

}  // namespace disktune::detail
