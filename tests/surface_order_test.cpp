// SPDX-License-Identifier: GPL-3.0-or-later
// SurfacePacking::order_by_place: the renumbered packing holds the same disks (center,
// triangle, radius, flags, patches) under ids 0..n-1 in the order it returns, its grid
// answers every query as a scan over all disks does, it counts as a new packing
// (serial), and ids near in number are near in space (far nearer than in the darts'
// order). Checked with one radius and a varying one, with fixed feature disks, after
// removals that left free ids.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

#include "disktune/surface_features.h"
#include "disktune/surface_sampling.h"
#include "disktune/surface_sizing.h"
#include "disktune/threads.h"
#include "surface_checks.h"

namespace disktune {
namespace {

struct Disk {
  SurfacePoint at;
  double radius;
  std::uint8_t flags;
  PatchSet patches;
};

Disk disk_of(const SurfacePacking& p, DiskId id) {
  return {p.point(id), p.radius(id), p.flags(id), p.patches(id)};
}

// The mean distance between disks of consecutive ids, over the live ones in id order.
double mean_step(const SurfacePacking& p) {
  const std::vector<DiskId> ids = p.ids();
  double sum = 0;
  for (std::size_t k = 1; k < ids.size(); ++k) sum += norm(p.center(ids[k]) - p.center(ids[k - 1]));
  return sum / static_cast<double>(ids.size() - 1);
}

TEST(SurfaceOrder, RenumbersTheSameDisksAndTheGridFollows) {
  auto fandisk = std::make_shared<SurfaceDomain>(*test::surface_file("fandisk.off"));
  fandisk->set_features(detect_features(*fandisk, {60, 60}));
  const auto elephant = test::surface_file("elephant.off");
  std::vector<double> radii;
  for (const Vec3 v : elephant->vertices())
    radii.push_back(0.02 + 0.02 * std::abs(std::sin(20 * v.x)));
  struct Case {
    std::shared_ptr<const SurfaceDomain> surface;
    SurfaceSizing sizing;
  };
  for (const Case& c : {Case{fandisk, SurfaceSizing::constant(0.03)},
                        Case{elephant, SurfaceSizing::per_vertex(*elephant, radii)}}) {
    Rng rng(5);
    const SurfacePacking sample = sample_mps(c.surface, c.sizing, rng);
    // The sample's disks in a random order (as darts come), then free ids in the middle.
    std::mt19937_64 gen(5);
    std::vector<DiskId> shuffled = sample.ids();
    std::shuffle(shuffled.begin(), shuffled.end(), gen);
    SurfacePacking p(c.surface, c.sizing);
    for (const DiskId id : shuffled) p.insert(sample.point(id), sample.flags(id));
    const std::vector<DiskId> before_removal = p.ids();
    for (std::size_t k = 0; k < before_removal.size(); k += 7) p.remove(before_removal[k]);
    std::vector<Disk> before(p.id_bound());
    for (const DiskId id : p.ids()) before[id] = disk_of(p, id);
    const std::size_t live = p.size();
    const double step_before = mean_step(p);
    const std::uint64_t serial = p.serial();

    const std::vector<DiskId> old = p.order_by_place();
    ASSERT_EQ(old.size(), live);
    ASSERT_EQ(p.size(), live);
    ASSERT_EQ(p.id_bound(), live) << "free ids are dropped";
    EXPECT_NE(p.serial(), serial);
    std::vector<char> seen(before.size(), 0);
    for (DiskId id = 0; id < live; ++id) {
      ASSERT_TRUE(p.alive(id));
      ASSERT_LT(old[id], before.size());
      ASSERT_FALSE(seen[old[id]]) << "old id " << old[id] << " twice";
      seen[old[id]] = 1;
      const Disk was = before[old[id]], now = disk_of(p, id);
      EXPECT_EQ(now.at.p, was.at.p);
      EXPECT_EQ(now.at.triangle, was.at.triangle);
      EXPECT_EQ(now.radius, was.radius);
      EXPECT_EQ(now.flags, was.flags);
      EXPECT_EQ(now.patches, was.patches);
    }
    // The grid against a scan over all disks, around random points of the surface.
    for (int trial = 0; trial < 200; ++trial) {
      std::uniform_real_distribution<double> u(0, 1);
      const Vec3 q = p.index().point_by_area(u(gen), u(gen), u(gen)).p;
      const double R = 3 * p.max_radius() * u(gen);
      std::vector<DiskId> found, scanned;
      p.for_each_near(q, R, [&](DiskId id) { found.push_back(id); });
      for (DiskId id = 0; id < live; ++id)
        if (squared_norm(p.center(id) - q) <= R * R) scanned.push_back(id);
      std::sort(found.begin(), found.end());
      ASSERT_EQ(found, scanned) << "around " << q.x << " " << q.y << " " << q.z;
    }
    // Consecutive ids are near: in a random order a step is about the surface's size.
    EXPECT_LT(mean_step(p), 0.25 * step_before) << step_before;
    // Still a packing to go on with: inserting at a disk's own point (a reference into
    // the packing, which the insert may move) and removing work.
    const DiskId twin = p.insert(p.point(0));
    EXPECT_EQ(p.center(twin), p.center(0));
    p.remove(twin);
    EXPECT_EQ(p.size(), live);
  }
}

// The sampler's own output comes in that order already, and sampling twice with one
// seed gives the same ids.
TEST(SurfaceOrder, SamplesComeOrderedAndRepeat) {
  const auto eight = test::surface_file("eight.off");
  Rng a(9), b(9);
  SurfacePacking p = sample_mps(eight, SurfaceSizing::constant(0.04), a);
  const SurfacePacking q = sample_mps(eight, SurfaceSizing::constant(0.04), b);
  ASSERT_EQ(p.size(), q.size());
  for (DiskId id = 0; id < p.id_bound(); ++id) ASSERT_EQ(p.center(id), q.center(id));
  const std::vector<DiskId> old = p.order_by_place();
  for (DiskId id = 0; id < old.size(); ++id) EXPECT_EQ(old[id], id);
}

// The sampler scans the cells and the darts on every core, in chunks joined in order:
// one, two and three threads give the same disks, on a smooth surface and on one with
// feature curves (fandisk at 60 degrees), each with a few thousand cells a level.
TEST(SurfaceOrder, SamplesAreTheSameOnAnyNumberOfThreads) {
  auto fandisk = std::make_shared<SurfaceDomain>(*test::surface_file("fandisk.off"));
  FeatureOptions sharp;
  sharp.angle = 60;
  fandisk->set_features(detect_features(*fandisk, sharp));
  const std::vector<std::pair<std::shared_ptr<const SurfaceDomain>, double>> cases = {
      {test::surface_file("elephant.off"), 0.015}, {fandisk, 0.025}};
  for (const auto& [surface, r] : cases) {
    std::vector<std::vector<SurfacePoint>> runs;
    for (const unsigned threads : {1u, 2u, 3u}) {
      set_default_threads(threads);
      Rng rng(5);
      const SurfacePacking p = sample_mps(surface, SurfaceSizing::constant(r), rng);
      std::vector<SurfacePoint> points;
      for (const DiskId id : p.ids()) points.push_back(p.point(id));
      runs.push_back(points);
    }
    set_default_threads(0);
    ASSERT_GT(runs[0].size(), 2000u);
    for (const std::size_t k : {1, 2}) {
      ASSERT_EQ(runs[k].size(), runs[0].size());
      for (std::size_t i = 0; i < runs[0].size(); ++i) {
        ASSERT_EQ(runs[k][i].p, runs[0][i].p) << "disk " << i << " on " << k + 1 << " threads";
        ASSERT_EQ(runs[k][i].triangle, runs[0][i].triangle);
      }
    }
  }
}

}  // namespace
}  // namespace disktune
