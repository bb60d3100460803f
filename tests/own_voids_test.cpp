// SPDX-License-Identifier: GPL-3.0-or-later
// OwnVoidCache (src/tuning/own_voids.h): through inserts, removals, moves and flag
// changes anywhere, every answer equals a fresh scan (voids_near) of the packing as it
// is then; a copy of the packing is never served from the original's cache.
#include "../src/tuning/own_voids.h"

#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "../src/tuning/surface_repair.h"
#include "disktune/surface_sampling.h"
#include "disktune/surface_sizing.h"
#include "surface_checks.h"

namespace disktune {
namespace {

double diagonal(const SurfaceDomain& d) { return norm(d.bbox_max() - d.bbox_min()); }

void expect_fresh(const SurfacePacking& packing, DiskId p) {
  const std::vector<SurfaceVoidPoint> kept = detail::own_voids(packing, p);
  const std::vector<SurfaceVoidPoint> fresh =
      detail::voids_near(packing, packing.center(p), detail::void_reach(packing.radius(p)), {p});
  ASSERT_EQ(kept.size(), fresh.size()) << "disk " << p;
  for (std::size_t i = 0; i < kept.size(); ++i) {
    EXPECT_TRUE(kept[i].at.p == fresh[i].at.p && kept[i].at.triangle == fresh[i].at.triangle)
        << "disk " << p;
  }
}

// A point of the surface: a random point of a random triangle.
SurfacePoint random_point(const SurfaceDomain& domain, Rng& rng) {
  const auto t = static_cast<std::uint32_t>(uniform_index(rng, domain.triangles().size()));
  const auto& tri = domain.triangles()[t];
  double a = uniform01(rng), b = uniform01(rng);
  if (a + b > 1) a = 1 - a, b = 1 - b;
  const auto& v = domain.vertices();
  return {v[tri[0]] + (v[tri[1]] - v[tri[0]]) * a + (v[tri[2]] - v[tri[0]]) * b, t};
}

// An MPS of eight.off (about 1,400 disks).
SurfacePacking eight_sample(const std::shared_ptr<const SurfaceDomain>& domain, Rng& rng) {
  return sample_mps(domain, SurfaceSizing::constant(0.03 * diagonal(*domain)), rng);
}

TEST(OwnVoidCache, AnswersAsAFreshScanThroughEveryKindOfChange) {
  const auto domain = test::surface_file("eight.off");
  Rng rng(3);
  SurfacePacking packing = eight_sample(domain, rng);
  const detail::OwnVoidCache cache(packing);
  const double r = packing.max_radius();
  for (const DiskId p : packing.ids()) expect_fresh(packing, p);  // all kept once
  for (int step = 0; step < 300; ++step) {
    std::vector<DiskId> ids = packing.ids();
    const DiskId d = ids[uniform_index(rng, ids.size())];
    Vec3 at = packing.center(d);
    switch (step % 4) {
      case 0:
        packing.remove(d);
        break;
      case 1:
        at = packing.center(packing.insert(random_point(*domain, rng)));
        break;
      case 2: {
        // A short step along the disk's own triangle, or a jump anywhere.
        const SurfacePoint to = step % 8 == 2 ? random_point(*domain, rng) : packing.point(d);
        packing.move(d,
                     to.p == packing.center(d) ? SurfacePoint{(at + to.p) * 0.5, to.triangle} : to);
        break;
      }
      case 3:
        packing.set_flags(d, packing.flags(d) ^ kFrozen);
        break;
    }
    // The disks near the change (whose voids it can change) and some anywhere.
    ids = packing.ids();
    packing.for_each_near(at, 3 * r, [&](DiskId p) { expect_fresh(packing, p); });
    for (int k = 0; k < 10; ++k) expect_fresh(packing, ids[uniform_index(rng, ids.size())]);
    if (HasFailure()) return;
  }
}

TEST(OwnVoidCache, AnotherPackingIsNotServedFromIt) {
  const auto domain = test::surface_file("eight.off");
  Rng rng(4);
  SurfacePacking packing = eight_sample(domain, rng);
  const detail::OwnVoidCache cache(packing);
  const DiskId p = packing.ids().front();
  expect_fresh(packing, p);
  SurfacePacking copy = packing;
  // The original loses p's neighbours and is asked again; the copy keeps them but
  // counts as many changes in the same cells (flags), so that only the packing's
  // identity tells the two apart.
  std::vector<DiskId> near;
  packing.for_each_near(packing.center(p), 2 * packing.max_radius(), [&](DiskId q) {
    if (q != p) near.push_back(q);
  });
  ASSERT_FALSE(near.empty());
  for (const DiskId q : near) packing.remove(q);
  expect_fresh(packing, p);
  for (const DiskId q : near) copy.set_flags(q, copy.flags(q) ^ kFrozen);
  ASSERT_EQ(copy.changes_near(copy.center(p), 3 * copy.max_radius()),
            packing.changes_near(packing.center(p), 3 * packing.max_radius()));
  expect_fresh(copy, p);
  EXPECT_NE(detail::own_voids(copy, p).size(), detail::own_voids(packing, p).size());
  packing = copy;  // an assignment makes it another packing too
  expect_fresh(packing, p);
}

}  // namespace
}  // namespace disktune
