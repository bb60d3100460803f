// SPDX-License-Identifier: GPL-3.0-or-later
// The library as a mesh generator uses it: the umbrella header, radius_for_count,
// remesh to an exact vertex count (judged by the independent surface oracle), tune as
// a transaction (cancelled or failing, the packing is as it was), and the CGAL and
// OpenMesh adapters.
#include <gtest/gtest.h>

// OpenMesh's PropertyT::push_back copies a default point it leaves uninitialized.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Surface_mesh.h>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "../src/geometry/threads.h"
#include "disktune/cgal/mesh_output.h"
#include "disktune/cgal/planar_domain_from_cdt.h"
#include "disktune/cgal/remesh.h"
#include "disktune/disktune.h"
#include "disktune/openmesh/remesh.h"
#include "oracle/mesh_topology.h"
#include "surface_checks.h"
#include "test_util.h"

namespace disktune {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalMesh = CGAL::Surface_mesh<Kernel::Point_3>;
using OpenMeshMesh = OpenMesh::TriMesh_ArrayKernelT<>;

// Everything that makes a packing's state: ids, centers, radii, flags.
template <class P>
std::vector<std::tuple<DiskId, double, double, double, double, int>> state_of(const P& packing) {
  std::vector<std::tuple<DiskId, double, double, double, double, int>> out;
  for (const DiskId id : packing.ids()) {
    double z = 0;
    if constexpr (std::is_same_v<P, SurfacePacking>) z = packing.center(id).z;
    out.emplace_back(id, packing.center(id).x, packing.center(id).y, z, packing.radius(id), packing.flags(id));
  }
  return out;
}

// One include gives every public header but the CGAL and OpenMesh adapters.
TEST(Umbrella, IncludesEveryPublicHeader) {
  const std::filesystem::path dir = std::filesystem::path(DISKTUNE_DATA_DIR) / ".." / "include" / "disktune";
  std::ifstream in(dir / "disktune.h");
  std::stringstream text;
  text << in.rdbuf();
  std::size_t headers = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (!entry.is_regular_file() || name == "disktune.h") continue;
    ++headers;
    EXPECT_NE(text.str().find("#include \"disktune/" + name + "\""), std::string::npos) << name;
  }
  EXPECT_GT(headers, 30u);
}

// The library's default thread count: one per core until set; a count given to a call
// wins; and what a call does on it does not depend on it.
TEST(Threads, TheDefaultIsOnePerCoreUntilSetAndChangesNoResult) {
  EXPECT_EQ(default_threads(), 0u);
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  EXPECT_EQ(detail::thread_count(0), cores);
  EXPECT_EQ(detail::thread_count(5), 5u);
  Rng rng(2);
  Packing p = sample_mps(PeriodicBox(1, 1), 0.01, rng);
  p.remove(p.ids()[4000]);
  const std::string on_every_core = packing_defect(p);
  set_default_threads(3);
  EXPECT_EQ(default_threads(), 3u);
  EXPECT_EQ(detail::thread_count(0), 3u);
  EXPECT_EQ(detail::thread_count(5), 5u);
  EXPECT_EQ(packing_defect(p), on_every_core);
  set_default_threads(1);
  EXPECT_EQ(packing_defect(p), on_every_core);
  set_default_threads(0);
  EXPECT_EQ(detail::thread_count(0), cores);
  EXPECT_NE(on_every_core.find("not maximal"), std::string::npos) << on_every_core;
}

TEST(RadiusForCount, AMaximalSampleAtThatRadiusHasAboutTheCount) {
  const PeriodicBox box(1.0, 1.0);
  for (const std::size_t n : {2000u, 20000u}) {
    Rng rng(n);
    const Packing mps = sample_mps(box, radius_for_count(n, box.area()), rng);
    EXPECT_NEAR(static_cast<double>(mps.size()) / n, 1.0, 0.02) << n;
  }
  const auto elephant = test::surface_file("elephant.off");
  for (const std::size_t n : {2000u, 8000u}) {
    Rng rng(n);
    const SurfacePacking mps =
        sample_mps(elephant, SurfaceSizing::constant(radius_for_count(n, elephant->area())), rng);
    EXPECT_NEAR(static_cast<double>(mps.size()) / n, 1.0, 0.05) << n;
  }
}

