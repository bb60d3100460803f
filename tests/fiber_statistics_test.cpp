// SPDX-License-Identifier: GPL-3.0-or-later
// Fiber statistics (fiber_statistics.h) against what the test derives itself: the
// hexagonal lattice's exact values, a brute-force count over all pairs of an RVE (the
// minimum image), and complete spatial randomness's analytic values for Poisson points.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <random>
#include <vector>

#include "disktune/errors.h"
#include "disktune/fiber_statistics.h"
#include "disktune/rve.h"

namespace disktune {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(FiberStatistics, HexagonalLatticeHasItsExactValues) {
  const int side = 20;
  const double a = 1.0 / side, row = a * std::sqrt(3.0) / 2, d = 0.045;  // a / d = 1.111, inside a ring
  const PeriodicBox cell(1, side * row);
  std::vector<Vec2> centers;
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) centers.push_back({(i + 0.5 * (j % 2)) * a, j * row});
  const FiberStatistics s = fiber_statistics(cell, centers, d);
  for (int k = 0; k < 6; ++k) {
    EXPECT_NEAR(s.nearest[k].mean, a / d, 1e-9) << "k " << k + 1;
    EXPECT_NEAR(s.nearest[k].stddev, 0, 1e-9) << "k " << k + 1;
  }
  EXPECT_NEAR(s.psi6_global, 1, 1e-9);
  EXPECT_NEAR(s.psi6_local_mean, 1, 1e-9);
  EXPECT_DOUBLE_EQ(s.psi6_hexagonal_share, 1);
  EXPECT_NEAR(s.voronoi_area_cv, 0, 1e-6);
  // Six neighbours at a, six more at sqrt(3) a: K steps from 0 to 6 A / (N - 1), then 12.
  const double n = centers.size(), step = cell.area() / (n - 1) / (d * d);
  for (std::size_t i = 0; i < s.r.size(); ++i) {
    const double want = s.r[i] < a / d ? 0 : s.r[i] < std::sqrt(3.0) * a / d ? 6 * step : s.r[i] < 2 * a / d ? 12 * step : -1;
    if (want >= 0) {
      EXPECT_NEAR(s.ripley_k[i], want, 1e-9 * step) << "r " << s.r[i];
    }
  }
  // The bonds point at 0, 60 and 120 degrees (any of six tied bonds is the nearest, to
  // rounding): only the bins on either side of those angles (and of 180) are used.
  for (std::size_t bin = 0; bin < 18; ++bin) {
    if (bin % 6 != 0 && bin % 6 != 5) {
      EXPECT_EQ(s.nearest_orientation.counts[bin], 0u) << "bin " << bin;
    }
  }
}

TEST(FiberStatistics, AgreesWithAllPairsOnAnRve) {
  RveSpec spec;
  spec.diameter = 0.04, spec.gap = 0.004, spec.fiber_fraction = 0.6, spec.seed = 5;
  const Rve rve = make_rve(spec);
  const FiberStatistics s = fiber_statistics(rve.cell, rve.centers, rve.diameter);
  const std::size_t n = rve.centers.size();
  ASSERT_GT(n, 300u);
  // All pairs, minimum image (the cell is 25 D wide: the six nearest and 5 D lie within half of it).
  std::vector<std::vector<double>> dist(n);
  std::complex<double> psi6 = 0;
  std::vector<double> within(s.r.size(), 0);
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<std::pair<double, double>> all;
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i) continue;
      double dx = rve.centers[j].x - rve.centers[i].x, dy = rve.centers[j].y - rve.centers[i].y;
      dx -= std::round(dx), dy -= std::round(dy);
      const double dd = std::hypot(dx, dy) / rve.diameter;
      all.push_back({dd, std::atan2(dy, dx)});
      for (std::size_t k = 0; k < s.r.size(); ++k) within[k] += dd <= s.r[k] * (1 + 1e-9);  // contacts count
    }
    std::sort(all.begin(), all.end());
    std::complex<double> local = 0;
    for (int k = 0; k < 6; ++k) dist[k].push_back(all[k].first), local += std::polar(1.0, 6 * all[k].second);
    psi6 += local / 6.0;
  }
  for (int k = 0; k < 6; ++k) {
    double mean = 0;
    for (const double v : dist[k]) mean += v;
    EXPECT_NEAR(s.nearest[k].mean, mean / n, 1e-12) << "k " << k + 1;
    EXPECT_NEAR(s.nearest[k].min, *std::min_element(dist[k].begin(), dist[k].end()), 1e-12);
  }
  EXPECT_NEAR(s.psi6_global, std::abs(psi6) / n, 1e-12);
  for (std::size_t k = 0; k < s.r.size(); ++k) {
    const double k_want = within[k] / (double(n) * double(n - 1)) / (rve.diameter * rve.diameter);
    EXPECT_NEAR(s.ripley_k[k], k_want, 1e-9 * (1 + k_want)) << "r " << s.r[k];
  }
  // No fiber closer than D + g: K and g vanish below 1.1 D.
  for (std::size_t k = 0; k < s.r.size() && s.r[k] < 1.1 - 1e-9; ++k) EXPECT_EQ(s.pair_correlation[k], 0);
  EXPECT_NEAR(s.fiber_fraction, n * kPi * 0.04 * 0.04 / 4, 1e-12);
}

