// SPDX-License-Identifier: GPL-3.0-or-later
// Maximal Poisson-disk sampling, checked by the independent oracle over many seeds,
// radii and box shapes.
#include <gtest/gtest.h>

#include <tuple>

#include "disktune/density.h"
#include "disktune/sampling.h"
#include "disktune/threads.h"
#include "test_util.h"

namespace disktune {
namespace {

oracle::Report check(const PeriodicBox& box, double r, const Packing& p, std::size_t probes,
                     std::uint64_t seed) {
  return oracle::check_all(test::box_of(box), r, test::centers_of(p), 1e-6, probes, seed);
}

TEST(Mps, ConflictFreeAndMaximalOverSeedsRadiiAndBoxes) {
  // Radii from a handful of disks up to thousands; square, wide, tall and tiny boxes.
  const std::tuple<double, double, double> cases[] = {
      {1.0, 1.0, 0.45},  {1.0, 1.0, 0.3},   {1.0, 1.0, 0.2},  {1.0, 1.0, 0.1},
      {1.0, 1.0, 0.02},  {3.0, 1.0, 0.05},  {1.0, 2.5, 0.07}, {0.1, 0.1, 0.004},
      {1.0, 0.3, 0.149}, {7.0, 5.0, 0.25},
  };
  for (const auto& [w, h, r] : cases) {
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
      const PeriodicBox box(w, h);
      Rng rng(seed);
      const Packing p = sample_mps(box, r, rng);
      const auto rep = check(box, r, p, 20000, seed);
      ASSERT_TRUE(rep.conflict_free() && rep.maximal())
          << w << "x" << h << " r=" << r << " seed=" << seed << ": " << rep.summary();
    }
  }
}

TEST(Mps, TheIssueCaseR0004IsMaximalWithTheJammingDensity) {
  // About 43,500 disks each; the area fraction of random sequential adsorption.
  for (std::uint64_t seed : {1, 2, 3}) {
    const PeriodicBox box;
    Rng rng(seed);
    const Packing p = sample_mps(box, 0.004, rng);
    const auto rep = check(box, 0.004, p, 200000, seed);
    ASSERT_TRUE(rep.conflict_free() && rep.maximal()) << rep.summary();
    const double eta = area_fraction(p.size(), 0.004, box.area());
    EXPECT_GE(eta, 0.540) << seed;
    EXPECT_LE(eta, 0.553) << seed;
  }
}

TEST(Mps, AreaFractionAveragesToTheRsaJammingLimit) {
  // The mean over seeds is much tighter than one sample: 0.547 within 0.003.
  double sum = 0;
  const int seeds = 8;
  for (int seed = 1; seed <= seeds; ++seed) {
    const PeriodicBox box;
    Rng rng(seed);
    sum += area_fraction(sample_mps(box, 0.01, rng).size(), 0.01, box.area());
  }
  EXPECT_NEAR(sum / seeds, 0.547, 0.003);
}

TEST(Mps, SameSeedSameBitsDifferentSeedDifferentSample) {
  const PeriodicBox box(1.0, 0.7);
  auto run = [&](std::uint64_t seed) {
    Rng rng(seed);
    return test::centers_of(sample_mps(box, 0.02, rng));
  };
  EXPECT_EQ(run(5), run(5));
  EXPECT_NE(run(5), run(6));
}

// The darts are tested in blocks on every core and the levels keep their cells on every
// core, in chunks joined in order: one, two and three threads give the same bits
// (r = 0.005: some 40,000 cells a level, 150,000 darts in three blocks).
TEST(Mps, SameSeedSameBitsOnAnyNumberOfThreads) {
  const PeriodicBox box(1.0, 0.7);
  auto run = [&](unsigned threads) {
    set_default_threads(threads);
    Rng rng(3);
    const auto centers = test::centers_of(sample_mps(box, 0.005, rng));
    set_default_threads(0);
    return centers;
  };
  const auto one = run(1);
  EXPECT_EQ(run(2), one);
  EXPECT_EQ(run(3), one);
}

TEST(Mps, EveryLevelSettingStaysExact) {
  // The exact void phase must finish the job however little the darts did.
  for (int levels : {0, 1, 2, 6}) {
    for (double darts : {0.1, 1.0}) {
      const PeriodicBox box;
      Rng rng(static_cast<std::uint64_t>(levels * 10 + 1));
      MpsOptions opt;
      opt.levels = levels;
      opt.darts_per_active_cell = darts;
      const Packing p = sample_mps(box, 0.03, rng, opt);
      const auto rep = check(box, 0.03, p, 20000, 1);
      ASSERT_TRUE(rep.conflict_free() && rep.maximal())
          << "levels=" << levels << " darts=" << darts << ": " << rep.summary();
    }
  }
}

TEST(Mps, BadRadiusIsRejected) {
  const PeriodicBox box;
  Rng rng(1);
  EXPECT_THROW(sample_mps(box, 0.0, rng), InvalidInput);
  EXPECT_THROW(sample_mps(box, -0.1, rng), InvalidInput);
  EXPECT_THROW(sample_mps(box, NAN, rng), InvalidInput);
  EXPECT_THROW(sample_mps(box, 0.5, rng), InvalidInput);
}

}  // namespace
}  // namespace disktune