TEST(RadiusForCount, AtATargetsAreaFractionTuningGivesTheCount) {
  const double r = radius_for_count(5000, 2.0, 0.8);
  EXPECT_EQ(count_for_area_fraction(0.8, r, 2.0), 5000u);
  EXPECT_EQ(target_count(Target::area_fraction(0.8), r, 2.0), 5000u);
}

TEST(RadiusForCount, RefusesNonsense) {
  EXPECT_THROW(radius_for_count(0, 1.0), InvalidInput);
  EXPECT_THROW(radius_for_count(10, -1.0), InvalidInput);
  EXPECT_THROW(radius_for_count(10, std::nan("")), InvalidInput);
  EXPECT_THROW(radius_for_count(10, 1.0, 0.95), InvalidInput);
  EXPECT_THROW(radius_for_count(10, 1.0, 0.0), InvalidInput);
}

TEST(Remesh, GivesExactlyTheVertexCountAsAConflictFreeMaximalPacking) {
  const auto elephant = test::surface_file("elephant.off");
  for (const std::size_t n : {1500u, 4000u}) {
    RemeshOptions options;
    options.seed = n;
    const RemeshResult result = remesh(elephant, n, options);
    ASSERT_TRUE(result.tuning.reached) << n;
    ASSERT_EQ(result.mesh.vertices.size(), n);
    EXPECT_GT(result.mesh.triangles.size(), n);
    // The vertices, judged as a packing of radius result.radius by the oracle.
    std::vector<oracle::Point3> centers;
    for (const Vec3 v : result.mesh.vertices) centers.push_back({v.x, v.y, v.z});
    const oracle::SurfaceReport report =
        oracle::check_surface(test::oracle_surface(*elephant), centers, result.radius);
    EXPECT_TRUE(report.ok()) << report.summary();
    // And the area fraction asked for, with `n` disks of that radius (or a little more,
    // where the sample came out denser than the count).
    const double eta = area_fraction(n, result.radius, elephant->area());
    EXPECT_GE(eta, options.area_fraction * (1 - 1e-9));
    EXPECT_LE(eta, options.area_fraction * 1.1);
    // Every triangle names three distinct existing vertices.
    for (const auto& t : result.mesh.triangles) {
      for (const auto v : t) ASSERT_LT(v, n);
      EXPECT_TRUE(t[0] != t[1] && t[1] != t[2] && t[0] != t[2]);
    }
  }
}

// remesh moves disks after its first mesh (the angle-opening passes, with edge flips
// between their rounds): its mesh must still be the restricted Delaunay mesh of its
// vertices, made anew from them here, and the vertices where its disks ended.
TEST(Remesh, GivesTheRestrictedDelaunayMeshOfItsVertices) {
  const auto elephant = test::surface_file("elephant.off");
  for (const std::uint64_t seed : {1u, 2u}) {
    RemeshOptions options;
    options.seed = seed;
    options.feature_angle = 0;
    const RemeshResult result = remesh(elephant, 3000, options);
    const SurfaceMesh again = restricted_delaunay(result.mesh.vertices, *elephant);
    const auto sorted = [](std::vector<std::array<std::uint32_t, 3>> tris) {
      for (auto& t : tris) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
      std::sort(tris.begin(), tris.end());
      return tris;
    };
    EXPECT_EQ(sorted(result.mesh.triangles), sorted(again.triangles)) << "seed " << seed;
    // Each vertex on the input triangle its disk was last put on (the oracle's distance).
    const oracle::SurfaceMeshInput surface = test::oracle_surface(*elephant);
    ASSERT_EQ(result.input_triangles.size(), result.mesh.vertices.size());
    for (std::size_t i = 0; i < result.mesh.vertices.size(); ++i) {
      const oracle::SurfaceMeshInput one{surface.vertices,
                                         {surface.triangles[result.input_triangles[i]]}};
      const Vec3 v = result.mesh.vertices[i];
      ASSERT_LE(oracle::distance_to_surface(one, {v.x, v.y, v.z}), 1e-9)
          << "seed " << seed << ", vertex " << i;
    }
  }
}

