// SPDX-License-Identifier: GPL-3.0-or-later
// Surface domains: the data files' topology, an independent genus by Gauss-Bonnet, the
// readers and adapters agreeing, and each kind of invalid surface named in its error.
// GCC 12 warns inside OpenMesh's property vectors (VectorT's default constructor leaves
// its elements unset on purpose): a false positive from inlined library code.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>

#include "disktune/cgal/surface_from_cgal.h"
#include "disktune/openmesh/surface_from_openmesh.h"
#include "disktune/surface_domain.h"
#include "disktune/surface_tuning.h"
#include "surface_checks.h"
#include "test_util.h"

namespace disktune {
namespace {

using test::message_of;
using test::TempDir;
using Tris = std::vector<SurfaceDomain::Triangle>;

std::string data(const std::string& name) {
  return std::string(DISKTUNE_DATA_DIR) + "/surfaces/" + name;
}

void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// Euler characteristic from angles, not counts (Gauss-Bonnet for polyhedra): the angle
// defects 2pi - sum at inner vertices and pi - sum at boundary vertices add to 2pi chi.
double gauss_bonnet_chi(const SurfaceDomain& s) {
  const auto& p = s.vertices();
  std::vector<double> angle_sum(p.size(), 0);
  for (const auto& t : s.triangles()) {
    for (int k = 0; k < 3; ++k) {
      const Vec3 u = p[t[(k + 1) % 3]] - p[t[k]], v = p[t[(k + 2) % 3]] - p[t[k]];
      angle_sum[t[k]] += std::atan2(norm(cross(u, v)), dot(u, v));
    }
  }
  std::vector<char> on_border(p.size(), 0);
  for (const auto& loop : s.boundary_loops()) {
    for (const std::size_t v : loop) on_border[v] = 1;
  }
  double total = 0;
  for (std::size_t v = 0; v < p.size(); ++v) {
    total += (on_border[v] ? M_PI : 2 * M_PI) - angle_sum[v];
  }
  return total / (2 * M_PI);
}

void expect_genus_by_angles(const SurfaceDomain& s) {
  ASSERT_EQ(s.component_count(), 1u);
  const double chi = gauss_bonnet_chi(s);
  const double genus = (2.0 - static_cast<double>(s.boundary_loops().size()) - chi) / 2;
  EXPECT_NEAR(genus, s.genus(), 1e-6);
}

// Triangles compared up to rotation (a mesh library may start a face at any corner).
Tris canonical(Tris tris) {
  for (auto& t : tris) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  return tris;
}

// rel: allowed coordinate difference relative to the bounding box diagonal.
void expect_same(const SurfaceDomain& a, const SurfaceDomain& b, double rel) {
  const double tol = rel * norm(b.bbox_max() - b.bbox_min());
  ASSERT_EQ(a.vertices().size(), b.vertices().size());
  for (std::size_t v = 0; v < a.vertices().size(); ++v) {
    EXPECT_LE(norm(a.vertices()[v] - b.vertices()[v]), tol) << "vertex " << v;
  }
  EXPECT_EQ(canonical(a.triangles()), canonical(b.triangles()));
  EXPECT_EQ(a.edge_count(), b.edge_count());
  EXPECT_EQ(a.boundary_loops(), b.boundary_loops());
  EXPECT_EQ(a.component_genus(), b.component_genus());
  EXPECT_NEAR(a.area(), b.area(), (1e-12 + 10 * rel) * b.area());
}

TEST(SurfaceDomainData, SphereIsClosedGenusZero) {
  const SurfaceDomain s = read_surface(data("sphere.off"));
  EXPECT_EQ(s.vertices().size(), 162u);
  EXPECT_EQ(s.triangles().size(), 320u);
  EXPECT_EQ(s.edge_count(), 480u);
  EXPECT_TRUE(s.is_closed());
  EXPECT_EQ(s.component_count(), 1u);
  EXPECT_EQ(s.genus(), 0);
  EXPECT_GT(s.area(), 0);
  EXPECT_LT(s.bbox_min().x, s.bbox_max().x);
  expect_genus_by_angles(s);
}

TEST(SurfaceDomainData, EightIsClosedGenusTwo) {
  const SurfaceDomain s = read_surface(data("eight.off"));
  EXPECT_EQ(s.vertices().size(), 315u);
  EXPECT_EQ(s.triangles().size(), 634u);
  EXPECT_TRUE(s.is_closed());
  EXPECT_EQ(s.genus(), 2);
  EXPECT_GT(s.area(), 0);
  expect_genus_by_angles(s);
}

TEST(SurfaceDomainData, MeshWithBorderHasBoundaryLoops) {
  const SurfaceDomain s = read_surface(data("mesh_with_border.off"));
  EXPECT_EQ(s.vertices().size(), 548u);
  EXPECT_EQ(s.triangles().size(), 1014u);
  EXPECT_FALSE(s.is_closed());
  ASSERT_GE(s.boundary_loops().size(), 1u);
  EXPECT_EQ(s.boundary_loops().size(), 1u);
  EXPECT_EQ(s.boundary_loops()[0].size(), 80u);
  EXPECT_EQ(s.edge_count(), 1561u);
  EXPECT_EQ(s.genus(), 0);
  EXPECT_GT(s.area(), 0);
  // Each step of a loop is an edge a->b of a triangle (the surface on its left), and of
  // no triangle the other way.
  std::set<std::pair<std::size_t, std::size_t>> directed;
  for (const auto& t : s.triangles()) {
    for (int k = 0; k < 3; ++k) directed.insert({t[k], t[(k + 1) % 3]});
  }
  for (const auto& loop : s.boundary_loops()) {
    ASSERT_GE(loop.size(), 3u);
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const std::size_t a = loop[i], b = loop[(i + 1) % loop.size()];
      EXPECT_TRUE(directed.count({a, b})) << a << "->" << b;
      EXPECT_FALSE(directed.count({b, a})) << b << "->" << a;
    }
  }
  expect_genus_by_angles(s);
}

const char* tetrahedron_off =
    "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";

TEST(SurfaceDomainRead, OffStartingWithACommentReadsWithReadSurfaceNotOpenMesh) {
  TempDir dir;
  write(dir.file("t.off"), std::string("# a tetrahedron\n") + tetrahedron_off);
  const SurfaceDomain s = read_surface(dir.file("t.off"));
  EXPECT_EQ(s.vertices().size(), 4u);
  EXPECT_EQ(s.edge_count(), 6u);
  EXPECT_EQ(s.genus(), 0);
  EXPECT_NEAR(s.area(), 1.5 + std::sqrt(3.0) / 2, 1e-12);
  const std::string msg = message_of<IoError>([&] { read_surface_openmesh(dir.file("t.off")); });
  EXPECT_NE(msg.find("'#' comment"), std::string::npos) << msg;
  EXPECT_NE(msg.find("read_surface"), std::string::npos) << msg;
}

TEST(SurfaceDomainRead, StlCornersAreMergedAndFacesOriented) {
  TempDir dir;
  // A tetrahedron with one facet turned the wrong way: the reader makes it agree.
  const char* facets[4][3] = {{"0 0 0", "0 1 0", "1 0 0"},
                              {"0 0 0", "1 0 0", "0 0 1"},
                              {"1 0 0", "0 0 1", "0 1 0"},  // flipped
                              {"0 0 0", "0 0 1", "0 1 0"}};
  std::string stl = "solid t\n";
  for (const auto& f : facets) {
    stl += "facet normal 0 0 0\nouter loop\n";
    for (const char* v : f) stl += std::string("vertex ") + v + "\n";
    stl += "endloop\nendfacet\n";
  }
  write(dir.file("t.stl"), stl + "endsolid t\n");
  const SurfaceDomain s = read_surface(dir.file("t.stl"));
  EXPECT_EQ(s.vertices().size(), 4u);
  EXPECT_EQ(s.triangles().size(), 4u);
  EXPECT_TRUE(s.is_closed());
  EXPECT_EQ(s.genus(), 0);
}

TEST(SurfaceDomainRead, QuadFaceIsNamed) {
  TempDir dir;
  write(dir.file("q.off"), "OFF\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 0 0\n3 0 1 3\n4 1 4 2 3\n");
  const std::string msg = message_of([&] { read_surface(dir.file("q.off")); });
  EXPECT_NE(msg.find("face 1"), std::string::npos) << msg;
  EXPECT_NE(msg.find("4 corners"), std::string::npos) << msg;
  const std::string om = message_of([&] { read_surface_openmesh(dir.file("q.off")); });
  EXPECT_NE(om.find("face 1"), std::string::npos) << om;
}

const std::vector<Vec3> five = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};

