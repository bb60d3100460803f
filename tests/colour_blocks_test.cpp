// SPDX-License-Identifier: GPL-3.0-or-later
// colour_blocks (src/tuning/colour_blocks.h), how relaxation spreads disks over threads:
// for all disks or some of them, each disk of the order once, each group's disks in one
// cube and in the order given, and two groups of one colour at least a cube apart
// (checked on the disks' centers, apart from the cube arithmetic).
#include "../src/tuning/colour_blocks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "disktune/surface_sampling.h"
#include "disktune/surface_sizing.h"
#include "surface_checks.h"

namespace disktune {
namespace {

TEST(ColourBlocks, HoldEachDiskOfTheOrderOnceWithGroupsOfAColourACubeApart) {
  const auto surface = test::surface_file("elephant.off");
  Rng rng(9);
  const SurfacePacking p = sample_mps(surface, SurfaceSizing::constant(0.02), rng);
  const double cube = 0.15;
  const Vec3 origin{0.01, -0.02, 0.03};
  for (const std::size_t every : {1u, 3u}) {  // all disks, then a third of them
    std::vector<DiskId> order;
    const std::vector<DiskId> ids = p.ids();
    for (std::size_t k = 0; k < ids.size(); k += every) order.push_back(ids[k]);
    std::reverse(order.begin(), order.end());  // an order other than the ids'
    const detail::ColourBlocks blocks = detail::colour_blocks(p, order, cube, origin);
    std::vector<DiskId> seen = blocks.disks;
    std::sort(seen.begin(), seen.end());
    std::vector<DiskId> want = order;
    std::sort(want.begin(), want.end());
    ASSERT_EQ(seen, want) << "every " << every;
    std::vector<std::size_t> at(p.id_bound());
    for (std::size_t k = 0; k < order.size(); ++k) at[order[k]] = k;
    std::size_t grouped = 0;
    for (int colour = 0; colour < 8; ++colour) {
      const auto& groups = blocks.groups[colour];
      for (std::size_t g = 0; g < groups.size(); ++g) {
        const auto [first, end] = groups[g];
        grouped += end - first;
        for (std::uint32_t k = first; k + 1 < end; ++k)
          EXPECT_LT(at[blocks.disks[k]], at[blocks.disks[k + 1]]) << "a group out of order";
        // Two groups of one colour: some axis separates their disks by at least a cube.
        for (std::size_t h = g + 1; h < groups.size(); ++h) {
          bool apart = false;
          for (int axis = 0; axis < 3 && !apart; ++axis) {
            const auto coord = [&](DiskId q) {
              const Vec3 c = p.center(q) - origin;
              return axis == 0 ? c.x : axis == 1 ? c.y : c.z;
            };
            double lo_g = 1e300, hi_g = -1e300, lo_h = 1e300, hi_h = -1e300;
            for (std::uint32_t k = first; k < end; ++k)
              lo_g = std::min(lo_g, coord(blocks.disks[k])),
              hi_g = std::max(hi_g, coord(blocks.disks[k]));
            for (std::uint32_t k = groups[h].first; k < groups[h].second; ++k)
              lo_h = std::min(lo_h, coord(blocks.disks[k])),
              hi_h = std::max(hi_h, coord(blocks.disks[k]));
            apart = lo_h - hi_g >= cube * (1 - 1e-9) || lo_g - hi_h >= cube * (1 - 1e-9);
          }
          EXPECT_TRUE(apart) << "colour " << colour << ", groups " << g << " and " << h;
        }
      }
    }
    EXPECT_EQ(grouped, order.size());
  }
}

}  // namespace
}  // namespace disktune
