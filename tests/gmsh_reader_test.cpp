// SPDX-License-Identifier: GPL-3.0-or-later
// The .msh files read back by Gmsh's own reader (its C++ API), an oracle independent of
// disktune's writers: surface and planar meshes (mesh_io.h) and the fiber RVE's
// (rve_mesh.h). A test program of its own: linking Gmsh loads some ninety libraries at
// every start (0.14 s), which the main test program, one process per test, would pay
// hundreds of times.
#include <gmsh.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "disktune/boundary.h"
#include "disktune/mesh_io.h"
#include "disktune/planar_domain.h"
#include "disktune/rve.h"
#include "disktune/rve_mesh.h"
#include "disktune/sampling.h"
#include "disktune/surface_mesh.h"
#include "test_util.h"

namespace disktune {
namespace {

Rve make(double vf, std::uint64_t seed) {
  RveSpec spec;
  spec.width = spec.height = 8;
  spec.diameter = 1;
  spec.gap = 0.05;
  spec.fiber_fraction = vf;
  spec.seed = seed;
  return make_rve(spec);
}

SurfaceMesh tetrahedron() {
  SurfaceMesh m{{{0, 0, 0}, {1, 0, 1.0 / 3}, {0, 1, 0}, {0, 0, 1.0 / 7}},
                {{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}}};
  m.feature_edges = {{0, 1}, {1, 2}};
  return m;
}

using test::TempDir;

// Gmsh, quiet, for the life of a test.
struct GmshSession {
  GmshSession() {
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", 0);
  }
  ~GmshSession() { gmsh::finalize(); }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
};

TEST(MeshIo, GmshReadsTheMshBack) {
  TempDir dir;
  const SurfaceMesh tetra = tetrahedron();
  write_surface_mesh(dir.file("t.msh"), tetra);
  const GmshSession gmsh_session;
  ASSERT_NO_THROW(gmsh::open(dir.file("t.msh")));
  std::vector<std::size_t> tags;
  std::vector<double> xyz, parametric;
  gmsh::model::mesh::getNodes(tags, xyz, parametric);
  ASSERT_EQ(tags.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_EQ((Vec3{xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2]}), tetra.vertices[tags[k] - 1]);
  }
  std::vector<std::size_t> element_tags, nodes;
  gmsh::model::mesh::getElementsByType(2, element_tags, nodes);
  ASSERT_EQ(nodes.size(), 12u);
  for (std::size_t t = 0; t < 4; ++t)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(nodes[3 * t + k] - 1, tetra.triangles[t][k]);
  std::vector<std::size_t> line_tags, line_nodes;  // fresh: the call does not clear its outputs
  gmsh::model::mesh::getElementsByType(1, line_tags, line_nodes);
  EXPECT_EQ(line_nodes, (std::vector<std::size_t>{1, 2, 2, 3}));
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups);
  EXPECT_EQ(groups, (gmsh::vectorpair{{1, 2}, {2, 1}}));
  std::string name;
  gmsh::model::getPhysicalName(2, 1, name);
  EXPECT_EQ(name, "surface");
  gmsh::model::getPhysicalName(1, 2, name);
  EXPECT_EQ(name, "feature edges");
}

