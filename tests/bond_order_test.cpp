// SPDX-License-Identifier: GPL-3.0-or-later
// Bond order (psi6 and grains): lattices with answers derived by hand, and maximal and
// crystal-tuned packings checked against a brute-force computation here (every pair's
// nearest periodic image, a full sort, a flood fill for the grains).
#include "disktune/bond_order.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <string>
#include <vector>

#include "disktune/periodic_box.h"
#include "disktune/random.h"
#include "disktune/sampling.h"
#include "disktune/tuning.h"
#include "lattices.h"

namespace disktune {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Everything bond_order reports, by brute force.
struct Expected {
  std::vector<double> local, orientation;
  double global = 0, local_mean = 0, hexagonal_share = 0;
  std::size_t grains = 0, largest = 0, in_grains = 0;
};

Expected brute_force(const Packing& p) {
  const std::vector<DiskId> ids = p.ids();
  const std::size_t n = ids.size();
  const double w = p.frame().extent.x, h = p.frame().extent.y;
  std::vector<std::vector<std::size_t>> six(n);
  std::vector<std::complex<double>> psi(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<std::pair<double, std::pair<std::size_t, Vec2>>> all;
    for (std::size_t j = 0; j < n; ++j) {
      Vec2 d = p.center(ids[j]) - p.center(ids[i]);
      d.x -= w * std::round(d.x / w), d.y -= h * std::round(d.y / h);  // nearest image
      if (j != i) all.push_back({d.x * d.x + d.y * d.y, {ids[j], d}});
    }
    std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) {
      return a.first != b.first ? a.first < b.first : a.second.first < b.second.first;
    });
    std::complex<double> sum = 0;
    for (int k = 0; k < 6; ++k) {
      const Vec2 d = all[k].second.second;
      sum += std::exp(std::complex<double>(0, 6 * std::atan2(d.y, d.x)));
      six[i].push_back(static_cast<std::size_t>(
          std::find(ids.begin(), ids.end(), all[k].second.first) - ids.begin()));
    }
    psi[i] = sum / 6.0;
  }
  Expected e;
  std::complex<double> total = 0;
  for (std::size_t i = 0; i < n; ++i) {
    total += psi[i];
    e.local.push_back(std::abs(psi[i]));
    e.local_mean += std::abs(psi[i]) / static_cast<double>(n);
    e.hexagonal_share += (std::abs(psi[i]) > 0.9) / static_cast<double>(n);
    e.orientation.push_back(std::fmod(std::arg(psi[i]) * 180 / kPi / 6 + 60, 60.0));
  }
  e.global = std::abs(total) / static_cast<double>(n);
  // Grains: flood over bonds (either way) between hexagonal disks within 10 degrees.
  const auto joined = [&](std::size_t i, std::size_t j) {
    const double d = std::fabs(e.orientation[i] - e.orientation[j]);
    return e.local[i] > 0.9 && e.local[j] > 0.9 && std::min(d, 60 - d) < 10;
  };
  std::vector<char> seen(n, 0);
  for (std::size_t s = 0; s < n; ++s) {
    if (seen[s] || e.local[s] <= 0.9) continue;
    std::vector<std::size_t> stack{s}, grain;
    seen[s] = 1;
    while (!stack.empty()) {
      const std::size_t i = stack.back();
      stack.pop_back();
      grain.push_back(i);
      for (std::size_t j = 0; j < n; ++j) {
        const bool bond = std::count(six[i].begin(), six[i].end(), j) ||
                          std::count(six[j].begin(), six[j].end(), i);
        if (!seen[j] && bond && joined(i, j)) seen[j] = 1, stack.push_back(j);
      }
    }
    if (grain.size() >= 10)
      ++e.grains, e.largest = std::max(e.largest, grain.size()), e.in_grains += grain.size();
  }
  return e;
}

void expect_as_brute_force(const Packing& p) {
  const BondOrder o = bond_order(p);
  const Expected e = brute_force(p);
  ASSERT_EQ(o.count, p.size());
  EXPECT_NEAR(o.psi6_global, e.global, 1e-12);
  EXPECT_NEAR(o.psi6_local_mean, e.local_mean, 1e-12);
  EXPECT_NEAR(o.hexagonal_share, e.hexagonal_share, 1e-12);
  for (std::size_t i = 0; i < e.local.size(); ++i) ASSERT_NEAR(o.local[i], e.local[i], 1e-12) << i;
  EXPECT_EQ(o.grain_count, e.grains);
  EXPECT_EQ(o.largest_grain, e.largest);
  EXPECT_NEAR(o.grain_share, static_cast<double>(e.in_grains) / static_cast<double>(p.size()),
              1e-12);
}

TEST(BondOrder, TheHexagonalLatticeIsOneGrainWithPsi6One) {
  const Packing p = test::hex_lattice(10, 12, 1.0, 1.0);
  const BondOrder o = bond_order(p);
  ASSERT_EQ(o.count, 120u);
  EXPECT_NEAR(o.psi6_global, 1, 1e-12);
  EXPECT_NEAR(o.psi6_local_mean, 1, 1e-12);
  EXPECT_EQ(o.hexagonal_share, 1);
  for (const double a : o.orientation) EXPECT_NEAR(std::min(a, 60 - a), 0, 1e-9);  // bonds along x
  EXPECT_EQ(o.grain_count, 1u);
  EXPECT_EQ(o.largest_grain, 120u);
  EXPECT_EQ(o.grain_share, 1);
  expect_as_brute_force(p);
}

