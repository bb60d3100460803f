// SPDX-License-Identifier: GPL-3.0-or-later
// Sharp features in sampling and meshing (issue #15, items 1 and 2): the feature corners
// and curves hold fixed disks, the curves are covered by them and spaced closely enough
// that the restricted Delaunay mesh keeps the curves as edges, and the mesh is a
// manifold with no triangle across a feature. Everything is checked here apart from the
// library: the packing by the surface oracle, the curves' coverage by exact segment-ball
// intervals, the spacing, the mesh edges and the patches by brute force, the topology
// by oracle/mesh_topology.h.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "disktune/restricted_delaunay.h"
#include "disktune/surface_features.h"
#include "disktune/surface_sampling.h"
#include "disktune/surface_tuning.h"
#include "oracle/mesh_topology.h"
#include "surface_checks.h"
#include "sweep_seeds.h"

namespace disktune {
namespace {

// Every edge by the angle rule, stray folds too: the elephant's many short ones are the
// hard case for the fixed disks.
std::shared_ptr<const SurfaceDomain> with_features(const SurfaceDomain& plain, double angle = 60) {
  SurfaceDomain d = plain;
  d.set_features(detect_features(d, {angle, 60, 0}));
  return std::make_shared<const SurfaceDomain>(std::move(d));
}

// Distance from p to the segment ab.
double segment_distance(Vec3 p, Vec3 a, Vec3 b) {
  const Vec3 d = b - a;
  const double t = std::clamp(dot(p - a, d) / dot(d, d), 0.0, 1.0);
  return norm(p - (a + d * t));
}

struct FeatureFindings {
  std::size_t corners_without_disk = 0;  // not covered by a fixed disk either
  std::size_t corners_by_neighbour = 0;  // covered by another corner's disk
  std::size_t fixed_off_curves = 0;      // fixed disks on no curve edge
  std::size_t uncovered_edges = 0;       // curve edges not covered by fixed disks
  std::size_t unheld_edges = 0;          // nor by the fixed disks on their own curve or
                                         // on one sharing a corner with it
  std::size_t pairs = 0, wide_pairs = 0; // consecutive feature disks; those > sqrt(2) r apart
  std::vector<std::array<std::size_t, 2>> close_pairs;  // packing ids, <= sqrt(2) r apart
};

// What the feature disks of `p` look like, by brute force over all disks.
FeatureFindings inspect(const SurfacePacking& p) {
  const SurfaceDomain& d = p.domain();
  const auto& v = d.vertices();
  FeatureFindings f;
  std::vector<DiskId> fixed;
  for (const DiskId id : p.ids())
    if (p.flags(id) & kFixed) fixed.push_back(id);
  const double tol = 1e-9;
  for (const std::size_t c : d.features().corners) {
    bool at = false, near = false;
    for (const DiskId id : fixed) {
      const double dist = norm(p.center(id) - v[c]);
      at = at || dist <= tol * p.radius(id);
      near = near || dist <= p.radius(id) * (1 + tol);
    }
    f.corners_without_disk += !near;
    f.corners_by_neighbour += near && !at;
  }
  // Every edge of every curve: the fixed disks on it, and its coverage by the union of
  // some disks' intervals (|a + t (b - a) - c| <= r solved for t): all fixed disks, and
  // those on the edge's own curve (a corner's on every curve that ends there) or on a
  // curve that shares a corner with it (at a sharp corner two curves share disks).
  std::vector<std::vector<std::array<Vec3, 2>>> edges;  // by curve
  for (const SurfaceCurve& curve : d.fixed_curves()) {
    edges.emplace_back();
    for (std::size_t k = 0; k + 1 < curve.vertices.size() + (curve.closed ? 1 : 0); ++k)
      edges.back().push_back({v[curve.vertices[k]], v[curve.vertices[(k + 1) % curve.vertices.size()]]});
  }
  std::vector<std::vector<DiskId>> on_curve(edges.size());
  for (const DiskId id : fixed) {
    bool on = false;
    for (std::size_t c = 0; c < edges.size(); ++c) {
      bool here = false;
      for (const auto& e : edges[c]) here = here || segment_distance(p.center(id), e[0], e[1]) <= tol * p.radius(id);
      if (here) on_curve[c].push_back(id);
      on = on || here;
    }
    f.fixed_off_curves += !on;
  }
  const auto covered = [&](const std::array<Vec3, 2>& e, const std::vector<DiskId>& disks) {
    std::vector<std::array<double, 2>> in;
    const Vec3 dir = e[1] - e[0];
    for (const DiskId id : disks) {
      const Vec3 w = e[0] - p.center(id);
      const double A = dot(dir, dir), B = 2 * dot(dir, w), C = dot(w, w) - std::pow(p.radius(id) * (1 + tol), 2);
      const double disc = B * B - 4 * A * C;
      if (disc < 0) continue;
      in.push_back({(-B - std::sqrt(disc)) / (2 * A), (-B + std::sqrt(disc)) / (2 * A)});
    }
    std::sort(in.begin(), in.end());
    double reach = 0;
    for (const auto& i : in)
      if (i[0] <= reach) reach = std::max(reach, i[1]);
    return reach >= 1;
  };
  const auto& curves = d.fixed_curves();
  const auto ends = [&](std::size_t c) {
    return curves[c].closed ? std::set<std::size_t>{} : std::set<std::size_t>{curves[c].vertices.front(), curves[c].vertices.back()};
  };
  for (std::size_t c = 0; c < edges.size(); ++c) {
    std::vector<DiskId> held = on_curve[c];
    for (std::size_t o = 0; o < edges.size(); ++o) {
      const std::set<std::size_t> a = ends(c), b = ends(o);
      if (o != c && std::any_of(a.begin(), a.end(), [&](std::size_t x) { return b.count(x) > 0; }))
        held.insert(held.end(), on_curve[o].begin(), on_curve[o].end());
    }
    for (const auto& e : edges[c]) {
      f.uncovered_edges += !covered(e, fixed);
      f.unheld_edges += !covered(e, held);
    }
  }
  // Consecutive feature disks: along each feature curve by arc length.
  const std::size_t first_feature = d.fixed_curves().size() - d.features().curves.size();
  for (std::size_t c = first_feature; c < d.fixed_curves().size(); ++c) {
    const SurfaceCurve& curve = d.fixed_curves()[c];
    std::vector<std::pair<double, DiskId>> along;
    double at = 0;
    const std::size_t n = curve.vertices.size(), steps = curve.closed ? n : n - 1;
    for (std::size_t k = 0; k < steps; ++k) {
      const Vec3 a = v[curve.vertices[k]], b = v[curve.vertices[(k + 1) % n]];
      for (const DiskId id : fixed) {
        if (segment_distance(p.center(id), a, b) > tol * p.radius(id)) continue;
        const double s = at + norm(p.center(id) - a);
        if (std::none_of(along.begin(), along.end(), [&](const auto& x) { return x.second == id; }))
          along.push_back({s, id});
      }
      at += norm(b - a);
    }
    std::sort(along.begin(), along.end());
    for (std::size_t i = 0; i + 1 < along.size() + (curve.closed && along.size() > 2 ? 1 : 0); ++i) {
      const DiskId x = along[i].second, y = along[(i + 1) % along.size()].second;
      const double gap = norm(p.center(x) - p.center(y));
      ++f.pairs;
      if (gap > std::sqrt(2.0) * std::max(p.radius(x), p.radius(y))) {
        ++f.wide_pairs;
      } else {
        f.close_pairs.push_back({x, y});
      }
    }
  }
  return f;
}

// Of the close consecutive feature pairs, those that are no edge of the mesh.
std::size_t missing_edges(const SurfacePacking& p, const FeatureFindings& f) {
  std::vector<std::size_t> vertex_of(p.id_bound(), 0);
  std::size_t n = 0;
  for (const DiskId id : p.ids()) vertex_of[id] = n++;
  const SurfaceMesh mesh = restricted_delaunay(p);
  std::set<std::pair<std::size_t, std::size_t>> edges;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) edges.insert(std::minmax(t[k], t[(k + 1) % 3]));
  std::size_t missing = 0;
  for (const auto& [x, y] : f.close_pairs) missing += !edges.count(std::minmax(vertex_of[x], vertex_of[y]));
  return missing;
}

// Issue #15, item 1, "surface disks never cover across a feature": each patch the
// features cut the surface into (brute force, expected_patches) is covered by the
// disks whose centers lie on it (inside it, or on its curves and corners), judged by
// the oracle on that patch's triangles alone. The uncovered witnesses over all patches.
std::size_t uncovered_within_patches(const SurfacePacking& p, double degrees) {
  const SurfaceDomain& d = p.domain();
  const std::vector<std::size_t> label = test::expected_patches(d, test::expected_features(d, degrees));
  std::map<std::size_t, std::vector<std::size_t>> patches;  // label -> triangles
  for (std::size_t t = 0; t < label.size(); ++t) patches[label[t]].push_back(t);
  const oracle::SurfaceMeshInput whole = test::oracle_surface(d);
  oracle::SurfaceOptions options;
  options.on_surface = options.conflicts = options.boundary = false;
  std::size_t uncovered = 0;
  for (const auto& [first, triangles] : patches) {
    oracle::SurfaceMeshInput part{whole.vertices, {}};
    Vec3 lo = d.vertices()[d.triangles()[first][0]], hi = lo;
    for (const std::size_t t : triangles) {
      part.triangles.push_back(whole.triangles[t]);
      for (const auto v : d.triangles()[t]) {
        const Vec3 q = d.vertices()[v];
        lo = {std::min(lo.x, q.x), std::min(lo.y, q.y), std::min(lo.z, q.z)};
        hi = {std::max(hi.x, q.x), std::max(hi.y, q.y), std::max(hi.z, q.z)};
      }
    }
    std::vector<oracle::Point3> centers;
    std::vector<double> radii;
    for (const DiskId id : p.ids()) {
      const Vec3 c = p.center(id);
      const double tol = 1e-9 * p.radius(id);
      if (c.x < lo.x - tol || c.y < lo.y - tol || c.z < lo.z - tol || c.x > hi.x + tol || c.y > hi.y + tol ||
          c.z > hi.z + tol || oracle::distance_to_surface(part, {c.x, c.y, c.z}) > tol) {
        continue;
      }
      centers.push_back({c.x, c.y, c.z});
      radii.push_back(p.radius(id));
    }
    if (centers.empty()) {
      ++uncovered;  // a patch without a disk of its own is not covered by its own
      continue;
    }
    uncovered += oracle::check_surface(part, centers, radii, options).uncovered_count;
  }
  return uncovered;
}

TEST(FeatureSampling, TheBoxKeepsItsTwelveEdgesOverSeeds) {
  const auto box = with_features(*test::box_surface({1.84, 0.4, 0.2}, {4, 3, 2}));
  ASSERT_EQ(box->features().curves.size(), 12u);
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    Rng rng(seed);
    const SurfacePacking p = sample_mps(box, SurfaceSizing::constant(0.05), rng);
    EXPECT_SURFACE_OK(p);
    const FeatureFindings f = inspect(p);
    EXPECT_EQ(f.corners_without_disk + f.corners_by_neighbour, 0u) << "seed " << seed;
    EXPECT_EQ(f.fixed_off_curves, 0u) << "seed " << seed;
    EXPECT_EQ(f.uncovered_edges, 0u) << "seed " << seed;
    EXPECT_EQ(f.unheld_edges, 0u) << "seed " << seed;
    // Every box edge is long enough to be cut into steps of r to sqrt(2) r.
    EXPECT_EQ(f.wide_pairs, 0u) << "seed " << seed << ", of " << f.pairs;
    EXPECT_EQ(missing_edges(p, f), 0u) << "seed " << seed;
    // The mesh names those edges as its feature edges (what OBJ and VTK files show).
    EXPECT_EQ(restricted_delaunay(p).feature_edges.size(), f.pairs) << "seed " << seed;
  }
}

