// SPDX-License-Identifier: GPL-3.0-or-later
// covers_lifted_voids (src/tuning/surface_repair.h), whether disk p moved to x still
// holds what lifting it leaves uncovered, with what one x's check learnt carried to the
// next (LiftedDisk, a relaxation move's halvings): p's cell as far as it was clipped,
// and a point an earlier x's scan found outside its ball, which answers no at once
// where x's ball does not hold it. Every answer must be the one a fresh call gives, for
// moves of every length on surfaces with creases and boundaries; some answers must come
// from a cell clipped before and some no answers with a point carried (the test fails
// where the carried point answers no whatever x's ball holds, or is never kept).
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

#include "../src/tuning/space.h"
#include "../src/tuning/surface_repair.h"
#include "disktune/surface_features.h"
#include "disktune/surface_sampling.h"
#include "disktune/surface_sizing.h"
#include "surface_checks.h"

namespace disktune {
namespace {

using S = detail::Space<SurfacePacking>;

TEST(CoversLiftedVoids, WhatAHalvingCarriesToTheNextAnswersAsAFreshCall) {
  struct Case {
    const char* file;
    double share;  // the radius, of the bounding box's diagonal
  };
  const Case cases[] = {
      {"fandisk.off", 0.025}, {"mesh_with_border.off", 0.02}, {"elephant.off", 0.009}};
  std::size_t yes = 0, no = 0, decided_by_carried = 0, cell_kept = 0;
  for (const auto& [file, share] : cases) {
    SurfaceDomain d = *test::surface_file(file);
    d.set_features(detect_features(d, {60, 60, 0}));
    const double r = share * norm(d.bbox_max() - d.bbox_min());
    const auto surface = std::make_shared<const SurfaceDomain>(std::move(d));
    Rng rng(5);
    const SurfacePacking packing = sample_mps(surface, SurfaceSizing::constant(r), rng);
    std::mt19937 pick(7);
    std::normal_distribution<double> gauss;
    const std::vector<DiskId> ids = packing.ids();
    for (std::size_t k = 0; k < ids.size(); k += 3) {
      const DiskId p = ids[k];
      if (packing.flags(p) & kFixed) continue;
      const Vec3 c = packing.center(p);
      // Steps of 0.2 to 1.2 r, halved twice, as relaxation's moves try them.
      Vec3 step = S::along_surface(packing, p, Vec3{gauss(pick), gauss(pick), gauss(pick)});
      if (!(norm(step) > 0)) continue;
      step = step * ((0.2 + std::uniform_real_distribution<double>(0, 1)(pick)) * r / norm(step));
      detail::LiftedDisk lifted;
      for (int halving = 0; halving < 3; ++halving, step = step * 0.5) {
        SurfacePoint x;
        if (!S::project(packing, p, c + step, x)) continue;
        const bool had = lifted.outside.has_value();
        cell_kept += lifted.cell.is_of(p, c);
        const bool fresh = detail::covers_lifted_voids(packing, c, S::void_reach(r), p, x);
        const bool carried =
            detail::covers_lifted_voids(packing, c, S::void_reach(r), p, x, nullptr, &lifted);
        EXPECT_EQ(carried, fresh) << file << ", disk " << p << ", halving " << halving;
        (fresh ? yes : no)++;
        decided_by_carried += had && !fresh;
      }
    }
  }
  std::printf("[ lifted ] %zu yes, %zu no, %zu no with a carried point, %zu with a cell kept\n",
              yes, no, decided_by_carried, cell_kept);
  EXPECT_GT(yes, 100u);
  EXPECT_GT(no, 100u);
  EXPECT_GT(decided_by_carried, 20u);
  EXPECT_GT(cell_kept, 100u);
}

}  // namespace
}  // namespace disktune
