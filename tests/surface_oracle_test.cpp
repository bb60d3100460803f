// SPDX-License-Identifier: GPL-3.0-or-later
// The surface oracle must be able to fail: hand-made packings with one defect each,
// which it has to name, and valid ones it has to pass. The answers are known by hand
// (the arguments are in the comments).
#include "oracle/surface_oracle.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>

namespace {

using oracle::check_surface;
using oracle::Point3;
using oracle::SurfaceMeshInput;
using oracle::SurfaceOptions;
using oracle::SurfaceReport;
using Points3 = std::vector<Point3>;

bool mentions(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

double dist(const Point3& a, const Point3& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                   (a[2] - b[2]) * (a[2] - b[2]));
}

// [0,L]^2 in the plane z = 0, m x m cells, each split into two triangles along the
// diagonal from (i, j) to (i+1, j+1).
SurfaceMeshInput square(double L, int m) {
  SurfaceMeshInput s;
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= m; ++i) s.vertices.push_back({L * i / m, L * j / m, 0});
  auto id = [m](int i, int j) { return static_cast<std::size_t>(j * (m + 1) + i); };
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      s.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      s.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return s;
}

// Hexagonal lattice of spacing s in [0,L]^2: rows k*s*sqrt(3)/2, odd rows shifted by
// s/2. With L = 4s every point of the square is within 0.734 s of a lattice point
// (inside the square: s/sqrt(3); on the edges, where the rows end: at most 0.734 s).
Points3 hex(double s, double L) {
  Points3 out;
  const double h = s * std::sqrt(3.0) / 2;
  for (int k = 0; k * h <= L + 1e-12; ++k)
    for (int j = 0; (k % 2) * s / 2 + j * s <= L + 1e-12; ++j)
      out.push_back({(k % 2) * s / 2 + j * s, k * h, 0});
  return out;
}

// A rigid motion: rotation about the axis (1, 2, 3) by 0.7 rad, then a shift.
Point3 tilt(const Point3& p) {
  const double ax = 1 / std::sqrt(14.0), ay = 2 / std::sqrt(14.0), az = 3 / std::sqrt(14.0);
  const double th = 0.7, co = std::cos(th), si = std::sin(th);
  const double d = ax * p[0] + ay * p[1] + az * p[2];
  const Point3 cr{ay * p[2] - az * p[1], az * p[0] - ax * p[2], ax * p[1] - ay * p[0]};
  Point3 q;
  const double a[3] = {ax, ay, az};
  for (int k = 0; k < 3; ++k) q[k] = p[k] * co + cr[k] * si + a[k] * d * (1 - co);
  return {q[0] + 10, q[1] - 3, q[2] + 0.5};
}

void tilt_all(SurfaceMeshInput& mesh, Points3& c) {
  for (auto& v : mesh.vertices) v = tilt(v);
  for (auto& p : c) p = tilt(p);
}