// Sharp edges are kept by default (60 degrees, as the command line), none with angle 0:
// on fandisk the mesh then has edges along its feature curves, and a mesh's vertices on
// them lie on the input's sharp edges (checked by distance, apart from the library).
TEST(Remesh, KeepsSharpEdgesUnlessToldNot) {
  const auto fandisk = test::surface_file("fandisk.off");
  RemeshOptions options;
  const RemeshResult kept = remesh(fandisk, 3000, options);
  ASSERT_TRUE(kept.tuning.reached);
  EXPECT_GT(kept.mesh.feature_edges.size(), 100u);
  std::vector<std::array<Vec3, 2>> sharp;
  for (const MeshEdge& e : test::expected_features(*fandisk, 60))
    sharp.push_back({fandisk->vertices()[e[0]], fandisk->vertices()[e[1]]});
  const auto on_sharp_edge = [&](Vec3 p) {
    for (const auto& [a, b] : sharp) {
      const double t = std::clamp(dot(p - a, b - a) / squared_norm(b - a), 0.0, 1.0);
      if (norm(p - (a + (b - a) * t)) <= 1e-9) return true;
    }
    return false;
  };
  for (const auto& e : kept.mesh.feature_edges) {
    EXPECT_TRUE(on_sharp_edge(kept.mesh.vertices[e[0]]) && on_sharp_edge(kept.mesh.vertices[e[1]]));
  }
  options.feature_angle = 0;
  const RemeshResult plain = remesh(fandisk, 3000, options);
  ASSERT_TRUE(plain.tuning.reached);
  EXPECT_TRUE(plain.mesh.feature_edges.empty());
  options.feature_angle = 180;
  EXPECT_THROW(remesh(fandisk, 3000, options), InvalidInput);
  options.feature_angle = -1;
  EXPECT_THROW(remesh(fandisk, 3000, options), InvalidInput);
}

// At 650 vertices fandisk's radius (about 0.05) is more than 0.45 times the gap under
// its ledge (0.031): with one radius the mesh of some seeds has edges in three triangles
// (seeds 1-20: 10 at 650 vertices, 1 at 700 since the sample's ids follow a spatial
// order, 13 at 600).
// remesh then meshes again with smaller radii there (thickness sizing). Every seed's
// vertices are judged as a packing of their own radii by the oracle, every mesh's
// topology by the independent check, and the graded path must have been taken.
TEST(Remesh, WhereTheSurfaceIsThinnerThanTheRadiusTheMeshStaysAManifold) {
  const auto fandisk = test::surface_file("fandisk.off");
  SurfaceDomain features_on = *fandisk;  // remesh keeps the 60-degree features
  features_on.set_features(detect_features(features_on, {60, 60}));
  int graded = 0;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    RemeshOptions options;
    options.seed = seed;
    const RemeshResult r = remesh(fandisk, 650, options);
    ASSERT_TRUE(r.tuning.reached);
    ASSERT_EQ(r.mesh.vertices.size(), 650u);
    ASSERT_EQ(r.radii.size(), 650u);
    const oracle::SurfaceReport report = test::remesh_report(features_on, r);
    EXPECT_TRUE(report.ok()) << report.summary();
    std::vector<std::array<std::size_t, 3>> tris;
    for (const auto& t : r.mesh.triangles) tris.push_back({t[0], t[1], t[2]});
    const oracle::TopologyReport topology = oracle::check_topology(r.mesh.vertices.size(), tris);
    EXPECT_TRUE(topology.manifold() && topology.genus == 0 && topology.boundary_loops == 0) << topology.summary();
    if (!r.sizing.is_constant()) {
      ++graded;
      EXPECT_LT(*std::min_element(r.radii.begin(), r.radii.end()), 0.5 * r.radius);
    }
  }
  std::printf(
      "[ remesh ] fandisk, 650 vertices: %d of 10 seeds meshed again with smaller radii in thin "
      "parts\n",
      graded);
  EXPECT_GT(graded, 0);
}

