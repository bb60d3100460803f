// SPDX-License-Identifier: GPL-3.0-or-later
// Quality of planar meshes with a boundary (domain meshes, the CVT reference), on
// lattice patches with known answers, and the CVT reference mesh checked by geometry.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "disktune/cvt_reference.h"
#include "disktune/errors.h"
#include "disktune/planar_domain.h"
#include "disktune/quality.h"

namespace disktune {
namespace {

/// An nx x ny patch of a lattice with cell vectors u, v, each cell cut into two
/// triangles along the diagonal u + v.
PlanarMesh lattice_patch(int nx, int ny, Vec2 u, Vec2 v) {
  PlanarMesh m;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      m.vertices.push_back(u * i + v * j);
      m.vertex_disk.push_back(kNoDisk);
    }
  auto at = [&](int i, int j) { return static_cast<std::uint32_t>(j * (nx + 1) + i); };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return m;
}

TEST(PlanarMeshQuality, HexPatchHasEquilateralTrianglesAndBetaOneOverSqrt3) {
  // u and v at 120 degrees: the diagonal u + v is a unit vector too, so every cell
  // splits into two equilateral triangles.
  const PlanarMesh m = lattice_patch(8, 8, {1, 0}, {-0.5, std::sqrt(3.0) / 2});
  const PlanarMeshQuality q = measure_planar_mesh(m, 1.0);
  EXPECT_EQ(q.vertex_count, 81u);
  EXPECT_EQ(q.triangle_count, 128u);
  EXPECT_EQ(q.interior_vertex_count, 49u);  // the 7 x 7 off the patch's boundary
  EXPECT_NEAR(q.angles.min, 60, 1e-9);
  EXPECT_NEAR(q.angles.max, 60, 1e-9);
  EXPECT_DOUBLE_EQ(q.angles.fraction_50_70, 1.0);
  EXPECT_NEAR(q.local_beta.min, 1 / std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(q.local_beta.max, 1 / std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(q.edges.min_over_r, 1, 1e-12);
  EXPECT_NEAR(q.edges.max_over_r, 1, 1e-12);
}

TEST(PlanarMeshQuality, SquarePatchHasRightTrianglesAndBetaOneOverSqrt2) {
  const PlanarMesh m = lattice_patch(5, 4, {0.5, 0}, {0, 0.5});
  const PlanarMeshQuality q = measure_planar_mesh(m, 0.5);
  EXPECT_EQ(q.interior_vertex_count, 12u);  // 4 x 3
  EXPECT_NEAR(q.angles.min, 45, 1e-9);
  EXPECT_NEAR(q.angles.max, 90, 1e-9);
  EXPECT_DOUBLE_EQ(q.angles.fraction_obtuse_triangles, 0.0);  // right is not obtuse
  EXPECT_NEAR(q.local_beta.mean, std::sqrt(0.5), 1e-12);     // circumradius sqrt2/2 a over a
  EXPECT_NEAR(q.edges.max_over_r, std::sqrt(2.0), 1e-12);
}

TEST(PlanarMeshQuality, RefusesAMeshWithoutTriangles) {
  PlanarMesh m;
  m.vertices = {{0, 0}, {1, 0}, {0, 1}};
  EXPECT_THROW(measure_planar_mesh(m, 1), InvalidInput);
}

TEST(CvtReference, TilesTheRectangleNearTheCountWithGoodAngles) {
  const Vec2 extent{2, 1};
  const CvtReference cvt = cvt_reference_mesh(extent, 600, 30);
  const PlanarMesh& m = cvt.mesh;
  EXPECT_NEAR(static_cast<double>(m.vertices.size()), 600, 0.05 * 600);
  double area = 0;
  for (const auto& t : m.triangles) {
    const double a = 0.5 * cross(m.vertices[t[1]] - m.vertices[t[0]], m.vertices[t[2]] - m.vertices[t[0]]);
    EXPECT_GT(a, 0);  // counterclockwise, not degenerate
    area += a;
  }
  EXPECT_NEAR(area, extent.x * extent.y, 1e-12);
  for (const Vec2 p : m.vertices) {
    EXPECT_GE(p.x, 0);
    EXPECT_LE(p.x, extent.x);
    EXPECT_GE(p.y, 0);
    EXPECT_LE(p.y, extent.y);
  }
  // Lloyd's cells are near-hexagonal: most angles within 10 degrees of 60.
  const PlanarMeshQuality q = measure_planar_mesh(m, 1);
  EXPECT_GT(q.angles.fraction_50_70, 0.6);
  EXPECT_GT(q.angles.min, 15);
}

TEST(CvtReference, RefusesBadArguments) {
  EXPECT_THROW(cvt_reference_mesh({0, 1}, 100), InvalidInput);
  EXPECT_THROW(cvt_reference_mesh({1, 1}, 3), InvalidInput);
  EXPECT_THROW(cvt_reference_mesh({1, 1}, 100, 0), InvalidInput);
}

// Even-odd ray casting over every loop: inside the outer loop and no hole.
bool inside_loops(const std::vector<std::vector<Vec2>>& loops, Vec2 p) {
  bool in = false;
  for (const auto& loop : loops)
    for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
      const Vec2 a = loop[i], b = loop[j];
      if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) in = !in;
    }
  return in;
}

// The CGAL reference a planar domain is compared with (docs/planar.md): Mesh_2 and Lloyd
// over the domain's loops, holes left out. Checked by plain geometry: the triangles tile
// exactly the domain's area (shoelace over the loops), each lies inside it, the count is
// near the one asked.
TEST(CvtReference, MeshesAPlanarDomainWithHolesNearTheCount) {
  const PlanarDomain d = read_poly(std::string(DISKTUNE_DATA_DIR) + "/domains/notch_and_holes.poly");
  ASSERT_GE(d.loops().size(), 2u);
  double area = 0;
  for (const auto& loop : d.loops())
    for (std::size_t i = 0; i < loop.size(); ++i) area += 0.5 * cross(loop[i], loop[(i + 1) % loop.size()]);
  const CvtReference cvt = cvt_reference_mesh(d, 2000, 20);
  const PlanarMesh& m = cvt.mesh;
  EXPECT_NEAR(static_cast<double>(m.vertices.size()), 2000, 0.05 * 2000);
  double covered = 0;
  for (const auto& t : m.triangles) {
    const Vec2 a = m.vertices[t[0]], b = m.vertices[t[1]], c = m.vertices[t[2]];
    const double ta = 0.5 * cross(b - a, c - a);
    EXPECT_GT(ta, 0);
    covered += ta;
    EXPECT_TRUE(inside_loops(d.loops(), (a + b + c) * (1.0 / 3)));
  }
  EXPECT_NEAR(covered, std::abs(area), 1e-9 * std::abs(area));
  EXPECT_THROW(cvt_reference_mesh(d, 7), InvalidInput);
}

}  // namespace
}  // namespace disktune