TEST(SurfaceDomainErrors, NonManifoldEdge) {
  const std::string msg =
      message_of([] { SurfaceDomain(five, Tris{{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}); });
  EXPECT_NE(msg.find("3 triangles (0, 1, 2)"), std::string::npos) << msg;
  EXPECT_NE(msg.find("vertex 0 (0, 0, 0)"), std::string::npos) << msg;
  EXPECT_NE(msg.find("vertex 1 (1, 0, 0)"), std::string::npos) << msg;
}

TEST(SurfaceDomainErrors, DegenerateTriangle) {
  const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}};
  const std::string msg = message_of([&] { SurfaceDomain(p, Tris{{0, 1, 2}, {1, 0, 3}}); });
  EXPECT_NE(msg.find("triangle 1"), std::string::npos) << msg;
  EXPECT_NE(msg.find("zero area"), std::string::npos) << msg;
  const std::string repeated = message_of([&] { SurfaceDomain(p, Tris{{0, 1, 1}}); });
  EXPECT_NE(repeated.find("triangle 0"), std::string::npos) << repeated;
}

TEST(SurfaceDomainErrors, InconsistentOrientation) {
  const std::string msg = message_of([] { SurfaceDomain(five, Tris{{0, 1, 2}, {0, 1, 3}}); });
  EXPECT_NE(msg.find("triangles 0 and 1"), std::string::npos) << msg;
  EXPECT_NE(msg.find("not consistently oriented"), std::string::npos) << msg;
}