TEST(Remesh, SameSeedSameMeshOtherSeedOtherMesh) {
  const auto sphere = test::surface_file("sphere.off");
  RemeshOptions options;
  options.seed = 5;
  const RemeshResult a = remesh(sphere, 600, options), b = remesh(sphere, 600, options);
  ASSERT_EQ(a.mesh.vertices.size(), b.mesh.vertices.size());
  for (std::size_t i = 0; i < a.mesh.vertices.size(); ++i) {
    EXPECT_EQ(a.mesh.vertices[i].x, b.mesh.vertices[i].x);
    EXPECT_EQ(a.mesh.vertices[i].z, b.mesh.vertices[i].z);
  }
  EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
  options.seed = 6;
  const RemeshResult c = remesh(sphere, 600, options);
  EXPECT_NE(a.mesh.vertices[0].x, c.mesh.vertices[0].x);
}

TEST(Remesh, RefusesTooFewOrTooManyVerticesAndABadAreaFraction) {
  const auto sphere = test::surface_file("sphere.off");
  EXPECT_NE(test::message_of([&] { remesh(sphere, 3); }).find("at least 4 vertices"), std::string::npos);
  EXPECT_NE(test::message_of([&] { remesh(sphere, std::size_t{1} << 40); }).find("too many"), std::string::npos);
  RemeshOptions options;
  options.area_fraction = 0.95;
  EXPECT_THROW(remesh(sphere, 100, options), InvalidInput);
  options = {};
  options.relax_sweeps = -1;
  EXPECT_THROW(remesh(sphere, 100, options), InvalidInput);
}

// Relaxation (on by default) moves the vertices toward a hexagonal spacing, and then
// out of the obtuse angles of the mesh (open_obtuse_angles): with it the
// mesh's angles, measured here by plain geometry, lie far more often near 60 degrees
// and fewer triangles are obtuse than without it; the packing stays valid (the
// oracle) and the mesh keeps the elephant's topology.
TEST(Remesh, RelaxationMakesTheTrianglesCloserToEquilateral) {
  const auto elephant = test::surface_file("elephant.off");
  RemeshOptions options;
  const RemeshResult relaxed = remesh(elephant, 8000, options);
  options.relax_sweeps = 0;
  const RemeshResult tuned = remesh(elephant, 8000, options);
  for (const RemeshResult* r : {&relaxed, &tuned}) {
    ASSERT_TRUE(r->tuning.reached);
    std::vector<oracle::Point3> centers;
    for (const Vec3 v : r->mesh.vertices) centers.push_back({v.x, v.y, v.z});
    const oracle::SurfaceReport report = oracle::check_surface(test::oracle_surface(*elephant), centers, r->radius);
    EXPECT_TRUE(report.ok()) << report.summary();
    std::vector<std::array<std::size_t, 3>> tris;
    for (const auto& t : r->mesh.triangles) tris.push_back({t[0], t[1], t[2]});
    const oracle::TopologyReport topology = oracle::check_topology(r->mesh.vertices.size(), tris);
    EXPECT_TRUE(topology.manifold() && topology.genus == 3)
        << (r == &relaxed ? "relaxed: " : "not relaxed: ") << topology.summary();
  }
  const test::AngleShares with = test::angle_shares(relaxed.mesh), without = test::angle_shares(tuned.mesh);
  std::printf("[ remesh ] elephant, 8000 vertices: angles in [50,70] %.3f relaxed, %.3f not; obtuse %.4f, %.4f\n",
              with.near_60, without.near_60, with.obtuse, without.obtuse);
  EXPECT_GT(with.near_60, without.near_60 + 0.25);
  EXPECT_LT(with.obtuse, without.obtuse / 10);
}

TEST(Transaction, ACancelledTuneLeavesThePeriodicPackingAsItWas) {
  const PeriodicBox box(1.0, 1.0);
  Rng rng(3);
  Packing packing = sample_mps(box, 0.02, rng);
  const auto before = state_of(packing);
  TuneOptions options;
  int calls = 0;
  options.on_progress = [&](const Progress&) { return ++calls < 5; };
  EXPECT_THROW(tune(packing, box, Target::area_fraction(0.85), rng, options), Cancelled);
  EXPECT_EQ(calls, 5);
  EXPECT_EQ(state_of(packing), before);
  // And it still tunes afterwards: nothing was left half-done.
  options.on_progress = nullptr;
  EXPECT_TRUE(tune(packing, box, Target::area_fraction(0.7), rng, options).reached);
  const oracle::Report report = oracle::check_all(test::box_of(box), 0.02, test::centers_of(packing));
  EXPECT_TRUE(report.conflict_free() && report.maximal()) << report.summary();
}

