// SPDX-License-Identifier: GPL-3.0-or-later
// The periodic Delaunay triangulation: lattices (every cell cocircular), tiny inputs,
// non-square boxes, maximal samples, and a brute-force triangulation to agree with.
#include "disktune/mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

#include "brute_delaunay.h"
#include "disktune/errors.h"
#include "disktune/sampling.h"
#include "lattices.h"

namespace disktune {
namespace {

double signed_area(const TriangleMesh& m, const std::array<std::uint32_t, 3>& t) {
  const Vec2 a = m.vertices[t[0]], b = m.vertices[t[1]], c = m.vertices[t[2]];
  return 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

/// The checks every torus triangulation passes: 2N counterclockwise triangles whose
/// areas sum to W*H, centroids in the box, vertices at their disk's offset image.
void expect_torus_triangulation(const Packing& p, const TriangleMesh& m) {
  const double W = p.frame().extent.x, H = p.frame().extent.y;
  ASSERT_EQ(m.disk_count, p.size());
  ASSERT_EQ(m.triangles.size(), 2 * p.size());
  double area = 0;
  for (const auto& t : m.triangles) {
    const double a = signed_area(m, t);
    EXPECT_GT(a, 0);
    area += a;
    const Vec2 g = (m.vertices[t[0]] + m.vertices[t[1]] + m.vertices[t[2]]) * (1.0 / 3);
    EXPECT_TRUE(g.x > -1e-12 * W && g.x < W * (1 + 1e-12) && g.y > -1e-12 * H &&
                g.y < H * (1 + 1e-12));
  }
  EXPECT_NEAR(area, W * H, 1e-9 * W * H);
  ASSERT_EQ(m.vertices.size(), m.vertex_disk.size());
  for (std::size_t v = 0; v < m.vertices.size(); ++v) {
    const Vec2 c = p.center(m.vertex_disk[v]);
    const Vec2 image = c + Vec2{m.vertex_offset[v][0] * W, m.vertex_offset[v][1] * H};
    EXPECT_EQ(m.vertices[v], image);
    if (v < m.disk_count) {
      EXPECT_EQ(m.vertex_disk[v], p.ids()[v]);
      EXPECT_EQ(m.vertex_offset[v][0], 0);
      EXPECT_EQ(m.vertex_offset[v][1], 0);
    }
  }
  EXPECT_EQ(unique_edges(m).size(), 3 * p.size());
  // A closed surface: every half-edge (disk u -> disk v at a relative offset) occurs
  // once and so does its opposite. Copies of a cell triangulated with different
  // diagonals pass the counts and the area sum, but not this.
  std::map<std::tuple<DiskId, DiskId, int, int>, int> half_edges;
  for (const auto& t : m.triangles) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t u = t[k], v = t[(k + 1) % 3];
      ++half_edges[{m.vertex_disk[u], m.vertex_disk[v],
                    m.vertex_offset[v][0] - m.vertex_offset[u][0],
                    m.vertex_offset[v][1] - m.vertex_offset[u][1]}];
    }
  }
  for (const auto& [e, n] : half_edges) {
    const auto& [u, v, ox, oy] = e;
    EXPECT_EQ(n, 1);
    const auto twin = half_edges.find({v, u, -ox, -oy});
    EXPECT_TRUE(twin != half_edges.end() && twin->second == 1)
        << "half-edge " << u << "->" << v << " (" << ox << "," << oy << ") has no twin";
  }
}

std::vector<double> edge_lengths(const TriangleMesh& m) {
  std::vector<double> out;
  for (const auto& e : unique_edges(m)) out.push_back(distance(m.vertices[e[0]], m.vertices[e[1]]));
  return out;
}

TEST(PeriodicDelaunay, HexLatticeGivesEquilateralTriangles) {
  for (const auto& [nx, ny, a] : {std::tuple{6, 4, 1.0}, {10, 8, 0.1}, {7, 6, 0.37}, {3, 4, 1.0}}) {
    const Packing p = test::hex_lattice(nx, ny, a, a);
    const TriangleMesh m = periodic_delaunay(p);
    expect_torus_triangulation(p, m);
    for (double len : edge_lengths(m)) EXPECT_NEAR(len, a, 1e-12 * a) << nx << "x" << ny;
  }
}

TEST(PeriodicDelaunay, ShiftedHexLatticeStaysConsistentAcrossTheSeam) {
  // Lattice points off the grid of the box: the copies differ in their rounding.
  const double a = 0.1;
  const Packing base = test::hex_lattice(10, 12, a, a);
  Packing p(base.frame(), a);
  for (DiskId id : base.ids()) p.insert(base.center(id) + Vec2{0.0317, 0.01234}, a);
  const TriangleMesh m = periodic_delaunay(p);
  expect_torus_triangulation(p, m);
  for (double len : edge_lengths(m)) EXPECT_NEAR(len, a, 1e-12);
}

TEST(PeriodicDelaunay, SquareLatticeSplitsEachCellInTwo) {
  for (const auto& [nx, ny] : {std::pair{5, 5}, {8, 3}, {12, 10}}) {
    const double a = 0.25;
    const Packing p = test::square_lattice(nx, ny, a, a);
    const TriangleMesh m = periodic_delaunay(p);
    expect_torus_triangulation(p, m);
    std::size_t sides = 0, diagonals = 0;
    for (double len : edge_lengths(m)) {
      if (std::abs(len - a) < 1e-12) ++sides;
      if (std::abs(len - a * std::sqrt(2.0)) < 1e-12) ++diagonals;
    }
    EXPECT_EQ(sides, 2 * p.size());
    EXPECT_EQ(diagonals, p.size());
  }
}

TEST(PeriodicDelaunay, ShiftedSquareLatticesStayConsistentAcrossTheSeam) {
  // Spacings and shifts that are not binary fractions: a copy across the seam is not
  // the float translate of the original, yet must be triangulated alike.
  for (const double a : {0.1, 0.07, 1.0 / 3}) {
    for (int s = 0; s < 8; ++s) {
      const Packing base = test::square_lattice(9, 7, a, a);
      Packing p(base.frame(), a);
      const Vec2 shift{0.1 * std::sqrt(s + 2.0), 0.07 * std::sqrt(s + 3.0)};
      for (DiskId id : base.ids()) p.insert(base.center(id) + shift, a);
      expect_torus_triangulation(p, periodic_delaunay(p));
    }
  }
}

TEST(PeriodicDelaunay, HexLatticeWithOnePointRemoved) {
  Packing p = test::hex_lattice(8, 6, 1.0, 1.0);
  p.remove(17);
  const TriangleMesh m = periodic_delaunay(p);
  expect_torus_triangulation(p, m);
  for (DiskId id : m.vertex_disk) EXPECT_NE(id, 17u);
}

TEST(PeriodicDelaunay, TinyInputsStillTriangulateTheTorus) {
  // One point: its images form a rectangular lattice (2 triangles, 3 edges).
  for (int n : {1, 2, 3, 5}) {
    for (std::uint64_t seed : {1, 2, 3}) {
      const Packing p = test::random_points(n, 1.3, 0.7, 0.1, seed);
      expect_torus_triangulation(p, periodic_delaunay(p));
    }
  }
}

TEST(PeriodicDelaunay, SparseCentersWithATinyRadiusGrowTheMargin) {
  // r far below the spacing: the first margin is far too small.
  for (int n : {2, 200}) {
    const Packing p = test::random_points(n, 1.0, 0.6, 1e-3, 8);
    expect_torus_triangulation(p, periodic_delaunay(p));
  }
}

TEST(PeriodicDelaunay, CollinearCentersStillTriangulateTheTorus) {
  Packing p(PeriodicBox(2.0, 1.0).frame(), 0.1);
  for (int k = 0; k < 7; ++k) p.insert({0.25 * k, 0.5}, 0.1);
  expect_torus_triangulation(p, periodic_delaunay(p));
}

TEST(PeriodicDelaunay, AgreesWithABruteForceTriangulationInNonSquareBoxes) {
  for (const auto& [W, H, n] : {std::tuple{1.7, 0.6, 80}, {0.5, 1.9, 60}, {1.0, 1.0, 120}}) {
    for (std::uint64_t seed : {4, 5}) {
      const Packing p = test::random_points(n, W, H, 0.05, seed);
      const TriangleMesh m = periodic_delaunay(p);
      expect_torus_triangulation(p, m);
      std::vector<test::BrutePoint> pts;
      for (DiskId id : p.ids()) pts.push_back({p.center(id).x, p.center(id).y});
      const auto brute = test::brute_periodic_delaunay(pts, W, H, 0.45);
      std::set<test::TriangleKey> want, got;
      double brute_area = 0;
      for (const auto& t : brute) {
        want.insert(t.key);
        const auto& c = t.corners;
        brute_area +=
            0.5 * ((c[1].x - c[0].x) * (c[2].y - c[0].y) - (c[1].y - c[0].y) * (c[2].x - c[0].x));
      }
      ASSERT_NEAR(brute_area, W * H, 1e-9) << "the brute force missed triangles";
      for (const auto& t : m.triangles) {
        std::array<test::Image, 3> im;
        for (int k = 0; k < 3; ++k) {
          im[k] = {static_cast<int>(m.vertex_disk[t[k]]), m.vertex_offset[t[k]][0],
                   m.vertex_offset[t[k]][1]};
        }
        got.insert(test::triangle_key(im));
      }
      EXPECT_EQ(got, want) << W << "x" << H << " seed " << seed;
    }
  }
}

TEST(PeriodicDelaunay, MaximalSampleMeetsTheKnownBounds) {
  // In an MPS every Delaunay circle is empty of centers, hence within r of none but its
  // own corners: circumradius <= r; every edge >= r; so every angle is in [30, 120].
  for (const auto& [W, H, r] :
       {std::tuple{1.0, 1.0, 0.03}, {1.3, 0.8, 0.05}, {0.4, 2.0, 0.02}, {3.0, 0.09, 0.04}}) {
    const PeriodicBox box(W, H);
    Rng rng(11);
    const Packing p = sample_mps(box, r, rng);
    const TriangleMesh m = periodic_delaunay(p);
    expect_torus_triangulation(p, m);
    for (double len : edge_lengths(m)) EXPECT_GE(len, r * (1 - 1e-9));
    for (const auto& t : m.triangles) {
      const Vec2 a = m.vertices[t[0]], b = m.vertices[t[1]], c = m.vertices[t[2]];
      const double la = distance(b, c), lb = distance(a, c), lc = distance(a, b);
      EXPECT_LE(la * lb * lc / (4 * signed_area(m, t)), r * (1 + 1e-9));
      for (const auto& [x, y, z] : {std::tuple{la, lb, lc}, {lb, lc, la}, {lc, la, lb}}) {
        const double deg = std::acos((y * y + z * z - x * x) / (2 * y * z)) * 180 / test::kBrutePi;
        EXPECT_GE(deg, 30 - 1e-6);
        EXPECT_LE(deg, 120 + 1e-6);
      }
    }
  }
}

TEST(PeriodicDelaunay, RefusesCoincidingCentersEmptyAndPlanarPackings) {
  Packing p(PeriodicBox(1, 1).frame(), 0.1);
  p.insert({0.2, 0.3}, 0.1);
  p.insert({0.7, 0.3}, 0.1);
  p.insert({0.2, 0.3}, 0.1);
  EXPECT_THROW(periodic_delaunay(p), InvalidInput);
  Packing empty(PeriodicBox(1, 1).frame(), 0.1);
  EXPECT_THROW(periodic_delaunay(empty), InvalidInput);
  Packing planar(Frame{{0, 0}, {1, 1}, false}, 0.1);
  planar.insert({0.5, 0.5}, 0.1);
  EXPECT_THROW(periodic_delaunay(planar), InvalidInput);
}

}  // namespace
}  // namespace disktune
