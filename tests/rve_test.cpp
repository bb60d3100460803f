// SPDX-License-Identifier: GPL-3.0-or-later
// Fiber RVEs (rve.h): the count and the fiber fraction the test computes itself, the
// arrangement checked by the independent torus oracle at center distance D + g
// (conflict-free: no two fibers closer than D + g; maximal: no room for one more
// fiber's center), and its disorder by a bond-orientational order computed here by brute
// force. Unequal fibers: the additive rule checked here over all pairs, maximality for
// the smallest fiber by the oracle with each fiber's reach as its radius.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <map>
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

// Unequal fibers: every pair at least (d_i + d_j) / 2 + g apart (all pairs, nearest
// image, computed here), and no room for a fiber of the smallest diameter: the oracle's
// maximality with disk i of radius (d_i + d_min) / 2 + g, the distance a new smallest
// fiber's center must keep from center i.
::testing::AssertionResult valid_unequal(const Rve& rve, std::uint64_t seed) {
  const double w = rve.cell.width(), h = rve.cell.height(), g = rve.gap;
  if (rve.diameters.size() != rve.centers.size()) return ::testing::AssertionFailure() << "one diameter per fiber";
  const double smallest = *std::min_element(rve.diameters.begin(), rve.diameters.end());
  for (std::size_t i = 0; i < rve.centers.size(); ++i) {
    const Vec2 a = rve.centers[i];
    if (!(a.x >= 0 && a.x < w && a.y >= 0 && a.y < h))
      return ::testing::AssertionFailure() << "center (" << a.x << ", " << a.y << ") outside the cell";
    for (std::size_t j = i + 1; j < rve.centers.size(); ++j) {
      double dx = rve.centers[j].x - a.x, dy = rve.centers[j].y - a.y;
      dx -= w * std::round(dx / w), dy -= h * std::round(dy / h);
      const double need = (rve.diameters[i] + rve.diameters[j]) / 2 + g;
      if (std::hypot(dx, dy) < need) {
        return ::testing::AssertionFailure() << "fibers " << i << " and " << j << " are " << std::hypot(dx, dy)
                                             << " apart, under " << need;
      }
    }
  }
  std::vector<double> reach;
  for (const double d : rve.diameters) reach.push_back((d + smallest) / 2 + g);
  const auto rep = oracle::check_maximal({w, h}, reach, points_of(rve), 1e-9, 20000, seed);
  if (rep.maximal()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << rep.summary();
}

TEST(Rve, UnequalFibersKeepTheirGapsAndLeaveNoRoomForTheSmallest) {
  struct Unequal {
    double width, diameter, gap, cv;
    std::size_t fibers;
    double vf;
  };
  const Unequal cases[] = {
      {1, 0.05, 0.0025, 0.1, 0, 0.70},  // the case with a 10 % spread
      {1, 0.05, 0, 0.05, 0, 0.67},      // the paper's vf, fibers may touch
      {1, 0.05, 0.0025, 0.2, 0, 0.65},  // the widest spread allowed
      {1, 0.04, 0.002, 0.1, 450, 0},    // an exact count (vf about 0.57)
  };
  for (const Unequal& c : cases) {
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
      RveSpec spec;
      spec.width = spec.height = c.width, spec.diameter = c.diameter, spec.gap = c.gap, spec.diameter_cv = c.cv;
      spec.fibers = c.fibers, spec.fiber_fraction = c.vf, spec.seed = seed;
      SCOPED_TRACE(::testing::Message() << "D " << c.diameter << ", g " << c.gap << ", cv " << c.cv << ", seed " << seed);
      const Rve rve = make_rve(spec);
      ASSERT_EQ(rve.diameters.size(), rve.centers.size());
      double area = 0, largest = 0;
      for (const double d : rve.diameters) {
        EXPECT_GE(d, c.diameter * (1 - 2 * c.cv) * (1 - 1e-12));
        EXPECT_LE(d, c.diameter * (1 + 2 * c.cv) * (1 + 1e-12));
        area += kPi * d * d / 4, largest = std::max(largest, d);
      }
      const double cell_area = c.width * c.width;
      EXPECT_NEAR(rve.fiber_fraction, area / cell_area, 1e-12);
      if (c.fibers) {
        EXPECT_EQ(rve.centers.size(), c.fibers);
      } else {  // the count whose areas come nearest: within half the largest fiber
        EXPECT_LE(std::abs(rve.fiber_fraction - c.vf), 0.5 * kPi * largest * largest / 4 / cell_area);
      }
      EXPECT_TRUE(valid_unequal(rve, seed));
    }
  }
}