TEST(Transaction, AnExceptionFromACallbackLeavesThePlanarPackingAsItWas) {
  const auto domain = std::make_shared<const PlanarDomain>(
      read_poly(std::string(DISKTUNE_DATA_DIR) + "/domains/square_with_hole.poly"));
  Rng rng(4);
  Packing packing = sample_mps(domain, 0.03, rng);
  const auto before = state_of(packing);
  TuneOptions options;
  int operations = 0;
  options.after_operation = [&](const Packing&) {
    if (++operations == 40) throw std::runtime_error("from the callback");
  };
  EXPECT_THROW(tune(packing, *domain, Target::area_fraction(0.3), rng, options), std::runtime_error);
  EXPECT_EQ(state_of(packing), before);
}

TEST(Transaction, ACancelledSurfaceTuneLeavesThePackingAsItWas) {
  const auto sphere = test::surface_file("sphere.off");
  Rng rng(5);
  SurfacePacking packing = sample_mps(sphere, SurfaceSizing::constant(0.08), rng);
  const auto before = state_of(packing);
  TuneOptions options;
  int calls = 0;
  options.on_progress = [&](const Progress&) { return ++calls < 3; };
  EXPECT_THROW(tune(packing, Target::count(packing.size() * 13 / 10), rng, options), Cancelled);
  EXPECT_EQ(state_of(packing), before);
  RemeshOptions remesh_options;
  remesh_options.tune.on_progress = [](const Progress&) { return false; };
  EXPECT_THROW(remesh(sphere, 500, remesh_options), Cancelled);
  // Relaxation reports too, and can be cancelled as well.
  remesh_options.tune.on_progress = [](const Progress& p) { return p.phase != Phase::relaxation; };
  EXPECT_THROW(remesh(sphere, 500, remesh_options), Cancelled);
}

TEST(Adapters, RemeshACgalSurfaceMeshIntoAnother) {
  const SurfaceDomain sphere = read_surface(std::string(DISKTUNE_DATA_DIR) + "/surfaces/sphere.off");
  CgalMesh in;
  std::vector<CgalMesh::Vertex_index> v;
  for (const Vec3 p : sphere.vertices()) v.push_back(in.add_vertex({p.x, p.y, p.z}));
  for (const auto& t : sphere.triangles()) in.add_face(v[t[0]], v[t[1]], v[t[2]]);
  CgalMesh out;
  const RemeshResult result = remesh(in, 700, out);
  EXPECT_EQ(out.number_of_vertices(), 700u);
  EXPECT_EQ(out.number_of_faces(), result.mesh.triangles.size());
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(out));
  EXPECT_TRUE(CGAL::is_closed(out));
  // The vertices are the mesh's, in order.
  for (std::size_t i = 0; i < 700; ++i) {
    const auto p = out.point(CgalMesh::Vertex_index(static_cast<CgalMesh::size_type>(i)));
    EXPECT_EQ(p.x(), result.mesh.vertices[i].x);
  }
  // In place: `out` may be `in`.
  remesh(in, 400, in);
  EXPECT_EQ(in.number_of_vertices(), 400u);
}

TEST(Adapters, RemeshAnOpenMeshMeshIntoAnother) {
  const SurfaceDomain sphere = read_surface(std::string(DISKTUNE_DATA_DIR) + "/surfaces/sphere.off");
  OpenMeshMesh in;
  std::vector<OpenMeshMesh::VertexHandle> v;
  for (const Vec3 p : sphere.vertices())
    v.push_back(in.add_vertex(OpenMeshMesh::Point(static_cast<float>(p.x), static_cast<float>(p.y),
                                                  static_cast<float>(p.z))));
  for (const auto& t : sphere.triangles()) in.add_face(v[t[0]], v[t[1]], v[t[2]]);
  OpenMeshMesh out;
  const RemeshResult result = remesh(in, 650, out);
  EXPECT_EQ(out.n_vertices(), 650u);
  EXPECT_EQ(out.n_faces(), result.mesh.triangles.size());
  for (const auto e : out.edges()) EXPECT_FALSE(out.is_boundary(e));  // closed, like the sphere
}