TEST(FeatureSampling, FandiskFeatureDisksCoverTheCurvesAndBecomeMeshEdges) {
  const auto fandisk = with_features(*test::surface_file("fandisk.off"));
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    Rng rng(seed);
    const SurfacePacking p = sample_mps(fandisk, SurfaceSizing::constant(0.02), rng);
    EXPECT_SURFACE_OK(p);
    const FeatureFindings f = inspect(p);
    EXPECT_EQ(f.corners_without_disk, 0u) << "seed " << seed;
    EXPECT_EQ(f.fixed_off_curves, 0u) << "seed " << seed;
    EXPECT_EQ(f.uncovered_edges, 0u) << "seed " << seed;
    EXPECT_EQ(f.unheld_edges, 0u) << "seed " << seed;  // r is below its curves' gaps (curves_fit)
    // Measured: 5 of about 538 pairs are wider, all on three curves too short for r
    // (2.95 r and 3.66 r between corners: no count of steps in [r, sqrt(2) r] fits, or the
    // next curve at an acute corner is in the way); local refinement is #15's item 3.
    EXPECT_LE(f.wide_pairs, 6u) << "seed " << seed << ", of " << f.pairs;
    const std::size_t missing = missing_edges(p, f);
    EXPECT_EQ(missing, 0u) << "seed " << seed;
    std::printf("[ features ] fandisk r 0.02 seed %llu: %zu disks, %zu corners (%zu covered by a neighbour's disk), "
                "%zu consecutive feature pairs, %zu wider than sqrt(2) r, %zu close pairs not a mesh edge\n",
                static_cast<unsigned long long>(seed), p.size(), fandisk->features().corners.size(),
                f.corners_by_neighbour, f.pairs, f.wide_pairs, missing);
  }
}