TEST(Rve, UnequalDiametersFollowTheirLaw) {
  // 10^4 draws of the normal law truncated at two standard deviations: mean D, standard
  // deviation 0.8796 cv D (the truncated variance 1 - 4 phi(2) / (2 Phi(2) - 1) = 0.7737
  // computed here from the closed form), both ends reached.
  RveSpec spec;
  spec.width = spec.height = 1.2, spec.diameter = 0.01, spec.gap = 0.0005, spec.diameter_cv = 0.1;
  spec.fibers = 10000;
  const Rve rve = make_rve(spec);
  double sum = 0, sum_square = 0, least = 1, most = 0;
  for (const double d : rve.diameters) sum += d, sum_square += d * d, least = std::min(least, d), most = std::max(most, d);
  const double n = static_cast<double>(rve.diameters.size()), mean = sum / n;
  const double sd = std::sqrt(sum_square / n - mean * mean);
  const double phi2 = std::exp(-2.0) / std::sqrt(2 * kPi), mass = std::erf(2 / std::sqrt(2.0));
  const double expected_sd = 0.1 * 0.01 * std::sqrt(1 - 4 * phi2 / mass);
  EXPECT_NEAR(mean, 0.01, 4 * expected_sd / std::sqrt(n));
  EXPECT_NEAR(sd, expected_sd, 0.03 * expected_sd);
  EXPECT_LT(least, 0.01 * (1 - 0.19));
  EXPECT_GT(most, 0.01 * (1 + 0.19));
  EXPECT_NEAR(rve.diameter, mean, 1e-15);
  EXPECT_TRUE(valid_unequal(rve, 1));

  // From a list: only its values, each about equally often (vf about 0.65).
  spec.width = spec.height = 0.6;
  spec.diameter_cv = 0, spec.diameter = 0, spec.diameter_list = {0.009, 0.01, 0.0115};
  spec.fibers = 3000;
  const Rve listed = make_rve(spec);
  std::map<double, int> seen;
  for (const double d : listed.diameters) ++seen[d];
  ASSERT_EQ(seen.size(), 3u);
  for (const auto& [d, k] : seen) EXPECT_NEAR(k, 1000, 4 * std::sqrt(1000 * 2.0 / 3)) << "diameter " << d;
  EXPECT_TRUE(valid_unequal(listed, 2));
}

TEST(Rve, TheUnequalChecksSeeOverlapsAndRoom) {
  // A test that cannot fail proves nothing: the checks above must catch a fiber removed
  // (room for the smallest where it was) and two fibers pushed together.
  RveSpec spec;
  spec.diameter = 0.05, spec.gap = 0.0025, spec.diameter_cv = 0.1, spec.fiber_fraction = 0.7, spec.seed = 3;
  const Rve rve = make_rve(spec);
  ASSERT_TRUE(valid_unequal(rve, 1));
  Rve fewer = rve;
  const auto smallest = std::min_element(fewer.diameters.begin(), fewer.diameters.end()) - fewer.diameters.begin();
  fewer.centers.erase(fewer.centers.begin() + (smallest == 0 ? 1 : 0));  // keeps the smallest diameter
  fewer.diameters.erase(fewer.diameters.begin() + (smallest == 0 ? 1 : 0));
  EXPECT_FALSE(valid_unequal(fewer, 1));
  // Fiber 0 moved to touch its nearest neighbour, minus a millionth of a diameter.
  Rve closer = rve;
  std::size_t nearest = 1;
  double best = INFINITY;
  const double w = rve.cell.width();
  Vec2 toward{0, 0};
  for (std::size_t j = 1; j < rve.centers.size(); ++j) {
    double dx = rve.centers[j].x - rve.centers[0].x, dy = rve.centers[j].y - rve.centers[0].y;
    dx -= w * std::round(dx / w), dy -= w * std::round(dy / w);
    if (std::hypot(dx, dy) < best) best = std::hypot(dx, dy), nearest = j, toward = {dx, dy};
  }
  const double need = (rve.diameters[0] + rve.diameters[nearest]) / 2 + rve.gap - 1e-6 * spec.diameter;
  const Vec2 moved = rve.centers[0] + toward * (1 - need / best);
  closer.centers[0] = {moved.x - w * std::floor(moved.x / w), moved.y - w * std::floor(moved.y / w)};
  EXPECT_FALSE(valid_unequal(closer, 1));
}