TEST(FiberStatistics, PoissonPointsMatchCompleteSpatialRandomness) {
  for (const unsigned seed : {1u, 2u, 3u}) {
    std::mt19937_64 gen(seed);
    std::uniform_real_distribution<double> u(0, 1);
    const std::size_t n = 4000;
    std::vector<Vec2> points;
    for (std::size_t i = 0; i < n; ++i) points.push_back({u(gen), u(gen)});
    const double d = 1 / std::sqrt(double(n));  // a unit near the spacing
    const FiberStatistics s = fiber_statistics(PeriodicBox(1, 1), points, d);
    for (int k = 1; k <= 6; ++k)
      EXPECT_NEAR(s.nearest[k - 1].mean * d / poisson_nearest_mean(k, double(n)), 1, 0.04) << "k " << k << " seed " << seed;
    for (std::size_t i = 0; i < s.r.size(); ++i) {
      if (s.r[i] < 1.5) continue;  // few pairs: noisy
      EXPECT_NEAR(s.ripley_k[i] / (kPi * s.r[i] * s.r[i]), 1, 0.06) << "r " << s.r[i] << " seed " << seed;
      EXPECT_NEAR(s.ripley_l[i] / s.r[i], 1, 0.03);
    }
    EXPECT_NEAR(s.voronoi_area_cv, kPoissonVoronoiAreaCv, 0.03) << "seed " << seed;
    EXPECT_LT(s.psi6_global, 0.05);
    // The local fraction's spread against Campbell's theorem: 961 and 225 windows.
    for (std::size_t w = 0; w < 2; ++w) {
      const double side = s.local_fraction[w].side * d;
      EXPECT_NEAR(s.local_fraction[w].fraction.stddev / poisson_local_fraction_stddev(side, d, double(n)), 1, 0.12)
          << "windows " << s.local_fraction[w].side << " D, seed " << seed;
    }
  }
}

