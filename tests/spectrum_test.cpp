// SPDX-License-Identifier: GPL-3.0-or-later
// The spectrum: lattices (peaks exactly at the reciprocal lattice, zero elsewhere),
// white noise, a maximal sample's low-frequency gap, and agreement with a direct sum
// written here with std::complex.
#include "disktune/spectrum.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <nlohmann/json.hpp>

#include "disktune/errors.h"
#include "disktune/quality_json.h"
#include "disktune/sampling.h"
#include "lattices.h"
#include "test_util.h"

namespace disktune {
namespace {

/// |sum_j exp(-2 pi i (kx x_j / W + ky y_j / H))|^2 / N, term by term.
double direct_power(const Packing& p, int kx, int ky) {
  const double pi = std::acos(-1.0);
  const Vec2 box = p.frame().extent;
  std::complex<double> f = 0;
  for (DiskId id : p.ids()) {
    const Vec2 c = p.center(id);
    f += std::exp(std::complex<double>(0, -2 * pi * (kx * c.x / box.x + ky * c.y / box.y)));
  }
  return std::norm(f) / static_cast<double>(p.size());
}

Spectrum spectrum(const Packing& p, int window = 0) {
  SpectrumOptions o;
  o.window = window;
  return measure_spectrum(p, o);
}

TEST(Spectrum, HexLatticeHasPeaksExactlyAtTheReciprocalLattice) {
  // 6 x 8 hexagonal lattice in its 6a x 8a(sqrt3/2) box: the reciprocal basis is
  // (1/a, -1/(sqrt3 a)) and (0, 2/(sqrt3 a)), i.e. integer frequencies (6, -4), (0, 8).
  const Packing p = test::hex_lattice(6, 8, 0.1, 0.1);
  const double n = static_cast<double>(p.size());
  const Spectrum s = spectrum(p, 20);
  ASSERT_EQ(s.side(), 39);
  int peaks = 0;
  for (int ky = -19; ky <= 19; ++ky) {
    for (int kx = -19; kx <= 19; ++kx) {
      const bool reciprocal = kx % 6 == 0 && (ky + 4 * (kx / 6)) % 8 == 0;
      if (kx == 0 && ky == 0) {
        EXPECT_EQ(s.at(kx, ky), 0.0);  // DC removed
      } else if (reciprocal) {
        EXPECT_NEAR(s.at(kx, ky), n, 1e-9 * n) << kx << ", " << ky;
        ++peaks;
      } else {
        EXPECT_LT(s.at(kx, ky), 1e-12) << kx << ", " << ky;
      }
    }
  }
  EXPECT_EQ(peaks, 3 * 5 - 1 + 4 * 4);  // kx = 6m: ky = 0 mod 8 for even m, 4 mod 8 for odd
  EXPECT_NEAR(s.peak_power, n, 1e-9 * n);
  // The first ring of peaks, |b2| = 2 / (sqrt3 a), in units of sqrt(N / A) / 2.
  const double a = 0.1, area = 6 * a * 8 * a * std::sqrt(3.0) / 2;
  EXPECT_NEAR(s.peak_frequency, 2 / (std::sqrt(3.0) * a) * 2 * std::sqrt(area / n), 1e-9);
  EXPECT_NEAR(s.peak_frequency, 2.1491, 1e-4);  // the same for every hexagonal lattice
  EXPECT_GT(s.effective_nyquist, 1.9);          // nothing below the first ring
}

TEST(Spectrum, SquareLatticeInARectangleHasPeaksOnTheGrid) {
  const Packing p = test::square_lattice(5, 3, 0.2, 0.2);  // a 1 x 0.6 box
  const double n = static_cast<double>(p.size());
  const Spectrum s = spectrum(p, 12);
  for (int ky = -11; ky <= 11; ++ky) {
    for (int kx = -11; kx <= 11; ++kx) {
      if (kx == 0 && ky == 0) continue;
      const double expected = (kx % 5 == 0 && ky % 3 == 0) ? n : 0;
      EXPECT_NEAR(s.at(kx, ky), expected, 1e-9 * n) << kx << ", " << ky;
    }
  }
}

TEST(Spectrum, WhiteNoiseHasFlatPowerAndNoAnisotropy) {
  const Packing p = test::random_points(3000, 1, 1, 0.01, 5);
  const Spectrum s = spectrum(p);
  ASSERT_GT(s.radial_mean.size(), 40u);
  double mean = 0, db = 0;
  for (const auto& [f, power] : s.radial_mean) mean += power;
  mean /= static_cast<double>(s.radial_mean.size());
  EXPECT_NEAR(mean, 1, 0.05);
  int rings = 0;
  for (const auto& [f, a] : s.anisotropy_db) {
    if (f < 0.5) continue;  // small rings: too few samples for a variance
    db += a;
    ++rings;
  }
  EXPECT_NEAR(db / rings, 0, 0.5);
  EXPECT_LT(s.effective_nyquist, 0.1);  // no low-power region
}

TEST(Spectrum, MaximalSampleHasLowPowerAtLowFrequencies) {
  const PeriodicBox box(1, 1);
  Rng rng(3);
  const Packing p = sample_mps(box, 0.02, rng);
  const Spectrum s = spectrum(p);
  EXPECT_GE(s.radial_mean.back()[0], 2.9);  // the automatic window reaches 3
  for (const auto& [f, power] : s.radial_mean) {
    if (f < 0.5) {
      EXPECT_LT(power, 0.25) << "at " << f;
    }
  }
  EXPECT_GT(s.effective_nyquist, 0.5);  // noisy for one small sample; ~1.0 at 4e4 disks
  EXPECT_GT(s.peak_frequency, 1.5);     // the bright ring
  EXPECT_GT(s.peak_power, 3);
}

TEST(Spectrum, AgreesWithADirectSum) {
  const PeriodicBox box(1, 1);
  Rng rng(11);
  const Packing mps = sample_mps(box, 0.03, rng);
  const Spectrum s = spectrum(mps);
  for (auto [kx, ky] : {std::pair{1, 0},
                        {0, 1},
                        {-3, 7},
                        {17, -2},
                        {s.window - 1, s.window - 1},
                        {1 - s.window, 5},
                        {12, 30}}) {
    EXPECT_NEAR(s.at(kx, ky), direct_power(mps, kx, ky), 1e-9) << kx << ", " << ky;
  }
  // A rectangle with its origin away from 0 (a phase only).
  const Packing rect = test::random_points(700, 2, 0.5, 0.01, 9);
  const Spectrum r = spectrum(rect, 15);
  for (auto [kx, ky] : {std::pair{1, 1}, {-14, 3}, {7, -14}, {0, 9}}) {
    EXPECT_NEAR(r.at(kx, ky), direct_power(rect, kx, ky), 1e-9) << kx << ", " << ky;
  }
}

// Each thread computes whole rows, so one thread or many give the same powers, bit for
// bit, and each agrees with the direct sum.
TEST(Spectrum, OneThreadOrManyGiveTheSamePowers) {
  const PeriodicBox box(1, 1);
  Rng rng(12);
  const Packing mps = sample_mps(box, 0.03, rng);
  SpectrumOptions one, many, all;
  one.threads = 1, many.threads = 3;
  const Spectrum a = measure_spectrum(mps, one), b = measure_spectrum(mps, many), c = measure_spectrum(mps, all);
  EXPECT_EQ(a.power, b.power);
  EXPECT_EQ(a.power, c.power);
  EXPECT_NEAR(a.at(5, -9), direct_power(mps, 5, -9), 1e-9);
}

TEST(Spectrum, AutomaticWindowReachesFrequencyThreeUnlessTooCostly) {
  // Unit box: normalised frequency 3 is |k| = 1.5 sqrt(N).
  EXPECT_EQ(default_spectrum_window(10000, 1, 1), 151);
  EXPECT_EQ(default_spectrum_window(10000, 1, 1, 1e8), 70);  // 1e4 * 70 * 139 <= 1e8
  EXPECT_EQ(default_spectrum_window(2500, 2, 0.5), 151);     // same density, wider box
  const int K = default_spectrum_window(1000000, 1, 1);
  EXPECT_LE(1e6 * K * (2.0 * K - 1), 1e10);
  EXPECT_GT(1e6 * (K + 1) * (2.0 * K + 1), 1e10);
}

TEST(Spectrum, RefusesBadInput) {
  const Packing empty(PeriodicBox(1, 1).frame(), 0.1);
  EXPECT_THROW(measure_spectrum(empty), InvalidInput);
  const Packing p = test::random_points(10, 1, 1, 0.1, 1);
  SpectrumOptions o;
  o.window = 1;
  EXPECT_THROW(measure_spectrum(p, o), InvalidInput);
  o.window = kMaxSpectrumWindow + 1;  // its powers alone would take gigabytes
  EXPECT_NE(test::message_of([&] { measure_spectrum(p, o); }).find("too large"), std::string::npos);
  Frame open;
  open.periodic = false;
  Packing q(open, 0.1);
  q.insert({0.5, 0.5}, 0.1);
  EXPECT_THROW(measure_spectrum(q), InvalidInput);
}

TEST(Spectrum, JsonHasTheSpectrumKeys) {
  const Packing p = test::hex_lattice(6, 8, 0.1, 0.1);
  const Spectrum s = spectrum(p, 20);
  const QualityReport q = measure_quality(p, periodic_delaunay(p), 0.1);
  const nlohmann::json j = nlohmann::json::parse(quality_json(q, &s));
  const nlohmann::json& js = j.at("spectrum");
  for (const char* key : {"radial_mean", "anisotropy_db", "peak_power", "effective_nyquist"}) {
    EXPECT_TRUE(js.contains(key)) << key;
  }
  EXPECT_EQ(js.at("radial_mean").size(), s.radial_mean.size());
  EXPECT_EQ(js.at("radial_mean")[0].size(), 2u);
  EXPECT_FALSE(nlohmann::json::parse(quality_json(q)).contains("spectrum"));
}

}  // namespace
}  // namespace disktune