TEST(FeatureSampling, TuningKeepsTheFeatureDisksAndTheirSpacing) {
  const auto fandisk = with_features(*test::surface_file("fandisk.off"));
  for (const double factor : {1.3, 0.75}) {
    Rng rng(4);
    SurfacePacking p = sample_mps(fandisk, SurfaceSizing::constant(0.04), rng);
    const std::size_t wide_before = inspect(p).wide_pairs;
    const auto goal = static_cast<std::size_t>(std::lround(factor * static_cast<double>(p.size())));
    const TuneResult result = tune(p, Target::count(goal), rng);
    EXPECT_TRUE(result.reached) << "factor " << factor;
    EXPECT_SURFACE_OK(p);
    const FeatureFindings f = inspect(p);
    EXPECT_EQ(f.corners_without_disk, 0u) << "factor " << factor;
    EXPECT_EQ(f.fixed_off_curves, 0u) << "factor " << factor;
    EXPECT_EQ(f.uncovered_edges, 0u) << "factor " << factor;
    EXPECT_EQ(f.unheld_edges, 0u) << "factor " << factor;  // 0.04 fits fandisk's curves
    // The spacing is tuned toward the target with random 1D steps (not laid out again):
    // a few more wide pairs than the sample had are allowed, one in a hundred.
    EXPECT_LE(f.wide_pairs, wide_before + f.pairs / 100) << "factor " << factor;
    EXPECT_EQ(missing_edges(p, f), 0u) << "factor " << factor;
    std::printf("[ features ] fandisk r 0.04 tuned to %zu (%.2fx): %zu consecutive feature pairs, %zu wider than sqrt(2) r "
                "(%zu in the sample)\n", p.size(), factor, f.pairs, f.wide_pairs, wide_before);
  }
}

