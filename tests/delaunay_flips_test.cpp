// SPDX-License-Identifier: GPL-3.0-or-later
// Edge flips toward Delaunay (src/mesh/delaunay_flips.h), checked in the plane, where
// Lawson's flips from any triangulation end at the Delaunay one: against a brute-force
// Delaunay triangulation of the moved points (every triple whose circumcircle holds no
// other point), written here with none of the library's code; with feature edges, which
// must stay, every other edge checked by its facing angles (atan2, not the library's
// sine test) unless its flip would repeat an edge.
#include "../src/mesh/delaunay_flips.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "disktune/errors.h"

namespace disktune {
namespace {

using Tri = std::array<std::uint32_t, 3>;
constexpr double kPi = 3.14159265358979323846;

double orient(Vec3 a, Vec3 b, Vec3 c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Whether d lies strictly inside the circle through a, b, c (counterclockwise).
bool in_circle(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const double ax = a.x - d.x, ay = a.y - d.y, bx = b.x - d.x, by = b.y - d.y, cx = c.x - d.x,
               cy = c.y - d.y;
  return (ax * ax + ay * ay) * (bx * cy - cx * by) - (bx * bx + by * by) * (ax * cy - cx * ay) +
             (cx * cx + cy * cy) * (ax * by - bx * ay) >
         0;
}

// Every counterclockwise triple of `p` whose circumcircle holds no other point.
std::vector<Tri> brute_delaunay(const std::vector<Vec3>& p) {
  std::vector<Tri> out;
  const auto n = static_cast<std::uint32_t>(p.size());
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = i + 1; j < n; ++j)
      for (std::uint32_t k = j + 1; k < n; ++k) {
        Tri t{i, j, k};
        const double o = orient(p[i], p[j], p[k]);
        if (o == 0) continue;
        if (o < 0) std::swap(t[1], t[2]);
        bool empty = true;
        for (std::uint32_t m = 0; m < n && empty; ++m)
          if (m != i && m != j && m != k) empty = !in_circle(p[t[0]], p[t[1]], p[t[2]], p[m]);
        if (empty) out.push_back(t);
      }
  return out;
}

// Each triangle turned to start at its smallest corner, the list sorted.
std::vector<Tri> normalized(std::vector<Tri> tris) {
  for (Tri& t : tris) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  std::sort(tris.begin(), tris.end());
  return tris;
}

// A jittered n x n grid in the unit square (z = 0): points in general position.
std::vector<Vec3> jittered_grid(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  std::vector<Vec3> out;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) out.push_back({(i + jitter(rng)) / n, (j + jitter(rng)) / n, 0});
  return out;
}

// The points of the grid's inner rows and columns moved by up to `by` grid spacings,
// where no triangle of `tris` turns over (else nothing moves); the outer ring stays, so
// the convex hull does too.
std::vector<Vec3> moved_inside(std::mt19937& rng, const std::vector<Vec3>& p, int n, double by,
                               const std::vector<Tri>& tris) {
  std::uniform_real_distribution<double> step(-by / n, by / n);
  for (int attempt = 0; attempt < 100; ++attempt) {
    std::vector<Vec3> q = p;
    for (int i = 1; i + 1 < n; ++i)
      for (int j = 1; j + 1 < n; ++j) {
        Vec3& v = q[static_cast<std::size_t>(i * n + j)];
        v.x += step(rng), v.y += step(rng);
      }
    if (std::all_of(tris.begin(), tris.end(),
                    [&](const Tri& t) { return orient(q[t[0]], q[t[1]], q[t[2]]) > 0; }))
      return q;
  }
  return p;
}

std::uint64_t key(std::uint32_t a, std::uint32_t b) {
  return a < b ? std::uint64_t{a} << 32 | b : std::uint64_t{b} << 32 | a;
}

// Each edge with the corners facing it (one for a hull edge).
std::map<std::uint64_t, std::vector<std::uint32_t>> facing(const std::vector<Tri>& tris) {
  std::map<std::uint64_t, std::vector<std::uint32_t>> out;
  for (const Tri& t : tris)
    for (int k = 0; k < 3; ++k) out[key(t[k], t[(k + 1) % 3])].push_back(t[(k + 2) % 3]);
  return out;
}

double angle_at(Vec3 apex, Vec3 a, Vec3 b) {
  const Vec3 u = a - apex, v = b - apex;
  return std::atan2(norm(cross(u, v)), dot(u, v));
}

TEST(DelaunayFlips, EndAtTheDelaunayTriangulationOfMovedPointsInThePlane) {
  int flipped_runs = 0;
  for (unsigned seed = 1; seed <= 20; ++seed) {
    std::mt19937 rng(seed);
    constexpr int n = 7;
    const std::vector<Vec3> before = jittered_grid(rng, n);
    SurfaceMesh mesh{before, brute_delaunay(before)};
    const std::vector<Vec3> after = moved_inside(rng, before, n, 0.25, mesh.triangles);
    ASSERT_NE(after, before) << "seed " << seed << ": no move kept every triangle upright";
    const std::size_t flips = detail::flip_toward_delaunay(mesh, after);
    flipped_runs += flips > 0;
    EXPECT_EQ(mesh.vertices, after);
    EXPECT_EQ(normalized(mesh.triangles), normalized(brute_delaunay(after)))
        << "seed " << seed << ", " << flips << " flips";
  }
  EXPECT_GE(flipped_runs, 15);  // the moves do change the triangulation
}

TEST(DelaunayFlips, FollowOneMovedVertex) {
  // Each inner vertex in turn moved alone: only the edges around it are looked at.
  std::mt19937 rng(7);
  constexpr int n = 6;
  const std::vector<Vec3> before = jittered_grid(rng, n);
  const std::vector<Tri> first = brute_delaunay(before);
  std::uniform_real_distribution<double> step(-0.5 / n, 0.5 / n);
  int flipped_runs = 0;
  for (int i = 1; i + 1 < n; ++i)
    for (int j = 1; j + 1 < n; ++j) {
      std::vector<Vec3> after = before;
      Vec3& v = after[static_cast<std::size_t>(i * n + j)];
      for (int attempt = 0; attempt < 100; ++attempt) {
        v = before[static_cast<std::size_t>(i * n + j)] + Vec3{step(rng), step(rng), 0};
        if (std::all_of(first.begin(), first.end(), [&](const Tri& t) {
              return orient(after[t[0]], after[t[1]], after[t[2]]) > 0;
            }))
          break;
      }
      SurfaceMesh mesh{before, first};
      flipped_runs += detail::flip_toward_delaunay(mesh, after) > 0;
      EXPECT_EQ(normalized(mesh.triangles), normalized(brute_delaunay(after)))
          << "vertex " << i * n + j;
    }
  EXPECT_GE(flipped_runs, 4);
}

TEST(DelaunayFlips, NeverRepeatAnEdge) {
  // A flat tetrahedron (a closed surface): the angles facing ab sum to nearly 360
  // degrees, but cd is an edge already.
  const std::vector<Vec3> p{{-1, 0, 0}, {1, 0, 0}, {0, 0.1, 0.05}, {0, -0.1, 0.05}};
  SurfaceMesh mesh{p, {{0, 1, 2}, {1, 0, 3}, {0, 2, 3}, {1, 3, 2}}};
  const std::vector<Tri> tris = mesh.triangles;
  std::vector<Vec3> after = p;
  after[2].z = 0.06;
  EXPECT_EQ(detail::flip_toward_delaunay(mesh, after), 0u);
  EXPECT_EQ(mesh.triangles, tris);
}

TEST(DelaunayFlips, KeepFeatureEdgesAndLeaveEveryOtherEdgeLocallyDelaunay) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    std::mt19937 rng(100 + seed);
    constexpr int n = 7;
    const std::vector<Vec3> before = jittered_grid(rng, n);
    SurfaceMesh mesh{before, brute_delaunay(before)};
    // A few inner edges of the first triangulation are features.
    std::set<std::uint64_t> features;
    for (const auto& [e, corners] : facing(mesh.triangles)) {
      if (corners.size() == 2 && features.size() < 6 && rng() % 8 == 0) {
        mesh.feature_edges.push_back(
            {static_cast<std::uint32_t>(e >> 32), static_cast<std::uint32_t>(e)});
        features.insert(e);
      }
    }
    const std::vector<Vec3> after = moved_inside(rng, before, n, 0.3, mesh.triangles);
    const std::size_t triangles = mesh.triangles.size();
    detail::flip_toward_delaunay(mesh, after);
    ASSERT_EQ(mesh.triangles.size(), triangles);
    for (const Tri& t : mesh.triangles)
      EXPECT_GT(orient(after[t[0]], after[t[1]], after[t[2]]), 0) << "seed " << seed;
    const auto edges = facing(mesh.triangles);
    for (const std::uint64_t e : features)
      EXPECT_TRUE(edges.count(e)) << "seed " << seed << ": a feature edge went";
    for (const auto& [e, corners] : edges) {
      ASSERT_LE(corners.size(), 2u) << "seed " << seed;
      if (corners.size() < 2 || features.count(e)) continue;
      const auto a = static_cast<std::uint32_t>(e >> 32), b = static_cast<std::uint32_t>(e);
      const double sum = angle_at(after[corners[0]], after[a], after[b]) +
                         angle_at(after[corners[1]], after[a], after[b]);
      if (edges.count(key(corners[0], corners[1]))) continue;  // its flip would repeat an edge
      // A quad with a reflex corner cannot flip either; in the plane its facing angles sum below
      // 180.
      EXPECT_LE(sum, kPi + 1e-9) << "seed " << seed << ": edge " << a << "-" << b;
    }
  }
}

TEST(DelaunayFlips, NeedOnePointPerVertex) {
  SurfaceMesh mesh{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}};
  EXPECT_THROW(detail::flip_toward_delaunay(mesh, {{0, 0, 0}}), InvalidInput);
}

}  // namespace
}  // namespace disktune