TEST(FiberStatistics, LocalFractionReferences) {
  // CSR: windows much wider than a fiber hold about intensity * side^2 fibers, Poisson
  // distributed, so the fraction's spread tends to vf / sqrt(intensity side^2) (here the
  // border fibers, cut by the window, change it by about D / side).
  const double d = 1, intensity = 0.8 / (kPi / 4);  // vf 0.8 of overlapping fibers
  for (const double side : {40.0, 80.0}) {
    const double expected = 0.8 / std::sqrt(intensity * side * side);
    EXPECT_NEAR(poisson_local_fraction_stddev(side, d, intensity) / expected, 1, 1.5 * d / side) << "side " << side;
  }
  // The lattice against counting the points of a fine grid that lie in a fiber (the
  // nearest lattice points by brute force): two windows 3 D wide.
  const double spacing = 1.1, lattice_intensity = 2 / (std::sqrt(3.0) * spacing * spacing), side = 3;
  const auto lattice = hexagonal_local_fraction(side, d, lattice_intensity, 2);
  ASSERT_EQ(lattice.windows, 4u);
  std::vector<double> counted;
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i < 2; ++i) {
      const int grid = 600;
      std::size_t inside = 0;
      for (int gy = 0; gy < grid; ++gy) {
        for (int gx = 0; gx < grid; ++gx) {
          const double x = (i + (gx + 0.5) / grid) * side, y = (j + (gy + 0.5) / grid) * side;
          bool in = false;
          for (int k = -2; k <= 12 && !in; ++k) {
            for (int m = -2; m <= 12 && !in; ++m) {
              const double cx = m * spacing + ((k % 2 != 0) ? spacing / 2 : 0), cy = k * spacing * std::sqrt(3.0) / 2;
              in = (x - cx) * (x - cx) + (y - cy) * (y - cy) <= 0.25;
            }
          }
          inside += in;
        }
      }
      counted.push_back(double(inside) / (grid * grid));
    }
  }
  EXPECT_NEAR(lattice.fraction.min, *std::min_element(counted.begin(), counted.end()), 0.003);
  EXPECT_NEAR(lattice.fraction.max, *std::max_element(counted.begin(), counted.end()), 0.003);
  // Wide windows average the lattice's fraction, pi D^2 / 4 times its intensity.
  const auto wide = hexagonal_local_fraction(40, d, lattice_intensity, 4);
  EXPECT_NEAR(wide.fraction.mean, kPi / 4 * lattice_intensity, 0.01);
  EXPECT_LT(wide.fraction.stddev, 0.01);
}

// The fraction of each window `side` wide (as many as fit the unit cell, laid from the
// origin) inside some fiber, by counting the points of a 1000 x 1000 grid.
std::vector<double> counted_fractions(const Rve& rve, double side) {
  const int grid = 1000, buckets = 20;  // buckets 0.05 wide: wider than any fiber here
  std::vector<std::vector<std::size_t>> bucket(buckets * buckets);
  for (std::size_t k = 0; k < rve.centers.size(); ++k) {
    const Vec2 c = rve.centers[k];
    bucket[int(c.y * buckets) * buckets + int(c.x * buckets)].push_back(k);
  }
  const auto per_side = static_cast<int>(std::floor(1 / side * (1 + 1e-12)));
  std::vector<double> inside(per_side * per_side, 0), points(per_side * per_side, 0);
  for (int j = 0; j < grid; ++j) {
    for (int i = 0; i < grid; ++i) {
      const double x = (i + 0.5) / grid, y = (j + 0.5) / grid;
      const int wx = static_cast<int>(x / side), wy = static_cast<int>(y / side);
      if (wx >= per_side || wy >= per_side) continue;
      bool in = false;
      for (int by = -1; by <= 1 && !in; ++by) {
        for (int bx = -1; bx <= 1 && !in; ++bx) {
          for (const std::size_t k : bucket[((int(y * buckets) + by + buckets) % buckets) * buckets +
                                            (int(x * buckets) + bx + buckets) % buckets]) {
            double dx = x - rve.centers[k].x, dy = y - rve.centers[k].y;
            dx -= std::round(dx), dy -= std::round(dy);
            const double r = rve.diameters[k] / 2;
            in = in || dx * dx + dy * dy < r * r;
          }
        }
      }
      inside[wy * per_side + wx] += in;
      points[wy * per_side + wx] += 1;
    }
  }
  for (std::size_t w = 0; w < inside.size(); ++w) inside[w] /= points[w];
  return inside;
}

// The 4 D windows' spread against counting points.
void expect_counted(const FiberStatistics& s, const Rve& rve) {
  const std::vector<double> counted = counted_fractions(rve, s.local_fraction[1].side * s.diameter);
  ASSERT_EQ(counted.size(), s.local_fraction[1].windows);
  double mean = 0, var = 0;
  const auto n = static_cast<double>(counted.size());
  for (const double c : counted) mean += c / n;
  for (const double c : counted) var += (c - mean) * (c - mean) / n;
  EXPECT_NEAR(s.local_fraction[1].fraction.stddev, std::sqrt(var), 2e-3);
  EXPECT_NEAR(s.local_fraction[1].fraction.min, *std::min_element(counted.begin(), counted.end()), 3e-3);
  EXPECT_NEAR(s.local_fraction[1].fraction.max, *std::max_element(counted.begin(), counted.end()), 3e-3);
}