// The restricted Delaunay mesh of `p` checked by the independent topology oracle, and
// for triangles that join the two sides of a feature: two vertices that are surface
// disks (not fixed) in different patches, the patches cut by the oracle's own dihedral
// test at 60 degrees.
struct MeshFindings {
  oracle::TopologyReport topology;
  std::size_t straddling = 0;
};

MeshFindings mesh_findings(const SurfacePacking& p) {
  const SurfaceMesh mesh = restricted_delaunay(p);
  std::vector<std::array<std::size_t, 3>> tris;
  for (const auto& t : mesh.triangles) tris.push_back({t[0], t[1], t[2]});
  MeshFindings out;
  out.topology = oracle::check_topology(mesh.vertices.size(), tris);
  const std::vector<std::size_t> patch = test::expected_patches(p.domain(), test::expected_features(p.domain(), 60));
  std::vector<std::size_t> patch_of;  // per mesh vertex; none for a fixed disk
  const std::size_t none = p.domain().triangles().size();
  for (const DiskId id : p.ids()) patch_of.push_back((p.flags(id) & kFixed) ? none : patch[p.point(id).triangle]);
  for (const auto& t : tris) {
    std::set<std::size_t> seen;
    for (const std::size_t v : t)
      if (patch_of[v] != none) seen.insert(patch_of[v]);
    out.straddling += seen.size() > 1;
  }
  return out;
}

TEST(FeatureMeshing, FandiskMeshesAreManifoldsThatFollowTheFeaturesOverSeeds) {
  const auto fandisk = with_features(*test::surface_file("fandisk.off"));
  for (const double r : {0.03, 0.02}) {
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
      Rng rng(seed);
      const SurfacePacking p = sample_mps(fandisk, SurfaceSizing::constant(r), rng);
      const MeshFindings m = mesh_findings(p);
      EXPECT_TRUE(m.topology.manifold() && m.topology.genus == 0 && m.topology.boundary_edges == 0)
          << "r " << r << " seed " << seed << ": " << m.topology.summary();
      // Where two consecutive feature disks are too far apart for an edge between them
      // (on curves too short for r, FeatureSampling above), the mesh bridges the gap
      // with two triangles across it; nowhere else may one cross.
      const std::size_t wide = inspect(p).wide_pairs;
      EXPECT_LE(m.straddling, 2 * wide) << "r " << r << " seed " << seed;
      std::printf("[ features ] fandisk r %.2f seed %llu: mesh %s, %zu triangles across a feature, %zu wide pairs\n", r,
                  static_cast<unsigned long long>(seed), m.topology.summary().c_str(), m.straddling, wide);
    }
  }
}

