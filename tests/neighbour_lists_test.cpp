// SPDX-License-Identifier: GPL-3.0-or-later
// NeighbourLists (src/tuning/neighbour_lists.h), relaxation's lists of the disks within a
// reach of each disk: after every move (small ones, which keep the lists, and jumps of a
// few radii, which relist the disk and must add it to the lists of the disks it lands
// among), the disks a list gives for any disk must be exactly those a scan over all
// disks finds within reach of its center, in order of id; and its conflict answer, where
// it gives one, the packing's own.
#include "../src/tuning/neighbour_lists.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <optional>
#include <random>
#include <vector>

#include "disktune/surface_sampling.h"
#include "disktune/surface_sizing.h"
#include "surface_checks.h"

namespace disktune {
namespace {

TEST(NeighbourLists, GiveExactlyTheDisksWithinReachAfterEveryMove) {
  for (const char* file : {"elephant.off", "fandisk.off"}) {
    const auto surface = test::surface_file(file);
    const double r = 0.02, reach = 1.9 * r, slack = 0.3 * r;
    Rng rng(3);
    SurfacePacking p = sample_mps(surface, SurfaceSizing::constant(r), rng);
    detail::NeighbourLists lists(p.id_bound(), reach, slack);
    lists.make(p, 2);
    const std::vector<DiskId> ids = p.ids();
    std::mt19937_64 gen(3);
    std::uniform_real_distribution<double> u(0, 1);
    const auto any_disk = [&] {
      return ids[static_cast<std::size_t>(u(gen) * static_cast<double>(ids.size()))];
    };
    std::size_t listed = 0, answered = 0;
    for (int trial = 0; trial < 400; ++trial) {
      const DiskId id = any_disk();
      // Steps of up to 0.2 r (kept lists), now and then 3 r (a relisted disk, among others).
      const double length = (trial % 5 == 4 ? 3.0 : 0.2) * r * u(gen);
      const Vec3 dir{u(gen) - 0.5, u(gen) - 0.5, u(gen) - 0.5};
      const Vec3 from = p.center(id);
      p.move(id, test::nearest_surface_point(p, from + dir * (length / norm(dir))));
      lists.moved(p, id);
      // The moved disk, and disks around where it left and where it went.
      std::vector<DiskId> asked{id, any_disk()};
      p.for_each_near(from, 2 * reach, [&](DiskId q) { asked.push_back(q); });
      p.for_each_near(p.center(id), 2 * reach, [&](DiskId q) { asked.push_back(q); });
      for (const DiskId a : asked) {
        const Vec3 c = p.center(a);
        std::vector<DiskId> expected;
        for (const DiskId q : ids)
          if (q != a && squared_norm(p.center(q) - c) <= reach * reach) expected.push_back(q);
        std::vector<DiskId> got;
        lists.for_each(p, a, c, [&](DiskId q, double d2) {
          got.push_back(q);
          EXPECT_EQ(d2, squared_norm(p.center(q) - c));
        });
        ASSERT_EQ(got, expected) << file << ", trial " << trial << ": the neighbours of disk " << a;
        listed += got.size();
        // A place a step from the disk: the list's conflict answer is the packing's.
        const Vec3 step{u(gen) - 0.5, u(gen) - 0.5, u(gen) - 0.5};
        const SurfacePoint x = test::nearest_surface_point(p, c + step * (0.8 * r / norm(step)));
        if (const std::optional<bool> meets = lists.conflicts(p, a, x)) {
          ++answered;
          ASSERT_EQ(*meets, p.conflicts(x, a)) << file << ", trial " << trial << ", disk " << a;
        }
      }
    }
    EXPECT_GT(listed, 10000u) << file;
    EXPECT_GT(answered, 1000u) << file;
  }
}

// Lists made for some disks only (relaxation's sweeps after a closing, which move only
// the disks near those the closing moved): while only those disks move, their lists
// must stay exactly the disks within reach, whoever those are.
TEST(NeighbourLists, ListsMadeForSomeDisksStayExactWhileOnlyTheyMove) {
  const auto surface = test::surface_file("elephant.off");
  const double r = 0.02, reach = 1.9 * r, slack = 0.3 * r;
  Rng rng(5);
  SurfacePacking p = sample_mps(surface, SurfaceSizing::constant(r), rng);
  const std::vector<DiskId> ids = p.ids();
  std::vector<DiskId> some;  // every fifth disk
  for (std::size_t k = 0; k < ids.size(); k += 5) some.push_back(ids[k]);
  detail::NeighbourLists lists(p.id_bound(), reach, slack);
  lists.make(p, 2, &some);
  std::mt19937_64 gen(5);
  std::uniform_real_distribution<double> u(0, 1);
  std::size_t listed = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const DiskId id = some[static_cast<std::size_t>(u(gen) * static_cast<double>(some.size()))];
    const double length = (trial % 5 == 4 ? 3.0 : 0.2) * r * u(gen);
    const Vec3 dir{u(gen) - 0.5, u(gen) - 0.5, u(gen) - 0.5};
    p.move(id, test::nearest_surface_point(p, p.center(id) + dir * (length / norm(dir))));
    lists.moved(p, id);
    for (std::size_t k = trial % 7; k < some.size(); k += 7) {
      const DiskId a = some[k];
      const Vec3 c = p.center(a);
      std::vector<DiskId> expected, got;
      for (const DiskId q : ids)
        if (q != a && squared_norm(p.center(q) - c) <= reach * reach) expected.push_back(q);
      lists.for_each(p, a, c, [&](DiskId q, double) { got.push_back(q); });
      ASSERT_EQ(got, expected) << "trial " << trial << ": the neighbours of disk " << a;
      listed += got.size();
    }
  }
  EXPECT_GT(listed, 10000u);
}

}  // namespace
}  // namespace disktune