TEST(SurfaceDomainErrors, BowTieVertex) {
  const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}};
  const std::string msg = message_of([&] { SurfaceDomain(p, Tris{{0, 1, 2}, {0, 3, 4}}); });
  EXPECT_NE(msg.find("vertex 0 (0, 0, 0)"), std::string::npos) << msg;
  EXPECT_NE(msg.find("bow-tie"), std::string::npos) << msg;
}

TEST(SurfaceDomainErrors, BadIndexUnusedVertexAndNoTriangles) {
  EXPECT_NE(message_of([] { SurfaceDomain(five, Tris{{0, 1, 7}}); }).find("vertex 7"),
            std::string::npos);
  EXPECT_NE(message_of([] { SurfaceDomain(five, Tris{{0, 1, 2}}); }).find("vertex 3"),
            std::string::npos);
  EXPECT_NE(message_of([] { SurfaceDomain(five, Tris{}); }).find("no triangles"),
            std::string::npos);
}

TEST(SurfaceDomainAdapters, CgalAndOpenMeshAgreeWithReadSurface) {
  for (const char* name : {"eight.off", "mesh_with_border.off"}) {
    SCOPED_TRACE(name);
    const SurfaceDomain ref = read_surface(data(name));

    CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> sm;
    ASSERT_TRUE(CGAL::IO::read_polygon_mesh(data(name), sm));
    {
      SCOPED_TRACE("CGAL Surface_mesh");
      expect_same(surface_domain_from(sm), ref, 0);
    }

    OpenMesh::TriMesh_ArrayKernelT<> om;  // float points: compared with a tolerance
    ASSERT_TRUE(OpenMesh::IO::read_mesh(om, data(name)));
    {
      SCOPED_TRACE("OpenMesh TriMesh");
      expect_same(surface_domain_from(om), ref, 1e-6);
    }
    SCOPED_TRACE("read_surface_openmesh");
    expect_same(read_surface_openmesh(data(name)), ref, 1e-6);  // OFF parsed as float
  }
}

// The algorithms see only the SurfaceDomain: a CGAL Surface_mesh and an OpenMesh
// TriMesh, read from the same file, give packings the oracle accepts, and the CGAL
// adapter (same coordinates) gives the very sample read_surface does.
TEST(SurfaceDomainAdapters, SamplingRunsOnEitherMesh) {
  const auto ref = std::make_shared<const SurfaceDomain>(read_surface(data("eight.off")));
  CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> sm;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(data("eight.off"), sm));
  OpenMesh::TriMesh_ArrayKernelT<> om;
  ASSERT_TRUE(OpenMesh::IO::read_mesh(om, data("eight.off")));
  const auto from_cgal = std::make_shared<const SurfaceDomain>(surface_domain_from(sm));
  const auto from_openmesh = std::make_shared<const SurfaceDomain>(surface_domain_from(om));
  Rng a(3), b(3), c(3);
  const SurfacePacking p = sample_mps(ref, SurfaceSizing::constant(0.05), a);
  const SurfacePacking q = sample_mps(from_cgal, SurfaceSizing::constant(0.05), b);
  const SurfacePacking o = sample_mps(from_openmesh, SurfaceSizing::constant(0.05), c);
  ASSERT_EQ(p.size(), q.size());
  for (const DiskId id : p.ids()) EXPECT_EQ(p.center(id), q.center(id));
  EXPECT_SURFACE_OK(o);
  EXPECT_GT(o.size(), 100u);
}

}  // namespace
}  // namespace disktune