// At r = 0.04 a ball of one of fandisk's feature disks reaches a face 0.033 away under a
// ledge; its Voronoi cell meets that face too, and the dual test gave the disk a second
// fan, a cone onto the far face (a bow tie; 19 of 50 seeds before the cap, 0 now), or
// one touching its own fan at a shared edge (an edge in three triangles). The cap over the
// cone's rim leaves one fan. Measured: 48 of 50 seeds manifold of genus 0 (26 before);
// seeds 26 and 32 keep an edge in three triangles.
TEST(FeatureMeshing, FandiskAtACoarseRadiusHasNoBowTies) {
  const auto fandisk = with_features(*test::surface_file("fandisk.off"));
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    Rng rng(seed);
    const SurfacePacking p = sample_mps(fandisk, SurfaceSizing::constant(0.04), rng);
    const MeshFindings m = mesh_findings(p);
    EXPECT_EQ(m.topology.bow_tie_vertices, 0u) << "seed " << seed << ": " << m.topology.summary();
    EXPECT_TRUE(m.topology.manifold() && m.topology.genus == 0 && m.topology.boundary_edges == 0)
        << "seed " << seed << ": " << m.topology.summary();
  }
}

using test::full_sweep;

// The surfaces of issue #15, item 2, at radii where a sample has 1-3 thousand disks.
struct TopologyCase {
  const char* file;
  double r;
};
const TopologyCase kTopologyCases[] = {
    {"eight.off", 0.02},  {"fandisk.off", 0.02}, {"joint.off", 0.03}, {"mesh_with_border.off", 0.2676},
    {"elephant.off", 0.01}};

// The topology the oracle finds in the input itself.
oracle::TopologyReport input_topology(const SurfaceDomain& surface) {
  const oracle::SurfaceMeshInput input = test::oracle_surface(surface);
  std::vector<std::array<std::size_t, 3>> tris(input.triangles.begin(), input.triangles.end());
  return oracle::check_topology(input.vertices.size(), tris);
}

// Whether the packing's mesh has the input's topology (a failure names it).
bool has_topology(const SurfacePacking& p, const oracle::TopologyReport& want, const std::string& what) {
  const MeshFindings m = mesh_findings(p);
  const bool ok = m.topology.manifold() && m.topology.genus == want.genus &&
                  m.topology.boundary_loops == want.boundary_loops && m.topology.components == want.components;
  EXPECT_TRUE(ok) << what << ": " << m.topology.summary() << "; input: " << want.summary();
  return ok;
}

// A unit cube with the edge x = y = 1 cut off 0.05 x 0.05, in 16 triangles, with its
// 30-degree features: the chamfer's two creases (45-degree folds) 0.0707 apart.
std::shared_ptr<const SurfaceDomain> chamfered_cube() {
  const std::vector<Vec3> corners{{0, 0, 0}, {1, 0, 0}, {1, 0.95, 0}, {0.95, 1, 0}, {0, 1, 0},
                                  {0, 0, 1}, {1, 0, 1}, {1, 0.95, 1}, {0.95, 1, 1}, {0, 1, 1}};
  const std::vector<SurfaceDomain::Triangle> faces{{0, 2, 1}, {0, 3, 2}, {0, 4, 3}, {5, 6, 7}, {5, 7, 8}, {5, 8, 9},
                                                   {0, 1, 6}, {0, 6, 5}, {1, 2, 7}, {1, 7, 6}, {2, 3, 8}, {2, 8, 7},
                                                   {3, 4, 9}, {3, 9, 8}, {4, 0, 5}, {4, 5, 9}};
  return with_features(SurfaceDomain(corners, faces), 30);
}

// Two feature curves closer than r along a face (a chamfer's creases, 0.05 x 0.05 cut
// off a unit cube's edge, 30-degree features): with one radius r = 0.1 the disks of one
// crease cover the other, which holds none of its own, and the mesh cuts across it.
// curves_fit says so from the distances alone, and the thickness sizing (auto:0.1)
// keeps r below the gap there: every curve edge is covered by the disks on its own
// curve (interval coverage above), the packing passes the oracle, the mesh is a sphere.
TEST(FeatureSampling, CloseCurvesKeepDisksOfTheirOwnWithTheThicknessSizing) {
  const auto chamfer = chamfered_cube();
  ASSERT_EQ(chamfer->features().curves.size(), 15u);
  const double gap = 0.05 * std::sqrt(2.0);  // from each crease to the other, and corner to corner
  EXPECT_FALSE(curves_fit(*chamfer, 1.01 * gap));
  EXPECT_TRUE(curves_fit(*chamfer, 0.99 * gap));
  const oracle::TopologyReport want = input_topology(*chamfer);
  const SurfaceSizing graded = thickness_sizing(*chamfer, 0.1);
  EXPECT_LT(graded.min_radius(), gap);
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    Rng one_rng(seed), graded_rng(seed);
    const SurfacePacking one = sample_mps(chamfer, SurfaceSizing::constant(0.1), one_rng);
    EXPECT_GT(inspect(one).unheld_edges, 0u) << "seed " << seed;  // what the sizing is for
    const SurfacePacking p = sample_mps(chamfer, graded, graded_rng);
    EXPECT_SURFACE_OK(p);
    const FeatureFindings f = inspect(p);
    EXPECT_EQ(f.unheld_edges, 0u) << "seed " << seed;
    EXPECT_EQ(f.fixed_off_curves, 0u) << "seed " << seed;
    has_topology(p, want, "chamfer auto:0.1 seed " + std::to_string(seed));
  }
}

