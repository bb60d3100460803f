// SPDX-License-Identifier: GPL-3.0-or-later
// Quality measures: lattices with known answers, maximal samples with known bounds, and
// agreement with a brute-force triangulation computed here.
#include "disktune/quality.h"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "brute_delaunay.h"
#include "disktune/errors.h"
#include "disktune/quality_json.h"
#include "disktune/sampling.h"
#include "lattices.h"

namespace disktune {
namespace {

const double kSqrt3 = std::sqrt(3.0);

QualityReport measure(const Packing& p, double r) {
  return measure_quality(p, periodic_delaunay(p), r);
}

std::size_t total(const Histogram& h) {
  std::size_t n = h.overflow;
  for (std::size_t c : h.counts) n += c;
  return n;
}

TEST(Quality, HexLatticeAtSpacingR) {
  const double a = 0.1;
  const Packing p = test::hex_lattice(10, 12, a, a);
  const QualityReport q = measure(p, a);
  const std::size_t n = p.size();
  EXPECT_EQ(q.count, n);
  EXPECT_EQ(q.triangle_count, 2 * n);
  EXPECT_EQ(q.edge_count, 3 * n);
  EXPECT_TRUE(q.maximal);
  EXPECT_TRUE(q.conflict_free);
  EXPECT_NEAR(q.relative_radius, 1.0, 1e-12);  // the hex lattice is r_max-spaced
  EXPECT_NEAR(q.min_distance_over_r, 1.0, 1e-12);
  EXPECT_NEAR(q.max_coverage_over_r, 1 / kSqrt3, 1e-12);
  EXPECT_NEAR(q.angles.min, 60, 1e-9);
  EXPECT_NEAR(q.angles.max, 60, 1e-9);
  EXPECT_NEAR(q.angles.mean_abs_dev_60, 0, 1e-9);
  EXPECT_EQ(q.angles.fraction_50_70, 1.0);
  EXPECT_EQ(q.angles.fraction_obtuse_triangles, 0.0);
  EXPECT_EQ(q.angles.histogram.counts[60], 6 * n);
  EXPECT_NEAR(q.edges.min_over_r, 1, 1e-12);
  EXPECT_NEAR(q.edges.max_over_r, 1, 1e-12);
  EXPECT_EQ(q.edges.histogram.counts[100], 3 * n);
  EXPECT_NEAR(q.local_beta.min, 1 / kSqrt3, 1e-12);
  EXPECT_NEAR(q.local_beta.max, 1 / kSqrt3, 1e-12);
  EXPECT_NEAR(q.local_beta.mean, 1 / kSqrt3, 1e-12);
  EXPECT_EQ(q.local_beta.histogram.counts[57], n);
  EXPECT_NEAR(q.voronoi.aspect_ratio.min, 2 / kSqrt3, 1e-12);
  EXPECT_NEAR(q.voronoi.aspect_ratio.max, 2 / kSqrt3, 1e-12);
  EXPECT_NEAR(q.voronoi.cell_area.mean, q.width * q.height / n, 1e-15);
  EXPECT_NEAR(q.voronoi.cell_area.min, a * a * kSqrt3 / 2, 1e-15);
  EXPECT_NEAR(q.voronoi.cell_area_cv, 0, 1e-9);
}

TEST(Quality, HexLatticeAtSpacingSqrt3RIsJustMaximal) {
  // The sparsest maximal state (ejection's limit): every Voronoi vertex exactly r away.
  const double a = 0.1, r = a / kSqrt3;
  const QualityReport q = measure(test::hex_lattice(10, 12, a, r), r);
  EXPECT_TRUE(q.maximal);
  EXPECT_TRUE(q.conflict_free);
  EXPECT_NEAR(q.max_coverage_over_r, 1, 1e-12);
  EXPECT_NEAR(q.min_distance_over_r, kSqrt3, 1e-12);
  EXPECT_NEAR(q.local_beta.max, 1 / kSqrt3, 1e-12);
}

TEST(Quality, SquareLatticeHasRightIsoscelesTriangles) {
  const double a = 0.25;
  const Packing p = test::square_lattice(8, 6, a, a);
  const QualityReport q = measure(p, a);
  const std::size_t n = p.size();
  EXPECT_TRUE(q.maximal);
  EXPECT_TRUE(q.conflict_free);
  EXPECT_NEAR(q.angles.min, 45, 1e-9);
  EXPECT_NEAR(q.angles.max, 90, 1e-9);
  EXPECT_EQ(q.angles.histogram.counts[45], 4 * n);
  EXPECT_EQ(q.angles.histogram.counts[90], 2 * n);
  EXPECT_EQ(q.angles.fraction_obtuse_triangles, 0.0);  // right angles are not obtuse
  EXPECT_EQ(q.angles.fraction_50_70, 0.0);
  EXPECT_NEAR(q.angles.mean_abs_dev_60, 20, 1e-9);
  EXPECT_NEAR(q.edges.min_over_r, 1, 1e-12);
  EXPECT_NEAR(q.edges.max_over_r, std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(q.max_coverage_over_r, 1 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(q.local_beta.min, 1 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(q.local_beta.max, 1 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(q.voronoi.cell_area.min, a * a, 1e-15);
  EXPECT_NEAR(q.voronoi.cell_area.max, a * a, 1e-15);
}

TEST(Quality, HexLatticeWithOnePointRemoved) {
  // The hole's center is one spacing from its six neighbours: coverage exactly r, and
  // those six cells reach it (beta = 1).
  const double a = 0.1;
  Packing p = test::hex_lattice(10, 12, a, a);
  p.remove(45);
  const QualityReport q = measure(p, a);
  EXPECT_EQ(q.count, p.size());
  EXPECT_EQ(q.triangle_count, 2 * p.size());
  EXPECT_TRUE(q.maximal);
  EXPECT_TRUE(q.conflict_free);
  EXPECT_NEAR(q.max_coverage_over_r, 1, 1e-12);
  EXPECT_NEAR(q.local_beta.max, 1, 1e-12);
  EXPECT_NEAR(q.local_beta.min, 1 / kSqrt3, 1e-12);
  EXPECT_EQ(q.local_beta.histogram.counts[100], 6u);
  EXPECT_NEAR(q.voronoi.cell_area.mean, q.width * q.height / p.size(), 1e-15);
  // With a smaller radius the hole is a void.
  Packing small = test::hex_lattice(10, 12, a, 0.9 * a);
  small.remove(45);
  EXPECT_FALSE(measure(small, 0.9 * a).maximal);
  EXPECT_THROW(measure(small, a), InvalidInput);  // not the disks' radius
}

TEST(Quality, ConflictsAreReported) {
  const double a = 0.1;
  const QualityReport q = measure(test::hex_lattice(10, 12, a, 1.1 * a), 1.1 * a);
  EXPECT_FALSE(q.conflict_free);
  EXPECT_NEAR(q.min_distance_over_r, 1 / 1.1, 1e-12);
}

TEST(Quality, MaximalSamplesMeetTheKnownBounds) {
  for (const auto& [W, H, r] : {std::tuple{1.0, 1.0, 0.02}, {1.3, 0.7, 0.03}}) {
    const PeriodicBox box(W, H);
    Rng rng(3);
    const Packing p = sample_mps(box, r, rng);
    const QualityReport q = measure(p, r);
    EXPECT_TRUE(q.maximal);
    EXPECT_TRUE(q.conflict_free);
    EXPECT_GE(q.min_distance_over_r, 1 - 1e-9);
    EXPECT_LE(q.max_coverage_over_r, 1 + 1e-9);
    EXPECT_GE(q.angles.min, 30 - 1e-6);
    EXPECT_LE(q.angles.max, 120 + 1e-6);
    EXPECT_LT(q.edges.max_over_r, 2 + 1e-9);
    EXPECT_LE(q.local_beta.max, 1 + 1e-9);
    EXPECT_EQ(total(q.angles.histogram), 3 * q.triangle_count);
    EXPECT_EQ(total(q.edges.histogram), q.edge_count);
    EXPECT_EQ(total(q.local_beta.histogram), q.count);
    EXPECT_NEAR(q.voronoi.cell_area.mean * q.count, W * H, 1e-9);
    EXPECT_NEAR(q.area_fraction, 0.547, 0.02);
  }
}

/// The numbers of the report recomputed from the brute-force triangulation.
void expect_agrees_with_brute_force(const Packing& p, double r) {
  const double W = p.frame().extent.x, H = p.frame().extent.y;
  std::vector<test::BrutePoint> pts;
  for (DiskId id : p.ids()) pts.push_back({p.center(id).x, p.center(id).y});
  const auto tris = test::brute_periodic_delaunay(pts, W, H, 0.45 * std::min(W, H));
  const QualityReport q = measure(p, r);
  ASSERT_EQ(tris.size(), q.triangle_count);

  std::vector<std::size_t> hist(180, 0);
  double min_angle = 180, max_angle = 0, max_circumradius = 0;
  std::vector<double> outradius(pts.size(), 0);
  for (const auto& t : tris) {
    const auto angles = test::brute_angles_degrees(t.corners);
    for (double deg : angles) {
      ++hist[static_cast<std::size_t>(deg)];
      min_angle = std::min(min_angle, deg);
      max_angle = std::max(max_angle, deg);
    }
    // Law of sines: R = a / (2 sin A).
    const auto& c = t.corners;
    const double side = std::hypot(c[1].x - c[2].x, c[1].y - c[2].y);
    const double rho = side / (2 * std::sin(angles[0] * test::kBrutePi / 180));
    max_circumradius = std::max(max_circumradius, rho);
    for (const auto& im : t.key) outradius[im.index] = std::max(outradius[im.index], rho);
  }
  EXPECT_EQ(q.angles.histogram.counts, hist);
  EXPECT_NEAR(q.angles.min, min_angle, 1e-9);
  EXPECT_NEAR(q.angles.max, max_angle, 1e-9);
  EXPECT_NEAR(q.max_coverage_over_r, max_circumradius / r, 1e-9);

  // Nearest neighbours over all pairs and images, then beta.
  double min_distance = 1e300, beta_min = 1e300, beta_max = 0, beta_sum = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    double nearest = 1e300;
    for (std::size_t j = 0; j < pts.size(); ++j) {
      for (int ox = -1; ox <= 1; ++ox) {
        for (int oy = -1; oy <= 1; ++oy) {
          if (i == j && ox == 0 && oy == 0) continue;
          nearest = std::min(
              nearest, std::hypot(pts[j].x + ox * W - pts[i].x, pts[j].y + oy * H - pts[i].y));
        }
      }
    }
    min_distance = std::min(min_distance, nearest);
    const double beta = outradius[i] / nearest;
    beta_min = std::min(beta_min, beta);
    beta_max = std::max(beta_max, beta);
    beta_sum += beta;
  }
  EXPECT_NEAR(q.min_distance_over_r, min_distance / r, 1e-12);
  EXPECT_NEAR(q.local_beta.min, beta_min, 1e-9);
  EXPECT_NEAR(q.local_beta.max, beta_max, 1e-9);
  EXPECT_NEAR(q.local_beta.mean, beta_sum / pts.size(), 1e-9);
}

TEST(Quality, AgreesWithABruteForceComputationOnRandomPoints) {
  for (std::uint64_t seed : {1, 2, 3}) {
    expect_agrees_with_brute_force(test::random_points(90, 1.4, 0.8, 0.05, seed), 0.05);
  }
}

TEST(Quality, AgreesWithABruteForceComputationOnAMaximalSample) {
  const PeriodicBox box(1.0, 0.8);
  Rng rng(9);
  expect_agrees_with_brute_force(sample_mps(box, 0.09, rng), 0.09);
}

TEST(Quality, RefusesAMeshOfAnotherPacking) {
  const Packing p = test::hex_lattice(6, 4, 1.0, 1.0);
  Packing other = test::hex_lattice(6, 4, 1.0, 1.0);
  other.remove(3);
  EXPECT_THROW(measure_quality(other, periodic_delaunay(p), 1.0), InvalidInput);
}

TEST(QualityJson, HasEveryKey) {
  const QualityReport q = measure(test::hex_lattice(6, 4, 1.0, 1.0), 1.0);
  const nlohmann::json j = nlohmann::json::parse(quality_json(q));
  for (const char* key : {"count", "area_fraction", "relative_radius", "min_distance_over_r",
                          "max_coverage_over_r"}) {
    EXPECT_TRUE(j.at(key).is_number()) << key;
  }
  EXPECT_TRUE(j.at("maximal").is_boolean());
  EXPECT_TRUE(j.at("conflict_free").is_boolean());
  for (const char* key :
       {"min", "max", "mean_abs_dev_60", "fraction_50_70", "fraction_obtuse_triangles"}) {
    EXPECT_TRUE(j.at("angles").at(key).is_number()) << key;
  }
  for (const char* key : {"min_over_r", "max_over_r"})
    EXPECT_TRUE(j.at("edges").at(key).is_number());
  for (const char* key : {"min", "mean", "max"})
    EXPECT_TRUE(j.at("local_beta").at(key).is_number());
  for (const char* group : {"angles", "edges", "local_beta"}) {
    const auto& h = j.at(group).at("histogram");
    EXPECT_TRUE(h.at("lo").is_number() && h.at("bin_width").is_number() &&
                h.at("counts").is_array() && h.at("overflow").is_number())
        << group;
  }
  EXPECT_EQ(j["angles"]["histogram"]["counts"].size(), 180u);
  EXPECT_EQ(j["angles"]["histogram"]["counts"][60], 6 * q.count);
  for (const char* key : {"min", "mean", "max", "stddev"}) {
    EXPECT_TRUE(j.at("voronoi").at("aspect_ratio").at(key).is_number());
  }
  EXPECT_TRUE(j.at("voronoi").at("cell_area_cv").is_number());
  EXPECT_EQ(j["count"], q.count);
  EXPECT_EQ(j["local_beta"]["max"].get<double>(), q.local_beta.max);  // every bit
}

}  // namespace
}  // namespace disktune