TEST(FiberStatistics, LocalFractionAgreesWithCountingPoints) {
  RveSpec spec;
  spec.diameter = 0.05, spec.gap = 0.0025, spec.fiber_fraction = 0.65, spec.seed = 3;
  const Rve rve = make_rve(spec);
  const FiberStatistics s = fiber_statistics(rve.cell, rve.centers, rve.diameter);
  // Windows 2, 4, 8 and 16 D: 10, 5, 2 and 1 a side (the last two leave a strip).
  ASSERT_EQ(s.local_fraction.size(), 4u);
  EXPECT_EQ(s.local_fraction[0].windows, 100u);
  EXPECT_EQ(s.local_fraction[1].windows, 25u);
  EXPECT_EQ(s.local_fraction[3].windows, 1u);
  // 10 x 10 and 5 x 5 windows tile the cell: the fiber area is all counted, once.
  EXPECT_NEAR(s.local_fraction[0].fraction.mean, s.fiber_fraction, 1e-12);
  EXPECT_NEAR(s.local_fraction[1].fraction.mean, s.fiber_fraction, 1e-12);
  expect_counted(s, rve);
}

TEST(FiberStatistics, UnequalFibersCountTheirOwnAreas) {
  RveSpec spec;
  spec.diameter = 0.05, spec.gap = 0.0025, spec.diameter_cv = 0.1, spec.fiber_fraction = 0.65, spec.seed = 5;
  const Rve rve = make_rve(spec);
  const FiberStatistics s = fiber_statistics(rve.cell, rve.centers, rve.diameters);
  double area = 0, sum = 0, squares = 0, least = INFINITY, most = 0;
  for (const double d : rve.diameters) {
    area += kPi * d * d / 4, sum += d, squares += d * d, least = std::min(least, d), most = std::max(most, d);
  }
  const double n = static_cast<double>(rve.diameters.size());
  EXPECT_NEAR(s.fiber_fraction, area, 1e-12);  // the cell is 1 x 1
  EXPECT_NEAR(s.diameter, sum / n, 1e-15);
  EXPECT_NEAR(s.diameter_rms, std::sqrt(squares / n), 1e-15);
  EXPECT_EQ(s.diameters.min, least);
  EXPECT_EQ(s.diameters.max, most);
  // Nearest neighbours in units of the mean diameter: no pair closer than the gap allows.
  EXPECT_GE(s.nearest[0].min, (2 * least / 2 + spec.gap) / s.diameter * (1 - 1e-12));
  expect_counted(s, rve);
  // Equal fibers through either call: the same figures.
  const FiberStatistics one = fiber_statistics(rve.cell, rve.centers, 0.05);
  const FiberStatistics each = fiber_statistics(rve.cell, rve.centers, std::vector<double>(rve.centers.size(), 0.05));
  EXPECT_EQ(one.fiber_fraction, each.fiber_fraction);
  EXPECT_EQ(one.diameter, 0.05);
  EXPECT_EQ(one.local_fraction[1].fraction.stddev, each.local_fraction[1].fraction.stddev);
  EXPECT_THROW(fiber_statistics(rve.cell, rve.centers, std::vector<double>(3, 0.05)), InvalidInput);
}

TEST(FiberStatistics, RefusesTooFewAndCoincidingFibers) {
  std::vector<Vec2> few(6, Vec2{0.1, 0.1});
  EXPECT_THROW(fiber_statistics(PeriodicBox(1, 1), few, 0.01), InvalidInput);
  std::vector<Vec2> twice;
  for (int i = 0; i < 10; ++i) twice.push_back({0.1 * i, 0.05 * i});
  twice.push_back(twice[3]);
  EXPECT_THROW(fiber_statistics(PeriodicBox(1, 1), twice, 0.01), InvalidInput);
  twice.pop_back();
  EXPECT_THROW(fiber_statistics(PeriodicBox(1, 1), twice, 0), InvalidInput);
}

}  // namespace
}  // namespace disktune