// Issue #15, item 1: no point is covered only by disks across a feature. Each patch
// between the features is covered by the disks on it and its curves alone (the oracle on
// the patch's triangles, the features found here at the angle given) in samples of the
// elephant, joint, fandisk and the chamfered cube (one radius and auto:0.1). Before
// coverage counted per patch (surface_packing.h), 3 or 4 of 10 fandisk samples at each
// of these radii had a place covered only from across a crease (a short crease one wide
// step long), and the chamfer's face beside its bare crease was covered from across it.
TEST(FeatureSampling, EveryPatchIsCoveredByItsOwnDisksNotAcrossAFeature) {
  for (const auto& [file, r, seeds] : {std::tuple{"elephant.off", 0.01, 1}, std::tuple{"joint.off", 0.03, 2},
                                       std::tuple{"fandisk.off", 0.02, 4}, std::tuple{"fandisk.off", 0.025, 4},
                                       std::tuple{"fandisk.off", 0.04, 4}}) {
    const auto surface = with_features(*test::surface_file(file));
    for (int seed = 1; seed <= seeds; ++seed) {
      Rng rng(static_cast<std::uint64_t>(seed));
      const SurfacePacking p = sample_mps(surface, SurfaceSizing::constant(r), rng);
      EXPECT_EQ(uncovered_within_patches(p, 60), 0u) << file << " r " << r << " seed " << seed;
    }
  }
  const auto chamfer = chamfered_cube();
  const SurfaceSizing graded = thickness_sizing(*chamfer, 0.1);
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    Rng one_rng(seed), graded_rng(seed);
    EXPECT_EQ(uncovered_within_patches(sample_mps(chamfer, SurfaceSizing::constant(0.1), one_rng), 30), 0u)
        << "chamfer r 0.1 seed " << seed;
    EXPECT_EQ(uncovered_within_patches(sample_mps(chamfer, graded, graded_rng), 30), 0u) << "chamfer seed " << seed;
  }
}

// The thickness sizing (auto:R) shrinks r under fandisk's ledge and at the elephant's
// thin parts, so coarse samples mesh as manifolds of the input's genus where one radius
// does not (measured over 50 seeds: fandisk auto:0.05 50 of 50, one radius 19; the
// elephant auto:0.03 50 of 50, one radius 0).
TEST(FeatureMeshing, ThicknessSizingMeshesCoarseSamplesWithTheInputsTopology) {
  for (const auto& [file, r_max, seeds] : {std::tuple{"fandisk.off", 0.05, 6}, std::tuple{"elephant.off", 0.03, 3}}) {
    const auto surface = with_features(*test::surface_file(file));
    const oracle::TopologyReport want = input_topology(*surface);
    const SurfaceSizing sizing = thickness_sizing(*surface, r_max);
    EXPECT_LT(sizing.min_radius(), r_max) << file;
    for (int seed = 1; seed <= seeds; ++seed) {
      Rng rng(static_cast<std::uint64_t>(seed));
      const SurfacePacking p = sample_mps(surface, sizing, rng);
      EXPECT_SURFACE_OK(p);
      EXPECT_EQ(inspect(p).unheld_edges, 0u) << file << " seed " << seed;
      has_topology(p, want, std::string(file) + " auto:" + std::to_string(r_max) + " seed " + std::to_string(seed));
    }
  }
}

// Issue #15, item 2: the mesh of a sample with the default features is a manifold with
// the input's genus and boundary loops, both counted by the oracle on the input too.
// Four seeds a surface here, fifty in tests/invariant_sweep.sh.
TEST(FeatureMeshing, SampleMeshesHaveTheInputsTopologyOverSeeds) {
  const std::vector<std::uint64_t> seeds = test::sweep_seeds(4, 50);
  for (const TopologyCase& c : kTopologyCases) {
    const auto surface = with_features(*test::surface_file(c.file));
    const oracle::TopologyReport want = input_topology(*surface);
    ASSERT_TRUE(want.manifold()) << c.file;
    int good = 0;
    for (const std::uint64_t seed : seeds) {
      Rng rng(seed);
      const SurfacePacking p = sample_mps(surface, SurfaceSizing::constant(c.r), rng);
      good += has_topology(p, want, std::string(c.file) + " seed " + std::to_string(seed));
    }
    std::printf("[ features ] %s r %g, seeds %llu-%llu: %d of %zu sample meshes have the input's topology\n", c.file,
                c.r, static_cast<unsigned long long>(seeds.front()), static_cast<unsigned long long>(seeds.back()), good,
                seeds.size());
    std::fflush(stdout);
  }
}