// Square lattice: the four sides at 0, 90, 180, 270 degrees give exp(6 i theta) = 1, -1,
// 1, -1 (sum 0); two of the four diagonals tie for the last two places, and theirs are
// -i, i, -i, i, so the six sum to 0 or +-2i: abs(psi6) is 0 or 1/3 at every disk.
TEST(BondOrder, TheSquareLatticeHasNoHexagonalDiskAndNoGrain) {
  const BondOrder o = bond_order(test::square_lattice(8, 8, 1.0, 1.0));
  ASSERT_EQ(o.count, 64u);
  for (const double m : o.local)
    EXPECT_TRUE(std::fabs(m) < 1e-9 || std::fabs(m - 1.0 / 3) < 1e-9) << m;
  EXPECT_EQ(o.hexagonal_share, 0);
  EXPECT_EQ(o.grain_count, 0u);
  EXPECT_EQ(o.grain_share, 0);
}

// f(sample, box, rng) for the maximal samples of the unit periodic square at r = 0.04
// of seeds 1..seeds, rng as the sample left it.
template <class F>
void for_samples(std::uint64_t seeds, F&& f) {
  const PeriodicBox box(1, 1);
  for (std::uint64_t seed = 1; seed <= seeds; ++seed) {
    SCOPED_TRACE(seed);
    Rng rng(seed);
    Packing p = sample_mps(box, 0.04, rng);
    f(p, box, rng);
  }
}

TEST(BondOrder, MaximalSamplesMatchTheBruteForceOverSeeds) {
  for_samples(4, [](const Packing& p, const PeriodicBox&, Rng&) {
    expect_as_brute_force(p);
    const BondOrder o = bond_order(p);
    EXPECT_LT(o.psi6_global, 0.1);  // no common orientation (about 1/sqrt(N) = 0.045)
    EXPECT_LT(o.hexagonal_share, 0.1);
  });
}

// Crystal injection to eta 0.85 grows hexagonal grains: the brute force agrees on them.
TEST(BondOrder, CrystalTunedPackingsHaveGrainsAsTheBruteForceFindsThem) {
  for_samples(2, [](Packing& p, const PeriodicBox& box, Rng& rng) {
    TuneOptions options;
    options.method = Method::crystal_injection;
    ASSERT_TRUE(tune(p, box, Target::area_fraction(0.85), rng, options).reached);
    const BondOrder o = bond_order(p);
    EXPECT_GT(o.hexagonal_share, 0.5);
    EXPECT_GE(o.grain_count, 1u);
    expect_as_brute_force(p);
  });
}

// The automatic schedule past squeeze injection grows many grains at orientations
// spread over the lattice's period (grain_inject), not one crystal: by the brute force,
// many grains, none a third of the packing, most disks hexagonal, and little common
// orientation left. About 4,800 disks here (r = 0.015): 9 grains at 0.85 (grown from the
// sample, a nucleus per 300 of its disks), whose unequal sizes leave 0.04-0.08 (at 40,000
// disks about 0.01-0.02, docs/tuning.md); one crystal leaves 0.7 at 0.85 in one grain of
// two thirds of the disks.
TEST(BondOrder, TheAutomaticScheduleGrowsGrainsWithoutACommonOrientation) {
  const PeriodicBox box(1, 1);
  for (const std::uint64_t seed : {1, 2}) {
    const double eta = 0.85;
    SCOPED_TRACE(std::to_string(seed) + " eta " + std::to_string(eta));
    Rng rng(seed);
    Packing p = sample_mps(box, 0.015, rng);
    ASSERT_TRUE(tune(p, box, Target::area_fraction(eta), rng).reached);
    const Expected e = brute_force(p);
    EXPECT_LT(e.global, 0.2);
    EXPECT_GE(e.grains, 5u);
    EXPECT_GT(e.hexagonal_share, 0.4);
    EXPECT_LT(e.largest, p.size() / 3);
    std::printf(
        "[figures] grains: seed %d eta %.2f N=%zu psi6 %.3f, %.1f %% hexagonal, %zu grains "
        "(largest %zu)\n",
        static_cast<int>(seed), eta, p.size(), e.global, 100 * e.hexagonal_share, e.grains,
        e.largest);
  }
}

// Up to eta 0.80 the automatic schedule squeezes the sample (squeeze_inject) and leaves it
// about as disordered as random close packing allows: by the brute force, few disks
// locally hexagonal, no common orientation, no grain of note. Grains there left about
// half the disks hexagonal (docs/tuning.md).
TEST(BondOrder, TheAutomaticScheduleKeepsThePackingDisorderedToEta080) {
  const PeriodicBox box(1, 1);
  for (const std::uint64_t seed : {1, 2, 3}) {
    SCOPED_TRACE(std::to_string(seed));
    Rng rng(seed);
    Packing p = sample_mps(box, 0.015, rng);
    ASSERT_TRUE(tune(p, box, Target::area_fraction(0.80), rng).reached);
    const Expected e = brute_force(p);
    EXPECT_LT(e.hexagonal_share, 0.2);
    EXPECT_LT(e.global, 0.1);
    EXPECT_LT(e.largest, p.size() / 20);
    std::printf(
        "[figures] squeeze: seed %d eta 0.80 N=%zu psi6 %.3f, %.1f %% hexagonal, %zu grains "
        "(largest %zu)\n",
        static_cast<int>(seed), p.size(), e.global, 100 * e.hexagonal_share, e.grains, e.largest);
  }
}

TEST(BondOrder, FewerThanSevenDisksAreNotMeasured) {
  const Packing p = test::hex_lattice(2, 2, 1.0, 0.5);
  EXPECT_EQ(bond_order(p).count, 0u);
}

}  // namespace
}  // namespace disktune