// A planar domain's mesh names its boundary loops: Gmsh finds each loop's edges, in
// order, in the physical group of its name (checked against the loops of disks the
// mesh was made from), and every triangle in "domain".
TEST(MeshIo, GmshFindsThePlanarBoundaryLoopsByName) {
  TempDir dir;
  const auto domain = std::make_shared<const PlanarDomain>(
      std::vector<Vec2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}},
      std::vector<std::vector<Vec2>>{{{0.2, 0.2}, {0.2, 0.4}, {0.4, 0.4}, {0.4, 0.2}},
                                     {{0.6, 0.6}, {0.6, 0.8}, {0.8, 0.8}, {0.8, 0.6}}});
  Rng rng(3);
  Packing packing = sample_mps(domain, 0.05, rng);
  const BoundaryLoops loops = boundary_loops(packing, *domain);
  const PlanarMesh mesh = constrained_delaunay(packing, loops);
  write_mesh(dir.file("p.msh"), mesh);
  const GmshSession gmsh_session;
  ASSERT_NO_THROW(gmsh::open(dir.file("p.msh")));
  std::vector<DiskId> disk_of_node(mesh.vertex_disk);  // node k + 1 is vertex k
  const char* names[] = {"outer boundary", "hole 1", "hole 2"};
  ASSERT_EQ(loops.size(), 3u);
  for (std::size_t k = 0; k < loops.size(); ++k) {
    SCOPED_TRACE(names[k]);
    std::string name;
    gmsh::model::getPhysicalName(1, static_cast<int>(k) + 2, name);
    EXPECT_EQ(name, names[k]);
    std::vector<int> curves;
    gmsh::model::getEntitiesForPhysicalGroup(1, static_cast<int>(k) + 2, curves);
    ASSERT_EQ(curves.size(), 1u);
    std::vector<std::size_t> tags, nodes;
    gmsh::model::mesh::getElementsByType(1, tags, nodes, curves[0]);
    ASSERT_EQ(nodes.size(), 2 * loops[k].size());
    for (std::size_t i = 0; i < loops[k].size(); ++i) {
      EXPECT_EQ(disk_of_node[nodes[2 * i] - 1], loops[k][i]);
      EXPECT_EQ(disk_of_node[nodes[2 * i + 1] - 1], loops[k][(i + 1) % loops[k].size()]);
    }
  }
  std::vector<int> surfaces;
  gmsh::model::getEntitiesForPhysicalGroup(2, 1, surfaces);
  ASSERT_EQ(surfaces.size(), 1u);
  std::vector<std::size_t> tags, nodes;
  gmsh::model::mesh::getElementsByType(2, tags, nodes, surfaces[0]);
  EXPECT_EQ(nodes.size(), 3 * mesh.triangles.size());
}

// The .msh read back by Gmsh itself: groups, periodic links and their node pairs.
TEST(RveMesh, GmshReadsTheMshBack) {
  const Rve rve = make(0.6, 3);
  const RveMesh mesh = mesh_rve(rve);
  const std::string path =
      (std::filesystem::temp_directory_path() / "disktune_rve_mesh_test.msh").string();
  write_rve_msh(path, mesh);
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::open(path);
  std::vector<std::size_t> node_tags;
  std::vector<double> xyz, parametric;
  gmsh::model::mesh::getNodes(node_tags, xyz, parametric);
  EXPECT_EQ(node_tags.size(), mesh.nodes.size());
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> tags, nodes;
  gmsh::model::mesh::getElements(types, tags, nodes, 2);
  std::size_t triangles = 0;
  for (const auto& t : tags) triangles += t.size();
  EXPECT_EQ(triangles, mesh.triangles.size());
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups);
  EXPECT_EQ(groups.size(), 7 + rve.centers.size());
  std::map<std::string, std::size_t> group_size;
  for (const auto& [dim, tag] : groups) {
    std::string name;
    gmsh::model::getPhysicalName(dim, tag, name);
    std::vector<std::size_t> in;
    std::vector<double> coords;
    gmsh::model::mesh::getNodesForPhysicalGroup(dim, tag, in, coords);
    group_size[name] = in.size();
  }
  EXPECT_EQ(group_size["corners"], 4u);
  EXPECT_EQ(group_size["left"], mesh.left.size() + 2);
  EXPECT_EQ(group_size["top"], mesh.top.size() + 2);
  EXPECT_EQ(group_size.count("fiber " + std::to_string(rve.centers.size())), 1u);
  // Right = left moved by W, top = bottom moved by H, node for node.
  for (const int copy : {2, 4}) {
    int master = 0;
    std::vector<std::size_t> copies, masters;
    std::vector<double> affine;
    gmsh::model::mesh::getPeriodicNodes(1, copy, master, copies, masters, affine);
    EXPECT_EQ(master, copy - 1);
    EXPECT_EQ(copies.size(), (copy == 2 ? mesh.left.size() : mesh.bottom.size()) + 2);
    for (std::size_t i = 0; i < copies.size(); ++i) {
      std::vector<double> a, b, param;
      gmsh::model::mesh::getNode(copies[i], a, param);
      gmsh::model::mesh::getNode(masters[i], b, param);
      EXPECT_EQ(a[0] - b[0], copy == 2 ? mesh.width : 0.0);
      EXPECT_EQ(a[1] - b[1], copy == 2 ? 0.0 : mesh.height);
    }
  }
  gmsh::finalize();
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace disktune