// The same for the sample tuned denser and sparser (automatic schedule): 1.4 and 0.6
// times its count over fifty seeds in tests/invariant_sweep.sh, 1.4 and 0.7 for one
// seed here. At these sizes ejection stalls near eta 0.33 (eight: 1079 disks for 1057
// asked, after 18 s), so 0.6 is not always reached: the mesh of the closest packing is
// judged then, and the count printed.
TEST(FeatureMeshing, TunedMeshesHaveTheInputsTopologyOverSeeds) {
  const std::vector<std::uint64_t> seeds = test::sweep_seeds(1, 50);
  for (const TopologyCase& c : kTopologyCases) {
    const auto surface = with_features(*test::surface_file(c.file));
    const oracle::TopologyReport want = input_topology(*surface);
    for (const double factor : {full_sweep() ? 0.6 : 0.7, 1.4}) {
      int good = 0, reached = 0;
      for (const std::uint64_t seed : seeds) {
        Rng rng(seed);
        SurfacePacking p = sample_mps(surface, SurfaceSizing::constant(c.r), rng);
        const auto goal = static_cast<std::size_t>(std::lround(factor * static_cast<double>(p.size())));
        const std::string what = std::string(c.file) + " x" + std::to_string(factor).substr(0, 3) + " seed " +
                                 std::to_string(seed);
        reached += tune(p, Target::count(goal), rng).reached;
        good += has_topology(p, want, what);
      }
      std::printf("[ features ] %s r %g, seeds %llu-%llu, tuned to %.1fx (reached %d of %zu): %d of %zu meshes have "
                  "the input's topology\n",
                  c.file, c.r, static_cast<unsigned long long>(seeds.front()),
                  static_cast<unsigned long long>(seeds.back()), factor, reached, seeds.size(), good, seeds.size());
      std::fflush(stdout);
    }
  }
}

// The case: the elephant at r = 0.01 tuned to 1.4 times its sample (library
// seeds 7 and 9) had edges in three triangles at its sharp creases; seeds 14 and 18
// had, beside a feature edge, a fan of two and of three triangles across the crease
// (restricted_delaunay.h).
TEST(FeatureMeshing, TheElephantTunedDenseIsAManifoldAtItsCreases) {
  const auto elephant = with_features(*test::surface_file("elephant.off"));
  for (const std::uint64_t seed : {7, 9, 14, 18}) {
    Rng rng(seed);
    SurfacePacking p = sample_mps(elephant, SurfaceSizing::constant(0.01), rng);
    const auto goal = static_cast<std::size_t>(std::lround(1.4 * static_cast<double>(p.size())));
    ASSERT_TRUE(tune(p, Target::count(goal), rng).reached);
    const MeshFindings m = mesh_findings(p);
    EXPECT_TRUE(m.topology.manifold() && m.topology.genus == 3) << "seed " << seed << ": " << m.topology.summary();
    EXPECT_EQ(m.straddling, 0u) << "seed " << seed;
  }
}

// The elephant's samples at r = 0.01 that once meshed with edges in three triangles and a
// hole. Seed 88: the dual test kept three faces of a tetrahedron over a feature edge at a
// crease whose curve ends inside the surface, where no patch tells the crease's sides
// apart (a fan across it, capped). Seed 587 (found by the invariant sweep, seeds
// 578-609): three faces of a tetrahedron around a fixed disk, the third a flap over the
// hole, one edge in no other triangle and two in three (drop_flaps).
TEST(FeatureMeshing, TheElephantsSamplesAreManifoldsWhereATetrahedronClosesOverACrease) {
  const auto elephant = with_features(*test::surface_file("elephant.off"));
  const oracle::TopologyReport want = input_topology(*elephant);
  for (const std::uint64_t seed : {88u, 587u}) {
    Rng rng(seed);
    const SurfacePacking p = sample_mps(elephant, SurfaceSizing::constant(0.01), rng);
    EXPECT_TRUE(has_topology(p, want, "elephant seed " + std::to_string(seed)));
  }
}