TEST(Adapters, ANonManifoldMeshIsRefusedAndTheTargetKept) {
  SurfaceMesh fin;  // three triangles on one edge
  fin.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  fin.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  CgalMesh cgal_out;
  cgal_out.add_vertex({7, 7, 7});
  EXPECT_NE(test::message_of([&] { copy_into(fin, cgal_out); }).find("not a manifold"), std::string::npos);
  EXPECT_EQ(cgal_out.number_of_vertices(), 1u);
  OpenMeshMesh om_out;
  om_out.add_vertex({7, 7, 7});
  EXPECT_THROW(copy_into(fin, om_out), InvalidInput);
  EXPECT_EQ(om_out.n_vertices(), 1u);
}

TEST(Adapters, APlanarMeshIntoTwoAndThreeDimensionalSurfaceMeshes) {
  PlanarMesh square;
  square.vertices = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  square.triangles = {{0, 1, 2}, {0, 2, 3}};
  CGAL::Surface_mesh<Kernel::Point_2> flat;
  copy_into(square, flat);
  EXPECT_EQ(flat.number_of_vertices(), 4u);
  EXPECT_EQ(flat.number_of_faces(), 2u);
  CgalMesh lifted;
  copy_into(square, lifted);
  EXPECT_EQ(lifted.number_of_faces(), 2u);
  EXPECT_EQ(lifted.point(CgalMesh::Vertex_index(2)), Kernel::Point_3(1, 1, 0));
}

// A planar packing's constrained Delaunay mesh into a CGAL CDT (the one CGAL's 2D mesher
// refines): the same vertices in order, every triangle of the mesh a face marked in the
// domain, nothing else marked (holes and the hull's pockets stay out), judged against
// the mesh's own arrays and, independently, the domain's area.
TEST(Adapters, APlanarMeshIntoACgalCdtWithItsDomainMarked) {
  using Tds = CGAL::Triangulation_data_structure_2<CGAL::Delaunay_mesh_vertex_base_2<Kernel>,
                                                   CGAL::Delaunay_mesh_face_base_2<Kernel>>;
  using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds>;
  for (const char* name : {"square_with_hole.poly", "gear.poly"}) {
    const auto domain =
        std::make_shared<const PlanarDomain>(read_poly(std::string(DISKTUNE_DATA_DIR) + "/domains/" + name));
    Rng rng(11);
    Packing packing = sample_mps(domain, 0.03, rng);
    const PlanarMesh mesh = constrained_delaunay(packing, boundary_loops(packing, *domain));
    Cdt cdt;
    cdt.insert(Kernel::Point_2(5, 5));  // replaced
    const auto handles = copy_into(mesh, cdt, [](auto f, bool in) { f->set_in_domain(in); });
    ASSERT_EQ(handles.size(), mesh.vertices.size()) << name;
    EXPECT_EQ(cdt.number_of_vertices(), mesh.vertices.size()) << name;
    for (std::size_t i = 0; i < handles.size(); ++i)
      EXPECT_EQ(handles[i]->point(), Kernel::Point_2(mesh.vertices[i].x, mesh.vertices[i].y)) << name;
    std::set<std::array<Cdt::Vertex_handle, 3>> inside;
    double area = 0;
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
      if (!f->is_in_domain()) continue;
      std::array<Cdt::Vertex_handle, 3> t{f->vertex(0), f->vertex(1), f->vertex(2)};
      std::sort(t.begin(), t.end());
      inside.insert(t);
      area += CGAL::to_double(cdt.triangle(f).area());
    }
    EXPECT_EQ(inside.size(), mesh.triangles.size()) << name;
    for (const auto& tri : mesh.triangles) {  // random points: no cocircular ties
      std::array<Cdt::Vertex_handle, 3> t{handles[tri[0]], handles[tri[1]], handles[tri[2]]};
      std::sort(t.begin(), t.end());
      EXPECT_TRUE(inside.count(t)) << name;
    }
    EXPECT_NEAR(area, domain->area(), 1e-9 * domain->area()) << name;
    EXPECT_NEAR(planar_domain_from_cdt(cdt, [](auto f) { return f->is_in_domain(); }).area(), domain->area(),
                1e-9 * domain->area())
        << name;
  }
}

}  // namespace
}  // namespace disktune
