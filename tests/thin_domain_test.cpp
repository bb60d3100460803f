// SPDX-License-Identifier: GPL-3.0-or-later
// Thin planar domains (issue #17): strips and slivers whose disks lie nearly all on the
// boundary. Their maximal packings hold more disks than the hexagonal density of their
// area (boundary disks have half their disk outside), the feature sizing there is
// measured inside and not only along the two long edges, and tune reaches counts on
// either side of the sample by moving boundary disks. Every result is judged by the
// independent planar oracle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "disktune/boundary.h"
#include "disktune/packing.h"
#include "disktune/planar_domain.h"
#include "disktune/sampling.h"
#include "disktune/sizing.h"
#include "disktune/tuning.h"
#include "oracle/planar_oracle.h"
#include "planar_checks.h"

namespace disktune {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::shared_ptr<const PlanarDomain> strip(double length, double width) {
  return std::make_shared<const PlanarDomain>(std::vector<Vec2>{{0, 0}, {length, 0}, {length, width}, {0, width}});
}

void expect_valid(const Packing& p, const PlanarDomain& d) {
  const auto report = test::check_with_oracle(p, d);
  EXPECT_TRUE(report.ok()) << report.summary();
}

// A strip 1e-3 wide and 1 long: with samples = 1000 the old lattice had only two rows,
// both on the long edges, and missed the larger radii along the middle.
TEST(ThinDomain, FeatureSizingIsMeasuredInsideAStrip) {
  const auto d = strip(1, 1e-3);
  const Sizing s = feature_sizing(d, 0.01);
  const SizingStats stats = measure_sizing(s, d->frame(), d.get(), 1000);
  double largest = 0;  // by brute force on a fine grid over the strip
  for (int i = 0; i <= 4000; ++i)
    for (int j = 0; j <= 40; ++j) largest = std::max(largest, s({i / 4000.0, j * 1e-3 / 40}));
  EXPECT_GE(stats.upper, largest);
  EXPECT_GE(stats.max, 0.9 * largest);
  std::printf("[thin] strip 1 x 1e-3: largest r %.4g, measured max %.4g, bound %.4g\n", largest, stats.max, stats.upper);

  Rng rng(3);
  const Packing p = sample_mps(d, std::make_shared<const Sizing>(s), rng);
  expect_valid(p, *d);
}

TEST(ThinDomain, BoundaryUnitIsTheBoundaryOverR) {
  const auto square = strip(1, 1);
  EXPECT_DOUBLE_EQ(boundary_unit(*square, nullptr, 0.1), 40.0);
  const Sizing constant = constant_sizing(0.1);
  EXPECT_NEAR(boundary_unit(*square, &constant, 0.1), 40.0, 1e-9);
  const Sizing linear = expression_sizing("0.1 + 0.1*x");  // along y = 0 and 1: ln 2 / 0.1 each
  EXPECT_NEAR(boundary_unit(*square, &linear, 0), 1 / 0.1 + 1 / 0.2 + 2 * std::log(2.0) / 0.1, 1e-2);
}

// A strip 0.02 wide at r = 0.015: the sample itself holds more disks than the hexagonal
// density of the area (once a count tune refused), and tune moves boundary disks to
// reach counts on both sides of it.
TEST(ThinDomain, TuneReachesCountsAboveTheAreasHexagonalDensity) {
  const auto d = strip(1, 0.02);
  const double r = 0.015, unit = 4 * d->area() / (kPi * r * r), hex = kPi / (2 * std::sqrt(3.0)) * unit;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    Rng rng(seed);
    const Packing sample = sample_mps(d, r, rng);
    EXPECT_GT(static_cast<double>(sample.size()), hex) << "seed " << seed;
    for (const long change : {-12L, -4L, 4L, 12L}) {
      SCOPED_TRACE("seed " + std::to_string(seed) + " change " + std::to_string(change));
      Packing p = sample;
      const std::size_t goal = static_cast<std::size_t>(static_cast<long>(p.size()) + change);
      EXPECT_EQ(target_count_for_unit(Target::count(static_cast<double>(goal)), unit, boundary_unit(*d, nullptr, r)), goal);
      const TuneResult res = tune(p, *d, Target::count(static_cast<double>(goal)), rng);
      EXPECT_TRUE(res.reached) << p.size() << " of " << goal;
      EXPECT_EQ(p.size(), goal);
      expect_valid(p, *d);
    }
  }
  // Beyond the area's hexagonal share and a row along the whole boundary: refused.
  EXPECT_THROW(target_count_for_unit(Target::count(std::ceil(hex + boundary_unit(*d, nullptr, r) + 1)), unit,
                                     boundary_unit(*d, nullptr, r)),
               InvalidInput);
}

}  // namespace
}  // namespace disktune
