// SPDX-License-Identifier: GPL-3.0-or-later
// Local feature size sizing (feature_sizing, `--sizing auto:R`; issue #15 item 3),
// judged by code of its own: lfs by brute force over every segment at boundary points
// far finer than the library's sites, the sizing's promises at the corners, its
// gradation, and the packings it gives in domains a single radius does not fit, checked
// by the independent planar oracle with each disk's radius.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "disktune/boundary.h"
#include "disktune/mesh.h"
#include "disktune/planar_domain.h"
#include "disktune/sampling.h"
#include "disktune/sizing.h"
#include "disktune/tuning.h"
#include "oracle/planar_oracle.h"
#include "planar_checks.h"

namespace disktune {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The unit square with a square hole whose corner is 0.0188 from the square's corner:
// a single radius 0.02 is refused there (the corner disks would conflict).
std::shared_ptr<const PlanarDomain> close_hole() {
  const double c = 0.0133;
  return std::make_shared<const PlanarDomain>(std::vector<Vec2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}},
                                              std::vector<std::vector<Vec2>>{{{c, c}, {c, 0.3}, {0.3, 0.3}, {0.3, c}}});
}

std::shared_ptr<const PlanarDomain> notch_and_holes() {
  return std::make_shared<const PlanarDomain>(read_poly(std::string(DISKTUNE_DATA_DIR) + "/domains/notch_and_holes.poly"));
}

double point_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double t = std::clamp(dot(p - a, ab) / squared_norm(ab), 0.0, 1.0);
  return distance(p, a + ab * t);
}

// Boundary points `step` apart with their lfs: the distance to every segment but their
// own and its two neighbours along the loop (at a vertex: every segment not ending there).
struct FinePoint {
  Vec2 p;
  double lfs;
};
std::vector<FinePoint> fine_boundary(const PlanarDomain& d, double step) {
  std::vector<FinePoint> out;
  const auto& loops = d.loops();
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const std::size_t n = loops[l].size();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 a = loops[l][i], b = loops[l][(i + 1) % n];
      const int pieces = std::max(1, static_cast<int>(std::ceil(distance(a, b) / step)));
      for (int k = 0; k <= pieces; ++k) {
        const Vec2 p = a + (b - a) * (static_cast<double>(k) / pieces);
        double lfs = std::numeric_limits<double>::infinity();
        for (std::size_t m = 0; m < loops.size(); ++m)
          for (std::size_t j = 0; j < loops[m].size(); ++j) {
            const Vec2 u = loops[m][j], w = loops[m][(j + 1) % loops[m].size()];
            const bool own_or_next = m == l && (j == i || j == (i + 1) % n || i == (j + 1) % n);
            const bool at_vertex = k == 0 || k == pieces;
            const Vec2 v = k == 0 ? a : b;
            if (at_vertex ? (u == v || w == v) : own_or_next) continue;
            lfs = std::min(lfs, point_segment(p, u, w));
          }
        out.push_back({p, lfs});
      }
    }
  }
  return out;
}

// min(R, min over the fine points of 0.45 lfs + g |x - q|).
double brute_sizing(const std::vector<FinePoint>& fine, double R, double g, Vec2 x) {
  double r = R;
  for (const FinePoint& q : fine) r = std::min(r, 0.45 * q.lfs + g * distance(x, q.p));
  return r;
}

TEST(FeatureSizing, MatchesABruteForceFieldAndKeepsItsGradation) {
  for (const auto& d : {close_hole(), notch_and_holes()}) {
    const double R = 0.02, g = 0.2, step = 2e-4;
    const Sizing s = feature_sizing(d, R, g);
    const std::vector<FinePoint> fine = fine_boundary(*d, step);
    Rng rng(7);
    double worst_low = 0, worst_high = 0;
    for (int k = 0; k < 1500; ++k) {
      const Vec2 x = d->random_point(rng);
      const double lib = s(x), bf = brute_sizing(fine, R, g, x);
      // The library's sites are a subset of the boundary (so never below the continuous
      // field, which the fine points approximate within 0.65 step / 2), a quarter of
      // their own radius apart (so above it by at most 0.65 / 8 of it).
      EXPECT_GE(lib, bf - 0.65 * step) << "at (" << x.x << ", " << x.y << ")";
      EXPECT_LE(lib, 1.1 * bf + 0.65 * step) << "at (" << x.x << ", " << x.y << ")";
      worst_low = std::max(worst_low, (bf - lib) / bf), worst_high = std::max(worst_high, (lib - bf) / bf);
      const Vec2 y = x + Vec2{uniform01(rng) - 0.5, uniform01(rng) - 0.5} * 0.05;
      EXPECT_LE(std::abs(s(y) - lib), g * distance(x, y) * (1 + 1e-9) + 1e-15);
      EXPECT_LE(lib, R);
    }
    std::printf("[feature sizing] %zu fine points; library below brute force by at most %.3g, above by %.3g (relative)\n",
                fine.size(), worst_low, worst_high);
  }
}

