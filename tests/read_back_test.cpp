// SPDX-License-Identifier: GPL-3.0-or-later
// A sample always reads back (#17): written as the command writes it and read as the
// command reads it, every domain kind, one radius and a sizing, many seeds, gives the
// same disks (bit for bit in the plane; on a surface each point back on its triangle),
// which the library accepts and the independent oracles judge conflict-free and maximal.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "disktune/boundary.h"
#include "disktune/io.h"
#include "disktune/sampling.h"
#include "disktune/sizing.h"
#include "disktune/surface_io.h"
#include "disktune/surface_sampling.h"
#include "disktune/voids.h"
#include "disktune/surface_voids.h"
#include "oracle/oracle.h"
#include "oracle/planar_oracle.h"
#include "planar_checks.h"
#include "surface_checks.h"
#include "test_util.h"

namespace disktune {
namespace {

using test::TempDir;

constexpr int kSeeds = 6;

std::vector<std::array<double, 3>> disks_of(const Packing& p) {
  std::vector<std::array<double, 3>> out;
  for (const DiskId id : p.ids()) out.push_back({p.center(id).x, p.center(id).y, p.radius(id)});
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::array<double, 5>> disks_of(const SurfacePacking& p) {
  std::vector<std::array<double, 5>> out;
  for (const DiskId id : p.ids()) {
    const Vec3 c = p.center(id);
    out.push_back({c.x, c.y, c.z, p.radius(id), (p.flags(id) & kFixed) ? 1.0 : 0.0});
  }
  std::sort(out.begin(), out.end());
  return out;
}

void expect_planar_oracle(const PlanarDomain& domain, const Packing& p) {
  oracle::PlanarOptions options;
  for (const DiskId id : p.ids()) options.boundary_flags.push_back((p.flags(id) & kFixed) != 0);
  const oracle::PlanarReport report =
      oracle::check_planar(test::oracle_domain(domain), test::centers_of(p), test::radii_of(p), options);
  EXPECT_TRUE(report.ok()) << report.summary();
}

TEST(ReadBack, BoxSamplesReadBackExactly) {
  const PeriodicBox box(1.3, 0.8);
  for (int seed = 1; seed <= kSeeds; ++seed) {
    TempDir dir;
    Rng rng(seed);
    const Packing sampled = sample_mps(box, 0.03, rng);
    write_points_csv(dir.file("s.csv"), sampled);
    const Packing back = read_packing_csv(dir.file("s.csv"), box, 0.03);
    EXPECT_EQ(disks_of(back), disks_of(sampled)) << "seed " << seed;
    EXPECT_NO_THROW(validate_packing(back, "read back"));
    const oracle::Report report = oracle::check_all(test::box_of(box), 0.03, test::centers_of(back));
    EXPECT_TRUE(report.conflict_free() && report.maximal()) << "seed " << seed << ": " << report.summary();
  }
}

TEST(ReadBack, PlanarSamplesReadBackExactly) {
  for (const char* name : {"square_with_hole.poly", "gear.poly"}) {
    const auto domain =
        std::make_shared<const PlanarDomain>(read_poly(std::string(DISKTUNE_DATA_DIR) + "/domains/" + name));
    const auto sizing = std::make_shared<const Sizing>(expression_sizing("0.02 + 0.02*x*x"));
    for (int seed = 1; seed <= kSeeds; ++seed) {
      TempDir dir;
      Rng rng(seed);
      // One radius.
      const Packing one = sample_mps(domain, 0.03, rng);
      write_points_csv(dir.file("one.csv"), one);
      Packing one_back = read_packing_csv(dir.file("one.csv"), domain, 0.03);
      boundary_loops(one_back, *domain);
      EXPECT_EQ(disks_of(one_back), disks_of(one)) << name << " seed " << seed;
      EXPECT_NO_THROW(validate_packing(one_back, "read back"));
      expect_planar_oracle(*domain, one_back);
      // A sizing.
      const Packing sized = sample_mps(domain, sizing, rng);
      write_points_csv(dir.file("sized.csv"), sized);
      Packing sized_back = sized_packing(sized.frame(), domain, sizing);
      read_packing_csv(dir.file("sized.csv"), sized_back);
      boundary_loops(sized_back, *domain);
      EXPECT_EQ(disks_of(sized_back), disks_of(sized)) << name << " sized, seed " << seed;
      EXPECT_NO_THROW(validate_packing(sized_back, "read back"));
      expect_planar_oracle(*domain, sized_back);
    }
  }
}

TEST(ReadBack, SurfaceSamplesReadBackExactly) {
  for (const char* name : {"eight.off", "mesh_with_border.off"}) {
    const auto surface = test::surface_file(name);
    const double r = 0.04 * std::sqrt(surface->area());
    for (int seed = 1; seed <= kSeeds; ++seed) {
      TempDir dir;
      Rng rng(seed);
      const SurfacePacking sampled = sample_mps(surface, SurfaceSizing::constant(r), rng);
      write_surface_csv(dir.file("s.csv"), sampled);
      SurfacePacking back(surface, SurfaceSizing::constant(r));
      read_surface_csv(dir.file("s.csv"), back);
      // Each point is put back on its nearest triangle, which may move its last bits.
      const auto got = disks_of(back), want = disks_of(sampled);
      ASSERT_EQ(got.size(), want.size()) << name << " seed " << seed;
      double moved = 0;
      for (std::size_t i = 0; i < got.size(); ++i) {
        for (int k = 0; k < 5; ++k) moved = std::max(moved, std::abs(got[i][k] - want[i][k]));
      }
      EXPECT_LE(moved, 1e-12 * r) << name << " seed " << seed;
      EXPECT_NO_THROW(validate_packing(back, "read back"));
      EXPECT_SURFACE_OK(back);
    }
  }
}

}  // namespace
}  // namespace disktune