// The unit cube [0,1]^3, two triangles per face (12 in all).
SurfaceMeshInput cube() {
  SurfaceMeshInput s;
  for (int k = 0; k < 8; ++k) s.vertices.push_back({double(k & 1), double((k >> 1) & 1), double(k >> 2)});
  const std::size_t faces[6][4] = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                   {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
  for (const auto& f : faces) {
    s.triangles.push_back({f[0], f[1], f[2]});
    s.triangles.push_back({f[0], f[2], f[3]});
  }
  return s;
}
const Point3 kFaceCenters[6] = {{0.5, 0.5, 0}, {0.5, 0.5, 1}, {0.5, 0, 0.5},
                                {0.5, 1, 0.5}, {0, 0.5, 0.5}, {1, 0.5, 0.5}};

// An icosahedron subdivided `level` times, on the unit sphere.
SurfaceMeshInput icosphere(int level) {
  SurfaceMeshInput s;
  const double g = (1 + std::sqrt(5.0)) / 2;
  auto push = [&s](Point3 p) {
    const double l = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    s.vertices.push_back({p[0] / l, p[1] / l, p[2] / l});
    return s.vertices.size() - 1;
  };
  for (double a : {-1.0, 1.0})
    for (double b : {-g, g}) {
      push({a, b, 0});
      push({0, a, b});
      push({b, 0, a});
    }
  // The 20 faces: triples of mutually adjacent vertices (edge length 2 before scaling).
  const double edge = 2 / std::sqrt(1 + g * g);
  for (std::size_t i = 0; i < 12; ++i)
    for (std::size_t j = i + 1; j < 12; ++j)
      for (std::size_t k = j + 1; k < 12; ++k)
        if (std::fabs(dist(s.vertices[i], s.vertices[j]) - edge) < 1e-9 &&
            std::fabs(dist(s.vertices[j], s.vertices[k]) - edge) < 1e-9 &&
            std::fabs(dist(s.vertices[i], s.vertices[k]) - edge) < 1e-9)
          s.triangles.push_back({i, j, k});
  for (int l = 0; l < level; ++l) {
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> mid;
    auto midpoint = [&](std::size_t a, std::size_t b) {
      const auto key = std::minmax(a, b);
      const auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      const Point3 &p = s.vertices[a], &q = s.vertices[b];
      return mid[key] = push({p[0] + q[0], p[1] + q[1], p[2] + q[2]});
    };
    std::vector<std::array<std::size_t, 3>> next;
    for (const auto& t : s.triangles) {
      const std::size_t a = midpoint(t[0], t[1]), b = midpoint(t[1], t[2]), c = midpoint(t[2], t[0]);
      next.push_back({t[0], a, c});
      next.push_back({t[1], b, a});
      next.push_back({t[2], c, b});
      next.push_back({a, b, c});
    }
    s.triangles = next;
  }
  return s;
}

// Disks at all vertices of an icosphere: r a bit above the largest circumradius (every
// triangle is acute, so its points are within its circumradius of a corner) and below
// the shortest edge (no conflicts).
struct VertexPacking {
  SurfaceMeshInput mesh;
  Points3 centers;
  double r;
};
VertexPacking icosphere_packing(int level) {
  VertexPacking p{icosphere(level), {}, 0};
  p.centers = p.mesh.vertices;
  double shortest = 1e300, circum = 0;
  for (const auto& t : p.mesh.triangles) {
    const double a = dist(p.mesh.vertices[t[1]], p.mesh.vertices[t[2]]);
    const double b = dist(p.mesh.vertices[t[0]], p.mesh.vertices[t[2]]);
    const double c = dist(p.mesh.vertices[t[0]], p.mesh.vertices[t[1]]);
    shortest = std::min({shortest, a, b, c});
    const double s = (a + b + c) / 2;
    const double area = std::sqrt(s * (s - a) * (s - b) * (s - c));
    circum = std::max(circum, a * b * c / (4 * area));
    EXPECT_LT(a * a, b * b + c * c);  // acute
    EXPECT_LT(b * b, a * a + c * c);
    EXPECT_LT(c * c, a * a + b * b);
  }
  p.r = circum * 1.01;
  EXPECT_LT(p.r * 1.01, shortest) << "the layout does not have the property the tests assume";
  return p;
}

std::size_t nearest_index(const Points3& c, const Point3& q) {
  std::size_t best = 0;
  for (std::size_t k = 1; k < c.size(); ++k)
    if (dist(c[k], q) < dist(c[best], q)) best = k;
  return best;
}

TEST(SurfaceOracle, HexLatticeOnFlatSquarePasses) {
  for (const double s : {1.0, 1.2})
    for (const int m : {1, 8})
      for (const bool tilted : {false, true}) {
        SurfaceMeshInput mesh = square(4 * s, m);
        Points3 c = hex(s, 4 * s);
        if (tilted) tilt_all(mesh, c);
        const SurfaceReport rep = check_surface(mesh, c, 1.0);
        SCOPED_TRACE("s=" + std::to_string(s) + " m=" + std::to_string(m) +
                     (tilted ? " tilted" : " flat"));
        EXPECT_TRUE(rep.ok()) << rep.summary();
        EXPECT_TRUE(rep.on_surface() && rep.conflict_free() && rep.maximal());
        EXPECT_FALSE(rep.boundary_checked);
        EXPECT_EQ(rep.triangles, std::size_t(2 * m * m));
        EXPECT_EQ(rep.boundary_edges, std::size_t(4 * m));
        EXPECT_NEAR(rep.min_distance, s, 1e-9);
        EXPECT_GT(rep.candidates, 0u);
        EXPECT_EQ(rep.probes, std::size_t(2 * m * m * 9 + (3 * m * m + 2 * m)));
        EXPECT_LE(rep.max_probe_gap, 0.734 * s);
        EXPECT_GT(rep.max_probe_gap, 0.3 * s);
        EXPECT_TRUE(mentions(rep.summary(), "Uncovered: 0")) << rep.summary();
      }
}

TEST(SurfaceOracle, RemovingAnInteriorDiskLeavesAVoid) {
  // Spacing 1.2: the removed center is 1.2 > r from its six neighbours. The void
  // reaches 0.2 from it towards a neighbour and 1.2*cos(30 deg) - sqrt(1 - 0.6^2) =
  // 0.239 between two (where their circles cross). With m = 1 the diagonal of the
  // square passes 0.228 from the hole: the void straddles an edge.
  for (const int m : {1, 8})
    for (const bool tilted : {false, true})
      for (const std::size_t probes : {std::size_t{0}, std::size_t{8}}) {
        SurfaceMeshInput mesh = square(4.8, m);
        Points3 c = hex(1.2, 4.8);
        const std::size_t gone = nearest_index(c, {2.4, 2.1, 0});
        Point3 hole = c[gone];
        EXPECT_NEAR(hole[0], 2.4, 1e-12);
        c.erase(c.begin() + static_cast<long>(gone));
        if (tilted) {
          tilt_all(mesh, c);
          hole = tilt(hole);
        }
        SurfaceOptions opt;
        opt.probes_per_triangle = probes;
        const SurfaceReport rep = check_surface(mesh, c, 1.0, opt);
        SCOPED_TRACE("m=" + std::to_string(m) + (tilted ? " tilted" : " flat"));
        EXPECT_FALSE(rep.maximal()) << rep.summary();
        EXPECT_FALSE(rep.ok());
        EXPECT_TRUE(rep.on_surface() && rep.conflict_free()) << rep.summary();
        bool crossing = false;
        for (const auto& u : rep.uncovered) {
          EXPECT_LE(dist({u.x, u.y, u.z}, hole), 0.24) << u.why;
          crossing |= mentions(u.why, "cross at a point no third disk covers");
          EXPECT_TRUE(mentions(u.why, "triangle " + std::to_string(u.triangle) + ":")) << u.why;
        }
        EXPECT_TRUE(crossing) << "the exact part alone must find the void";
      }
}

TEST(SurfaceOracle, FindsVoidOnTheRimWithoutProbes) {
  // Without the disk at (2.4, 0) a void opens on the bottom edge: its corners there are
  // where the circles of (1.2, 0) and (3.6, 0) cross it, x = 2.2 and 2.6, which are
  // sqrt(0.4^2 + 1.08) = 1.11 > r from (1.8, 1.039) and (3, 1.039). (The interior
  // mesh edges through the void have such witnesses too.)
  for (const bool tilted : {false, true}) {
    SurfaceMeshInput mesh = square(4.8, 8);
    Points3 c = hex(1.2, 4.8);
    c.erase(c.begin() + static_cast<long>(nearest_index(c, {2.4, 0, 0})));
    if (tilted) tilt_all(mesh, c);
    SurfaceOptions opt;
    opt.probes_per_triangle = 0;
    const SurfaceReport rep = check_surface(mesh, c, 1.0, opt);
    EXPECT_FALSE(rep.maximal()) << rep.summary();
    int on_edge = 0;
    for (const auto& u : rep.uncovered) {
      const Point3 at = tilted ? tilt({2.4, 0, 0}) : Point3{2.4, 0, 0};
      EXPECT_LE(dist({u.x, u.y, u.z}, at), 0.25) << u.why;
      // The bottom edge's mesh edges there: vertices 3 (1.8, 0), 4 (2.4, 0), 5 (3, 0).
      if (mentions(u.why, "crosses edge (3, 4) at a point no other disk covers") ||
          mentions(u.why, "crosses edge (4, 5) at a point no other disk covers")) {
        ++on_edge;
        EXPECT_NEAR(dist({u.x, u.y, u.z}, at), 0.2, 1e-9) << u.why;
      }
    }
    EXPECT_EQ(on_edge, 2) << rep.summary();
  }
}

TEST(SurfaceOracle, RemovingADiskFromTheTightLatticeStaysCovered) {
  // Spacing r: the removed center is exactly r from six neighbours, and every point
  // near it is strictly inside one of them (a closed cover: degenerate, but maximal).
  for (const bool tilted : {false, true}) {
    SurfaceMeshInput mesh = square(4, 8);
    Points3 c = hex(1.0, 4);
    c.erase(c.begin() + static_cast<long>(nearest_index(c, {2, 1.8, 0})));
    if (tilted) tilt_all(mesh, c);
    const SurfaceReport rep = check_surface(mesh, c, 1.0);
    EXPECT_TRUE(rep.ok()) << rep.summary();
  }
}

TEST(SurfaceOracle, FindsConflict) {
  for (const bool tilted : {false, true}) {
    SurfaceMeshInput mesh = square(4.8, 8);
    Points3 c = hex(1.2, 4.8);
    const std::size_t i = nearest_index(c, {2.4, 2.1, 0});
    const std::size_t j = nearest_index(c, {3.6, 2.1, 0});  // its right neighbour
    c[j] = {c[i][0] + 0.5, c[i][1], 0};
    if (tilted) tilt_all(mesh, c);
    const SurfaceReport rep = check_surface(mesh, c, 1.0);
    EXPECT_FALSE(rep.conflict_free()) << rep.summary();
    EXPECT_FALSE(rep.ok());
    ASSERT_EQ(rep.conflict_count, 1u) << rep.summary();  // others are >= 1.04 from j
    EXPECT_EQ(rep.conflicts[0].i, std::min(i, j));
    EXPECT_EQ(rep.conflicts[0].j, std::max(i, j));
    EXPECT_NEAR(rep.conflicts[0].distance, 0.5, 1e-12);
    EXPECT_NEAR(rep.min_distance, 0.5, 1e-12);
    EXPECT_EQ(rep.covered_center_count, 0u);
    EXPECT_TRUE(rep.on_surface()) << rep.summary();
    EXPECT_TRUE(mentions(rep.summary(), "Conflicts: 1")) << rep.summary();
  }
}

TEST(SurfaceOracle, CoveredCenterWithVaryingRadiiIsNoConflict) {
  const SurfaceMeshInput mesh = square(4, 2);
  const Points3 c{{1, 1, 0}, {1.75, 1, 0}, {3, 3, 0}};
  SurfaceOptions opt;
  opt.maximality = false;
  SurfaceReport rep = check_surface(mesh, c, {1.0, 0.5, 1.0}, opt);
  EXPECT_TRUE(rep.ok()) << rep.summary();
  EXPECT_FALSE(rep.maximality_checked);
  EXPECT_FALSE(rep.maximal());
  EXPECT_EQ(rep.covered_center_count, 1u);
  EXPECT_DOUBLE_EQ(rep.r_min, 0.5);
  EXPECT_DOUBLE_EQ(rep.r, 1.0);
  // The smaller disk at 0.4: it covers the larger one's center, a conflict.
  rep = check_surface(mesh, {{1, 1, 0}, {1.4, 1, 0}}, {1.0, 0.5}, opt);
  EXPECT_EQ(rep.conflict_count, 1u) << rep.summary();
}

TEST(SurfaceOracle, FindsCenterOffTheSurface) {
  for (const bool tilted : {false, true}) {
    SurfaceMeshInput mesh = square(4.8, 8);
    Points3 c = hex(1.2, 4.8);
    const std::size_t i = nearest_index(c, {2.4, 2.1, 0});
    SurfaceOptions opt;
    opt.maximality = false;  // lifted, the disk still covers about the same
    for (const double lift : {0.01, 2e-6, 0.5e-6}) {
      Points3 moved = c;
      moved[i][2] = lift;
      SurfaceMeshInput m2 = mesh;
      if (tilted) tilt_all(m2, moved);
      const SurfaceReport rep = check_surface(m2, moved, 1.0, opt);
      if (lift < 1e-6) {
        EXPECT_TRUE(rep.ok()) << rep.summary();  // within r*tol
        continue;
      }
      EXPECT_FALSE(rep.on_surface()) << rep.summary();
      EXPECT_FALSE(rep.ok());
      ASSERT_EQ(rep.off_surface_count, 1u) << rep.summary();
      EXPECT_EQ(rep.off_surface[0].i, i);
      EXPECT_NEAR(rep.off_surface[0].distance, lift, 1e-12);
      EXPECT_TRUE(rep.conflict_free());
    }
    // Beside the square (in its plane): the distance is to the nearest edge.
    Points3 out = c;
    out.push_back({5.8, 2.4, 0});
    SurfaceMeshInput m3 = mesh;
    if (tilted) tilt_all(m3, out);
    const SurfaceReport rep = check_surface(m3, out, 1.0, opt);
    ASSERT_EQ(rep.off_surface_count, 1u) << rep.summary();
    EXPECT_NEAR(rep.off_surface[0].distance, 1.0, 1e-12);
  }
}

TEST(SurfaceOracle, CubeWithCornerDisks) {
  // Corner disks on the unit cube: each face is covered by the balls of its 4 corners
  // iff r >= sqrt(1/2) (the face center is the farthest point); the far corners are
  // >= sqrt(1.5) from a face center. Pairs are >= 1 apart: no conflicts.
  const SurfaceMeshInput mesh = cube();
  const Points3 c = mesh.vertices;
  const SurfaceReport rep = check_surface(mesh, c, 0.71);
  EXPECT_TRUE(rep.ok()) << rep.summary();
  EXPECT_EQ(rep.boundary_edges, 0u);
  EXPECT_NEAR(rep.max_probe_gap, std::sqrt(0.5), 0.01);  // the face centers are probed
  EXPECT_DOUBLE_EQ(rep.min_distance, 1.0);

  for (const std::size_t probes : {std::size_t{0}, std::size_t{8}}) {
    SurfaceOptions opt;
    opt.probes_per_triangle = probes;
    const SurfaceReport bad = check_surface(mesh, c, 0.70, opt);
    EXPECT_FALSE(bad.maximal()) << bad.summary();
    EXPECT_TRUE(bad.on_surface() && bad.conflict_free());
    // Each face has a void around its center, of radius < 0.011 (adjacent corners'
    // circles cross at 0.01 from it).
    bool face_hit[6] = {};
    for (const auto& u : bad.uncovered) {
      bool near = false;
      for (int k = 0; k < 6; ++k)
        if (dist({u.x, u.y, u.z}, kFaceCenters[k]) < 0.011) near = face_hit[k] = true;
      EXPECT_TRUE(near) << u.why;
    }
    for (int k = 0; k < 6; ++k) EXPECT_TRUE(face_hit[k]) << "face " << k << ": " << bad.summary();
  }

  // Without the disk on corner 7 = (1, 1, 1): that corner is 1 > r from every center.
  Points3 c7(c.begin(), c.begin() + 7);
  SurfaceOptions opt;
  opt.probes_per_triangle = 0;
  const SurfaceReport gone = check_surface(mesh, c7, 0.71, opt);
  EXPECT_FALSE(gone.maximal()) << gone.summary();
  bool corner = false;
  for (const auto& u : gone.uncovered) {
    // The void reaches to where the circles of (1,0,1) and (0,1,1) cross on the top
    // face's diagonal: sqrt(1/2) - sqrt(0.71^2 - 1/2) = 0.64308 from the corner.
    EXPECT_LE(dist({u.x, u.y, u.z}, {1, 1, 1}), 0.64308) << u.why;
    corner |= mentions(u.why, ": corner ") && mentions(u.why, "(vertex 7) is covered by no disk");
  }
  EXPECT_TRUE(corner) << gone.summary();
}

TEST(SurfaceOracle, CubeWithNineDisksPerFace) {
  // Disks of r = 0.5 at the corners, edge midpoints and face centers (26): on each face
  // a 3x3 grid of spacing 0.5, every point within sqrt(1/8) of one; pairs >= 0.5 apart.
  // Many balls cross on the cube's edges (creases) and at the diagonals.
  const SurfaceMeshInput mesh = cube();
  Points3 c;
  for (int x = 0; x <= 2; ++x)
    for (int y = 0; y <= 2; ++y)
      for (int z = 0; z <= 2; ++z)
        if (x != 1 || y != 1 || z != 1) c.push_back({x / 2.0, y / 2.0, z / 2.0});
  ASSERT_EQ(c.size(), 26u);
  const SurfaceReport rep = check_surface(mesh, c, 0.5);
  EXPECT_TRUE(rep.ok()) << rep.summary();
  EXPECT_NEAR(rep.max_probe_gap, std::sqrt(0.125), 0.05);

  // Without a face center it stays covered (as with the tight hex lattice: the four
  // edge midpoints are exactly r from it and cover everything around it)...
  Points3 c2 = c;
  c2.erase(c2.begin() + static_cast<long>(nearest_index(c2, {0.5, 0.5, 0})));
  const SurfaceReport rep2 = check_surface(mesh, c2, 0.5);
  EXPECT_TRUE(rep2.ok()) << rep2.summary();
  // ... but not with a slightly smaller radius: the face center is then uncovered.
  const SurfaceReport rep3 = check_surface(mesh, c2, 0.49);
  EXPECT_FALSE(rep3.maximal()) << rep3.summary();
  for (const auto& u : rep3.uncovered) EXPECT_LE(dist({u.x, u.y, u.z}, {0.5, 0.5, 0}), 0.15) << u.why;
}

TEST(SurfaceOracle, DisksAtTheVerticesOfAnIcosphere) {
  const VertexPacking p = icosphere_packing(3);
  ASSERT_EQ(p.mesh.vertices.size(), 642u);
  ASSERT_EQ(p.mesh.triangles.size(), 1280u);
  const SurfaceReport rep = check_surface(p.mesh, p.centers, p.r);
  EXPECT_TRUE(rep.ok()) << rep.summary();
  EXPECT_EQ(rep.boundary_edges, 0u);
  EXPECT_LE(rep.max_probe_gap, p.r);

  // Without one vertex's disk that vertex is farther than r from every other center.
  Points3 c = p.centers;
  c.erase(c.begin() + 100);
  SurfaceOptions opt;
  opt.probes_per_triangle = 0;
  const SurfaceReport bad = check_surface(p.mesh, c, p.r, opt);
  EXPECT_FALSE(bad.maximal()) << bad.summary();
  EXPECT_TRUE(bad.on_surface() && bad.conflict_free());
  bool corner = false;
  for (const auto& u : bad.uncovered) {
    EXPECT_LE(dist({u.x, u.y, u.z}, p.centers[100]), p.r) << u.why;
    corner |= mentions(u.why, ": corner ") && mentions(u.why, "(vertex 100) is covered by no disk");
  }
  EXPECT_TRUE(corner) << bad.summary();

  // Below the largest circumradius, that triangle's circumcenter is uncovered (the
  // other vertices lie on the sphere beyond the triangle's plane: no nearer).
  const SurfaceReport shrunk = check_surface(p.mesh, p.centers, p.r / 1.01 * 0.99);
  EXPECT_FALSE(shrunk.maximal()) << shrunk.summary();
  EXPECT_TRUE(shrunk.conflict_free());
}

TEST(SurfaceOracle, BoundaryEdgesMustBeCoveredByFlaggedDisks) {
  // [0,4]^2 (open: its 32 outer mesh edges are boundary edges), disks of r = 1 on the
  // 25 integer points: every point within sqrt(1/2) of one, pairs >= 1 apart.
  const SurfaceMeshInput mesh = square(4, 8);
  Points3 c;
  for (int y = 0; y <= 4; ++y)
    for (int x = 0; x <= 4; ++x) c.push_back({double(x), double(y), 0});
  auto on_rim = [](const Point3& p) { return p[0] == 0 || p[0] == 4 || p[1] == 0 || p[1] == 4; };
  SurfaceOptions opt;
  for (const auto& p : c) opt.boundary_flags.push_back(on_rim(p));
  SurfaceReport rep = check_surface(mesh, c, 1.0, opt);
  EXPECT_TRUE(rep.ok()) << rep.summary();
  EXPECT_TRUE(rep.boundary_ok());
  EXPECT_EQ(rep.boundary_edges, 32u);
  EXPECT_EQ(rep.boundary_count, 16u);

  // Flags on the 9 interior disks only: the boundary is 1 from them (touched at single
  // points) and they are off the boundary.
  opt.boundary_flags.clear();
  for (const auto& p : c) opt.boundary_flags.push_back(!on_rim(p));
  rep = check_surface(mesh, c, 1.0, opt);
  EXPECT_FALSE(rep.boundary_ok()) << rep.summary();
  EXPECT_FALSE(rep.ok());
  EXPECT_TRUE(rep.maximal() && rep.conflict_free() && rep.on_surface());
  EXPECT_EQ(rep.off_boundary_count, 9u);
  EXPECT_GE(rep.boundary_gap_count, 32u);

  // The rim without (1,4), (2,4), (3,4): the top edge is covered by the flagged (0,4)
  // and (4,4) for x <= 1 and x >= 3 only: gaps on the 4 mesh edges between.
  opt.boundary_flags.clear();
  for (const auto& p : c) opt.boundary_flags.push_back(on_rim(p) && !(p[1] == 4 && p[0] > 0 && p[0] < 4));
  rep = check_surface(mesh, c, 1.0, opt);
  EXPECT_FALSE(rep.boundary_ok()) << rep.summary();
  EXPECT_EQ(rep.off_boundary_count, 0u);
  ASSERT_EQ(rep.boundary_gap_count, 4u) << rep.summary();
  double length = 0;
  for (const auto& g : rep.boundary_gaps) {
    EXPECT_NEAR(g.y, 4, 1e-12);
    EXPECT_GT(g.x, 1);
    EXPECT_LT(g.x, 3);
    length += (g.t1 - g.t0) * 0.5;
  }
  EXPECT_NEAR(length, 2, 1e-5);

  // A closed surface has no boundary edges: a flagged disk is off the boundary.
  const SurfaceMeshInput box = cube();
  SurfaceOptions cube_opt;
  cube_opt.boundary_flags.assign(8, 0);
  cube_opt.boundary_flags[3] = 1;
  const SurfaceReport closed = check_surface(box, box.vertices, 0.71, cube_opt);
  EXPECT_EQ(closed.boundary_edges, 0u);
  EXPECT_EQ(closed.boundary_gap_count, 0u);
  EXPECT_EQ(closed.off_boundary_count, 1u) << closed.summary();
}

TEST(SurfaceOracle, DegenerateTrianglesAreSegments) {
  // The square plus a zero-area triangle along its bottom edge (a sliver) and one with a
  // repeated vertex: still valid, and the sliver's corners and edges are checked.
  SurfaceMeshInput mesh = square(4.8, 2);
  Points3 c = hex(1.2, 4.8);
  mesh.vertices.push_back({1.0, 0, 0});
  const std::size_t v = mesh.vertices.size() - 1;
  mesh.triangles.push_back({0, v, 1});
  mesh.triangles.push_back({0, 0, 1});
  EXPECT_TRUE(check_surface(mesh, c, 1.0).ok()) << check_surface(mesh, c, 1.0).summary();
  // A sliver sticking out 0.1 beyond the square's corner (0,0) along x: still within r.
  // 1.5 out it is not covered.
  for (const double out : {0.1, 1.5}) {
    SurfaceMeshInput m2 = mesh;
    m2.vertices.push_back({-out, 0, 0});
    m2.triangles.push_back({m2.vertices.size() - 1, v, 0});
    const SurfaceReport rep = check_surface(m2, c, 1.0);
    EXPECT_EQ(rep.maximal(), out < 1) << rep.summary();
  }
}

TEST(SurfaceOracle, RejectsBadInput) {
  const SurfaceMeshInput mesh = square(1, 1);
  const Points3 c{{0.5, 0.5, 0}};
  EXPECT_THROW(check_surface(mesh, c, 0.0), std::invalid_argument);
  EXPECT_THROW(check_surface(mesh, c, -1.0), std::invalid_argument);
  EXPECT_THROW(check_surface(mesh, c, std::nan("")), std::invalid_argument);
  EXPECT_THROW(check_surface(mesh, c, std::vector<double>{1, 1}), std::invalid_argument);
  EXPECT_THROW(check_surface(mesh, {{0.5, std::nan(""), 0}}, 1.0), std::invalid_argument);
  EXPECT_THROW(check_surface(mesh, {{0.5, 1 / 0.0, 0}}, 1.0), std::invalid_argument);
  SurfaceMeshInput bad = mesh;
  bad.triangles.push_back({0, 1, 4});
  EXPECT_THROW(check_surface(bad, c, 1.0), std::invalid_argument);
  bad = mesh;
  bad.vertices[2][1] = std::nan("");
  EXPECT_THROW(check_surface(bad, c, 1.0), std::invalid_argument);
  EXPECT_THROW(check_surface(SurfaceMeshInput{mesh.vertices, {}}, c, 1.0), std::invalid_argument);
  SurfaceOptions opt;
  opt.tol = 1;
  EXPECT_THROW(check_surface(mesh, c, 1.0, opt), std::invalid_argument);
  opt.tol = -1e-9;
  EXPECT_THROW(check_surface(mesh, c, 1.0, opt), std::invalid_argument);
  opt = {};
  opt.boundary_flags = {1, 0};
  EXPECT_THROW(check_surface(mesh, c, 1.0, opt), std::invalid_argument);
  // No disks: valid input, not maximal.
  const SurfaceReport empty = check_surface(mesh, {}, 1.0);
  EXPECT_FALSE(empty.maximal());
  EXPECT_TRUE(empty.on_surface() && empty.conflict_free());
  EXPECT_EQ(empty.max_probe_gap, std::numeric_limits<double>::infinity());
}

TEST(SurfaceOracle, UnrunChecksReadAsFalse) {
  const SurfaceMeshInput mesh = cube();
  SurfaceOptions opt;
  opt.on_surface = opt.conflicts = opt.maximality = false;
  const SurfaceReport rep = check_surface(mesh, mesh.vertices, 0.71, opt);
  EXPECT_FALSE(rep.ok());  // nothing was checked
  EXPECT_FALSE(rep.on_surface() || rep.conflict_free() || rep.maximal() || rep.boundary_ok());
  EXPECT_TRUE(mentions(rep.summary(), "not checked")) << rep.summary();
}

TEST(SurfaceOracle, FastEnoughForThousandsOfDisks) {
  // About 5000 disks on 5000 triangles (flat), and 2562 on 5120 (the icosphere).
  // (80.4 = 67 spacings: the rows end on the right edge; the top row is 0.38 below it.)
  SurfaceMeshInput mesh = square(80.4, 50);
  Points3 c = hex(1.2, 80.4);
  tilt_all(mesh, c);
  auto t0 = std::chrono::steady_clock::now();
  const SurfaceReport rep = check_surface(mesh, c, 1.0);
  const double flat = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_TRUE(rep.ok()) << rep.summary();
  EXPECT_GT(rep.n, 5000u);
  EXPECT_EQ(rep.triangles, 5000u);

  const VertexPacking p = icosphere_packing(4);
  t0 = std::chrono::steady_clock::now();
  const SurfaceReport sphere = check_surface(p.mesh, p.centers, p.r);
  const double curved = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_TRUE(sphere.ok()) << sphere.summary();
  std::cout << "surface oracle: " << rep.n << " disks on " << rep.triangles << " triangles in "
            << flat << " s; " << sphere.n << " on " << sphere.triangles << " in " << curved
            << " s\n";
  EXPECT_LT(flat, 20.0);  // generous: Debug builds and busy machines
}

}  // namespace