// An open boundary's sharp turns are corners, as a planar domain's polygon vertices are:
// each holds a fixed disk, and the pieces between them are laid out evenly, so that
// along the whole loop consecutive boundary disks are less than sqrt(2) r apart. (Before,
// mesh_with_border's one loop, a square with four turns near 90 degrees, had no corner;
// its layout from a random point failed whole at a turn, and 1D darts left 213-239
// boundary disks by seed with steps up to 2 r.) The turns, the order along the loop and
// the steps are found here by plain geometry.
TEST(FeatureSampling, OpenBoundaryTurnsAreCornersAndItsDisksCloseTogether) {
  const auto d = test::surface_file("mesh_with_border.off");
  const auto& v = d->vertices();
  ASSERT_EQ(d->boundary_loops().size(), 1u);
  const auto& loop = d->boundary_loops()[0];
  std::vector<std::size_t> turns;  // loop vertices where the boundary turns by > 60 degrees
  std::vector<double> at{0};       // arc length at each loop vertex, and the whole length
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const Vec3 in = v[loop[k]] - v[loop[(k + loop.size() - 1) % loop.size()]], out = v[loop[(k + 1) % loop.size()]] - v[loop[k]];
    if (dot(in, out) < 0.5 * norm(in) * norm(out)) turns.push_back(loop[k]);
    at.push_back(at.back() + norm(out));
  }
  ASSERT_EQ(turns.size(), 4u);
  std::sort(turns.begin(), turns.end());
  EXPECT_EQ(d->corners(), turns);
  const double r = 0.2676;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    Rng rng(seed);
    const SurfacePacking p = sample_mps(d, SurfaceSizing::constant(r), rng);
    EXPECT_SURFACE_OK(p);
    std::vector<double> s;  // arc length of each disk on the loop
    for (const DiskId id : p.ids()) {
      for (std::size_t k = 0; k < loop.size(); ++k) {
        const Vec3 a = v[loop[k]], b = v[loop[(k + 1) % loop.size()]];
        if (segment_distance(p.center(id), a, b) > 1e-9 * r) continue;
        EXPECT_TRUE(p.flags(id) & kFixed) << "seed " << seed;
        s.push_back(at[k] + norm(p.center(id) - a));
        break;
      }
    }
    for (const std::size_t c : turns) {
      std::size_t held = 0;
      for (const DiskId id : p.ids()) held += norm(p.center(id) - v[c]) <= 1e-12 * r;
      EXPECT_EQ(held, 1u) << "seed " << seed << ": corner " << c;
    }
    std::sort(s.begin(), s.end());
    ASSERT_GE(s.size(), 4u);
    double widest = s.front() + at.back() - s.back();  // the step across the loop's start
    for (std::size_t i = 1; i < s.size(); ++i) widest = std::max(widest, s[i] - s[i - 1]);
    EXPECT_LT(widest, std::sqrt(2.0) * r) << "seed " << seed << ": " << s.size() << " disks on the loop";
    std::printf("[ features ] mesh_with_border seed %d: %zu disks on the boundary, widest step %.3f r (arc)\n",
                static_cast<int>(seed), s.size(), widest / r);
  }
}

TEST(TopologyOracle, TellsManifoldsFromTheRest) {
  // A tetrahedron: closed, genus 0; without one face: one boundary loop, still genus 0.
  std::vector<std::array<std::size_t, 3>> tet{{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  auto r = oracle::check_topology(4, tet);
  EXPECT_TRUE(r.manifold() && r.genus == 0 && r.boundary_edges == 0 && r.components == 1) << r.summary();
  r = oracle::check_topology(4, {tet[0], tet[1], tet[2]});
  EXPECT_TRUE(r.manifold() && r.genus == 0 && r.boundary_loops == 1) << r.summary();
  // A 4 x 4 torus grid: genus 1.
  std::vector<std::array<std::size_t, 3>> torus;
  const auto at = [](std::size_t i, std::size_t j) { return (i % 4) * 4 + j % 4; };
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j) {
      torus.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      torus.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  r = oracle::check_topology(16, torus);
  EXPECT_TRUE(r.manifold() && r.genus == 1) << r.summary();
  // An edge in three triangles; two fans at one vertex; a flipped triangle.
  EXPECT_EQ(oracle::check_topology(5, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}).non_manifold_edges, 1u);
  EXPECT_EQ(oracle::check_topology(5, {{0, 1, 2}, {0, 3, 4}}).bow_tie_vertices, 1u);
  tet[3] = {0, 2, 3};
  r = oracle::check_topology(4, tet);
  EXPECT_FALSE(r.manifold());
  EXPECT_EQ(r.misoriented_edges, 3u);
}

}  // namespace
}  // namespace disktune