TEST(Rve, UnequalFibersSameSeedSameArrangement) {
  RveSpec spec;
  spec.diameter = 0.05, spec.gap = 0.0025, spec.diameter_cv = 0.08, spec.fiber_fraction = 0.65, spec.seed = 4;
  const Rve a = make_rve(spec), b = make_rve(spec);
  ASSERT_EQ(a.centers.size(), b.centers.size());
  for (std::size_t i = 0; i < a.centers.size(); ++i) {
    EXPECT_EQ(a.centers[i].x, b.centers[i].x);
    EXPECT_EQ(a.centers[i].y, b.centers[i].y);
    EXPECT_EQ(a.diameters[i], b.diameters[i]);
  }
  // An ensemble's realization k is the single run of seed + k, its own count and all.
  const std::vector<Rve> ensemble = make_rves(spec, 2, 2);
  for (std::size_t k = 0; k < 2; ++k) {
    RveSpec single = spec;
    single.seed = spec.seed + k;
    const Rve alone = make_rve(single);
    ASSERT_EQ(ensemble[k].centers.size(), alone.centers.size());
    for (std::size_t i = 0; i < alone.centers.size(); ++i) {
      ASSERT_EQ(ensemble[k].centers[i].x, alone.centers[i].x);
      ASSERT_EQ(ensemble[k].diameters[i], alone.diameters[i]);
    }
  }
  // Equal fibers keep their one diameter per fiber too.
  spec.diameter_cv = 0;
  const Rve equal = make_rve(spec);
  ASSERT_EQ(equal.diameters.size(), equal.centers.size());
  for (const double d : equal.diameters) EXPECT_EQ(d, 0.05);
}

TEST(Rve, RefusesUnequalFibersItCannotMakeSayingWhy) {
  const auto message = [](RveSpec spec, bool make) {
    try {
      if (make) {
        make_rve(spec);
      } else {
        rve_fiber_count(spec);
      }
    } catch (const InvalidInput& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  RveSpec ok;
  ok.diameter = 0.05, ok.gap = 0.0025, ok.fiber_fraction = 0.7, ok.diameter_cv = 0.1;
  // The count of the mean fiber area: E[d^2] = D^2 (1 + cv^2 0.7737).
  const double mean_area = kPi * 0.05 * 0.05 / 4 * (1 + 0.01 * 0.77374);
  EXPECT_EQ(rve_fiber_count(ok), static_cast<std::size_t>(std::lround(0.7 / mean_area)));
  RveSpec s = ok;
  for (const double cv : {-0.01, 0.21, std::nan("")}) {
    s.diameter_cv = cv;
    EXPECT_NE(message(s, false).find("coefficient of variation must lie between 0 and 0.2"), std::string::npos)
        << message(s, false);
  }
  s = ok, s.diameter_list = {0.05, 0.04};
  EXPECT_NE(message(s, false).find("not both"), std::string::npos) << message(s, false);
  s = ok, s.diameter_cv = 0, s.diameter_list = {0.05, -0.04};
  EXPECT_NE(message(s, false).find("every diameter in the list must be finite and positive"), std::string::npos);
  // The largest fiber, not the mean one, must fit the cell.
  s = ok, s.width = s.height = 0.13, s.diameter_cv = 0.2, s.fiber_fraction = 0, s.fibers = 2;
  EXPECT_NE(message(s, false).find("fibers of diameter 0.07 with gap 0.0025 are too wide"), std::string::npos)
      << message(s, false);
  // Far sparser than any maximal arrangement of them.
  s = ok, s.fiber_fraction = 0.2;
  EXPECT_NE(message(s, true).find("ask for a higher fiber fraction"), std::string::npos) << message(s, true);
}

}  // namespace
}  // namespace disktune
