// SPDX-License-Identifier: GPL-3.0-or-later
// Fiber RVEs (rve.h): the count and the fiber fraction the test computes itself, the
// arrangement checked by the independent torus oracle at center distance D + g
// (conflict-free: no two fibers closer than D + g; maximal: no room for one more
// fiber's center), and its disorder by a bond-orientational order computed here by brute
// force.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include "disktune/errors.h"
#include "disktune/rve.h"
#include "oracle/oracle.h"

namespace disktune {
namespace {

constexpr double kPi = 3.14159265358979323846;

oracle::Points points_of(const Rve& rve) {
  oracle::Points out;
  for (const Vec2 c : rve.centers) out.push_back({c.x, c.y});
  return out;
}

::testing::AssertionResult valid(const Rve& rve, std::uint64_t seed) {
  for (const Vec2 c : rve.centers) {
    if (!(c.x >= 0 && c.x < rve.cell.width() && c.y >= 0 && c.y < rve.cell.height()))
      return ::testing::AssertionFailure() << "center (" << c.x << ", " << c.y << ") outside the cell";
  }
  const auto rep = oracle::check_all({rve.cell.width(), rve.cell.height()}, rve.diameter + rve.gap, points_of(rve),
                                     1e-6, 20000, seed);
  if (rep.conflict_free() && rep.maximal()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << rep.summary();
}

// |mean over fibers of (1/6) sum over the 6 nearest of exp(6 i theta)|: 1 for the
// hexagonal lattice, about 1/sqrt(n) for no common orientation. All pairs, minimum image.
double global_psi6(const Rve& rve) {
  const double w = rve.cell.width(), h = rve.cell.height();
  std::complex<double> sum = 0;
  std::vector<std::pair<double, double>> near;  // squared distance, bond angle
  for (const Vec2 a : rve.centers) {
    near.clear();
    for (const Vec2 b : rve.centers) {
      double dx = b.x - a.x, dy = b.y - a.y;
      dx -= w * std::round(dx / w), dy -= h * std::round(dy / h);
      if (dx != 0 || dy != 0) near.push_back({dx * dx + dy * dy, std::atan2(dy, dx)});
    }
    std::partial_sort(near.begin(), near.begin() + 6, near.end());
    std::complex<double> local = 0;
    for (int k = 0; k < 6; ++k) local += std::polar(1.0, 6 * near[k].second);
    sum += local / 6.0;
  }
  return std::abs(sum) / static_cast<double>(rve.centers.size());
}

struct Case {
  double width, height, diameter, gap;
  std::size_t fibers;
  double vf;
};

TEST(Rve, ExactCountConflictFreeAndMaximalOverSeeds) {
  const Case cases[] = {
      {1, 1, 0.05, 0.0025, 0, 0.70},  // the case: g = 0.05 D, vf 0.70 (eta 0.772)
      {1, 1, 0.05, 0, 0, 0.67},       // the paper's vf, fibers may touch
      {2, 0.7, 0.04, 0.004, 500, 0},  // a rectangle, an exact count
      {1, 1, 0.1, 0.02, 0, 0.30},     // sparser than the sample: ejection
  };
  for (const Case& c : cases) {
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
      RveSpec spec;
      spec.width = c.width, spec.height = c.height, spec.diameter = c.diameter, spec.gap = c.gap;
      spec.fibers = c.fibers, spec.fiber_fraction = c.vf, spec.seed = seed;
      const Rve rve = make_rve(spec);
      const double one = kPi * c.diameter * c.diameter / 4, area = c.width * c.height;
      const std::size_t asked = c.fibers ? c.fibers : static_cast<std::size_t>(std::lround(c.vf * area / one));
      SCOPED_TRACE(::testing::Message() << "cell " << c.width << " x " << c.height << ", D " << c.diameter << ", g "
                                        << c.gap << ", seed " << seed);
      EXPECT_TRUE(rve.tuning.reached);
      EXPECT_EQ(rve.centers.size(), asked);
      EXPECT_NEAR(rve.fiber_fraction, static_cast<double>(asked) * one / area, 1e-12);
      if (c.vf > 0) {
        EXPECT_LE(std::abs(rve.fiber_fraction - c.vf), 0.5 * one / area);
      }
      EXPECT_TRUE(valid(rve, seed));
    }
  }
}

TEST(Rve, DenseArrangementsStayRandom) {
  // vf 0.70 with g = 0.05 D, about 2000 fibers: a crystal would give |psi6| near 1; the
  // issue asks for below 0.1.
  Rve lattice;  // the measure itself tells order: 1 for a hexagonal lattice
  lattice.cell = PeriodicBox(1, 20 * std::sqrt(3.0) / 40);  // 20 rows sqrt(3)/2 spacings apart
  for (int j = 0; j < 20; ++j)
    for (int i = 0; i < 20; ++i) lattice.centers.push_back({(i + 0.5 * (j % 2)) / 20, j * std::sqrt(3.0) / 40});
  EXPECT_GT(global_psi6(lattice), 0.999);
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    RveSpec spec;
    spec.diameter = 0.02, spec.gap = 0.001, spec.fiber_fraction = 0.70, spec.seed = seed;
    const Rve rve = make_rve(spec);
    ASSERT_TRUE(rve.tuning.reached);
    EXPECT_LT(global_psi6(rve), 0.1) << "seed " << seed;
  }
}

TEST(Rve, SameSeedSameFibersOtherSeedOthers) {
  RveSpec spec;
  spec.diameter = 0.05, spec.gap = 0.005, spec.fiber_fraction = 0.6, spec.seed = 9;
  const Rve a = make_rve(spec), b = make_rve(spec);
  spec.seed = 10;
  const Rve c = make_rve(spec);
  ASSERT_EQ(a.centers.size(), b.centers.size());
  for (std::size_t i = 0; i < a.centers.size(); ++i) {
    EXPECT_EQ(a.centers[i].x, b.centers[i].x);
    EXPECT_EQ(a.centers[i].y, b.centers[i].y);
  }
  EXPECT_NE(a.centers.front().x, c.centers.front().x);
}

TEST(Rve, AnEnsembleIsTheSingleRunsOfItsSeedsOnAnyThreads) {
  RveSpec spec;
  spec.diameter = 0.04, spec.gap = 0.002, spec.fiber_fraction = 0.68, spec.seed = 7;
  const std::vector<Rve> two_threads = make_rves(spec, 4, 2), one_thread = make_rves(spec, 4, 1);
  ASSERT_EQ(two_threads.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    RveSpec single = spec;
    single.seed = spec.seed + k;
    const Rve alone = make_rve(single);
    for (const auto* rves : {&two_threads, &one_thread}) {
      const Rve& got = (*rves)[k];
      ASSERT_EQ(got.centers.size(), alone.centers.size()) << "realization " << k;
      for (std::size_t i = 0; i < alone.centers.size(); ++i) {
        ASSERT_EQ(got.centers[i].x, alone.centers[i].x);
        ASSERT_EQ(got.centers[i].y, alone.centers[i].y);
      }
    }
    EXPECT_TRUE(valid(two_threads[k], k + 1));
  }
  EXPECT_TRUE(make_rves(spec, 0).empty());
}

TEST(Rve, RefusesWhatCannotBeMadeSayingWhy) {
  const auto message = [](RveSpec spec) {
    try {
      rve_fiber_count(spec);
    } catch (const InvalidInput& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  RveSpec ok;
  ok.diameter = 0.05, ok.gap = 0.0025, ok.fiber_fraction = 0.7;
  EXPECT_EQ(rve_fiber_count(ok), static_cast<std::size_t>(std::lround(0.7 / (kPi * 0.05 * 0.05 / 4))));
  RveSpec s = ok;
  s.diameter = 0;
  EXPECT_NE(message(s).find("diameter must be finite and positive"), std::string::npos) << message(s);
  s.diameter = std::nan("");
  EXPECT_NE(message(s).find("diameter must be finite and positive"), std::string::npos) << message(s);
  s = ok, s.gap = -0.001;
  EXPECT_NE(message(s).find("gap between fibers must be finite and 0 or more"), std::string::npos) << message(s);
  s = ok, s.diameter = 0.3, s.gap = 0.2;
  EXPECT_NE(message(s).find("too wide for the 1 x 1 cell"), std::string::npos) << message(s);
  s = ok, s.fibers = 100;
  EXPECT_NE(message(s).find("not both"), std::string::npos) << message(s);
  s = ok, s.fiber_fraction = 0;
  EXPECT_NE(message(s).find("give a fiber count or a fiber volume fraction"), std::string::npos) << message(s);
  s = ok, s.fiber_fraction = 1.2;
  EXPECT_NE(message(s).find("between 0 and 1"), std::string::npos) << message(s);
  s = ok, s.fiber_fraction = 1e-6;
  EXPECT_NE(message(s).find("less than half a fiber"), std::string::npos) << message(s);
  // g = 0.05 D: the hexagonal arrangement reaches vf 0.9069 / 1.1025 = 0.8226.
  s = ok, s.fiber_fraction = 0.83;
  EXPECT_NE(message(s).find("densest (hexagonal) arrangement reaches vf 0.822"), std::string::npos) << message(s);
  s = ok, s.width = 1e300, s.height = 1e300;
  EXPECT_NE(message(s).find("far too many"), std::string::npos) << message(s);
  s = ok, s.width = -1;
  EXPECT_THROW(rve_fiber_count(s), InvalidInput);
}

}  // namespace
}  // namespace disktune