// At each corner the radius leaves room: at most 0.45 of each segment ending there (so
// the segment holds a disk between its corner disks) and of the distance to any other
// segment, so corner disks never conflict.
TEST(FeatureSizing, CornersGetRoom) {
  for (const auto& d : {close_hole(), notch_and_holes()}) {
    const Sizing s = feature_sizing(d, 0.05);
    for (const auto& loop : d->loops())
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const Vec2 v = loop[i];
        const double r = s(v);
        EXPECT_LE(r, 0.45 * distance(v, loop[(i + 1) % loop.size()]) * (1 + 1e-9));
        EXPECT_LE(r, 0.45 * distance(v, loop[(i + loop.size() - 1) % loop.size()]) * (1 + 1e-9));
        for (const BoundarySegment& seg : d->segments()) {
          if (!(seg.a == v) && !(seg.b == v)) {
            EXPECT_LE(r, 0.45 * point_segment(v, seg.a, seg.b) * (1 + 1e-9));
          }
        }
      }
  }
}

TEST(FeatureSizing, RefusesBadParametersAndParsesAuto) {
  EXPECT_THROW(feature_sizing(nullptr, 0.02), InvalidInput);
  EXPECT_THROW(feature_sizing(close_hole(), 0), InvalidInput);
  EXPECT_THROW(feature_sizing(close_hole(), 0.02, 0.5), InvalidInput);
  EXPECT_THROW(feature_sizing(close_hole(), 0.02, 0), InvalidInput);
  EXPECT_THROW(feature_sizing(close_hole(), std::nan(""), 0.2), InvalidInput);
  EXPECT_THROW(parse_sizing("auto:0.02", nullptr), InvalidInput);
  EXPECT_THROW(parse_sizing("auto:", close_hole()), InvalidInput);
  EXPECT_THROW(parse_sizing("auto:0.02,0.1,3", close_hole()), InvalidInput);
  const Sizing s = parse_sizing("auto:0.02,0.1", close_hole());
  EXPECT_DOUBLE_EQ(s({0.7, 0.7}), 0.02);
  EXPECT_LT(s({0.0133, 0.0133}), 0.45 * 0.0188 * 1.000001);
}

// A domain a single radius 0.02 does not fit (refused), and one it fits with slivers
// (gaps of 0.0188): sampled and tuned with feature sizing, every result passes the
// independent oracle, its mesh tiles the domain, and its angles stay above the bound of
// the sizing's gradation (docs/sizing.md; measured: far above it).
TEST(FeatureSizing, DomainsASingleRadiusDoesNotFitAreMeshed) {
  const auto close = close_hole();
  EXPECT_FALSE(close->corners_fit(0.02));
  EXPECT_TRUE(close->corners_fit(0.0188));  // the corners are 0.01881 apart
  EXPECT_THROW(close->validate_radius(0.02), InvalidInput);
  for (const auto& d : {close, notch_and_holes()}) {
    const auto sizing = std::make_shared<const Sizing>(feature_sizing(d, 0.02));
    const oracle::Domain od = test::oracle_domain(*d);
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      Rng rng(seed);
      Packing p = sample_mps(d, sizing, rng);
      for (const double eta : {0.0, 0.8}) {
        if (eta > 0) tune(p, *d, Target::area_fraction(eta), rng);
        SCOPED_TRACE("seed " + std::to_string(seed) + " eta " + std::to_string(eta));
        const auto report = test::check_with_oracle(p, *d);
        EXPECT_TRUE(report.ok()) << report.summary();
        Packing copy = p;
        const PlanarMesh mesh = constrained_delaunay(copy, boundary_loops(copy, *d));
        test::expect_mesh_tiles(mesh, od, 1e-6 * 0.02);
        double min_angle = 180;
        for (const auto& t : mesh.triangles)
          for (int k = 0; k < 3; ++k) {
            const Vec2 a = mesh.vertices[t[k]], b = mesh.vertices[t[(k + 1) % 3]], c = mesh.vertices[t[(k + 2) % 3]];
            min_angle = std::min(min_angle, std::acos(std::clamp(dot(b - a, c - a) / (distance(a, b) * distance(a, c)), -1.0, 1.0)) * 180 / kPi);
          }
        std::printf("[feature sizing] seed %llu eta %.1f: %zu disks, min angle %.2f\n",
                    static_cast<unsigned long long>(seed), eta, p.size(), min_angle);
        EXPECT_GE(min_angle, angle_bound_degrees(kFeatureGradation));
      }
    }
  }
}

}  // namespace
}  // namespace disktune
