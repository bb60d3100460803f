// SPDX-License-Identifier: GPL-3.0-or-later
// Feature edges and curves (issue #15, item 1), checked against an independent count:
// the dihedral test recomputed here from each triangle pair found by brute force over a
// map of vertex pairs, and the curves checked as a partition of the feature edges.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "disktune/errors.h"
#include "disktune/surface_features.h"
#include "surface_checks.h"

namespace disktune {
namespace {

// Every feature edge in exactly one curve, consecutive curve vertices joined by feature
// edges, open curves from corner to corner with no corner inside, closed ones with none.
void expect_curves_partition(const SurfaceFeatures& f) {
  const std::set<std::size_t> corners(f.corners.begin(), f.corners.end());
  std::multiset<MeshEdge> walked;
  for (const SurfaceCurve& c : f.curves) {
    ASSERT_GE(c.vertices.size(), c.closed ? 3u : 2u);
    const std::size_t steps = c.closed ? c.vertices.size() : c.vertices.size() - 1;
    for (std::size_t i = 0; i < steps; ++i) {
      const std::size_t a = c.vertices[i], b = c.vertices[(i + 1) % c.vertices.size()];
      walked.insert({std::min(a, b), std::max(a, b)});
    }
    for (std::size_t i = 0; i < c.vertices.size(); ++i) {
      const bool end = !c.closed && (i == 0 || i + 1 == c.vertices.size());
      EXPECT_EQ(corners.count(c.vertices[i]) == 1, end) << "vertex " << c.vertices[i] << " of a curve";
    }
  }
  const std::multiset<MeshEdge> all(f.edges.begin(), f.edges.end());
  EXPECT_EQ(walked, all);
  EXPECT_EQ(std::set<MeshEdge>(f.edges.begin(), f.edges.end()).size(), f.edges.size());
}

// A closed cylinder of radius 1 and height 1, `n` sides, its caps fans around centers:
// two rims of 90 degrees, side seams of 360 / n degrees.
std::shared_ptr<const SurfaceDomain> cylinder(int n) {
  std::vector<Vec3> v;
  std::vector<SurfaceDomain::Triangle> t;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * 3.14159265358979323846 * k / n;
    v.push_back({std::cos(a), std::sin(a), 0});
    v.push_back({std::cos(a), std::sin(a), 1});
  }
  const std::size_t bottom = v.size(), top = bottom + 1;
  v.push_back({0, 0, 0});
  v.push_back({0, 0, 1});
  for (int k = 0; k < n; ++k) {
    const std::size_t b0 = 2 * k, t0 = 2 * k + 1, b1 = 2 * ((k + 1) % n), t1 = b1 + 1;
    t.push_back({b0, b1, t1});
    t.push_back({b0, t1, t0});
    t.push_back({bottom, b1, b0});
    t.push_back({top, t0, t1});
  }
  return std::make_shared<const SurfaceDomain>(std::move(v), std::move(t));
}

TEST(SurfaceFeatures, TheBoxHasTwelveEdgeCurvesBetweenEightCorners) {
  const auto box = test::box_surface({1.84, 0.4, 0.2}, {4, 3, 2});
  const SurfaceFeatures f = detect_features(*box);
  const auto expected = test::expected_features(*box, 60);
  EXPECT_EQ(std::set<MeshEdge>(f.edges.begin(), f.edges.end()), expected);
  EXPECT_EQ(f.edges.size(), 4u * (4 + 3 + 2));  // each box edge split as its axis is
  EXPECT_EQ(f.corners.size(), 8u);
  EXPECT_EQ(f.curves.size(), 12u);
  for (const SurfaceCurve& c : f.curves) EXPECT_FALSE(c.closed);
  expect_curves_partition(f);
}

TEST(SurfaceFeatures, ACylinderHasTwoClosedRimsAndNoCorner) {
  const auto cyl = cylinder(16);
  const SurfaceFeatures f = detect_features(*cyl);
  EXPECT_EQ(f.edges.size(), 32u);
  EXPECT_TRUE(f.corners.empty());
  ASSERT_EQ(f.curves.size(), 2u);
  for (const SurfaceCurve& c : f.curves) {
    EXPECT_TRUE(c.closed);
    EXPECT_EQ(c.vertices.size(), 16u);
  }
  expect_curves_partition(f);
  // Below the seams' 22.5 degrees every side edge is a feature too, and the rims' vertices
  // (four feature edges each) are corners.
  const SurfaceFeatures all = detect_features(*cyl, {20, 60});
  EXPECT_EQ(std::set<MeshEdge>(all.edges.begin(), all.edges.end()), test::expected_features(*cyl, 20));
  EXPECT_EQ(all.corners.size(), 32u);
  expect_curves_partition(all);
  // A rim turns by 22.5 degrees at each vertex: with corners from 20 degrees, each is one.
  const SurfaceFeatures turning = detect_features(*cyl, {60, 20});
  EXPECT_EQ(turning.corners.size(), 32u);
  EXPECT_EQ(turning.curves.size(), 32u);
  expect_curves_partition(turning);
}

// Stray folds (short groups of feature edges with a loose end) are dropped as the
// brute-force flood in expected_without_strays finds them, at several angles and lengths.
TEST(SurfaceFeatures, StrayFoldsAreDroppedAsTheIndependentFloodFindsThem) {
  for (const char* file : {"fandisk.off", "joint.off", "elephant.off", "mesh_with_border.off"}) {
    const auto d = test::surface_file(file);
    for (const double angle : {20.0, 45.0, 60.0}) {
      const auto all = test::expected_features(*d, angle);
      for (const double share : {0.01, 0.05, 0.2, 1.0}) {
        SCOPED_TRACE(std::string(file) + " at " + std::to_string(angle) + ", share " +
                     std::to_string(share));
        const SurfaceFeatures f = detect_features(*d, {angle, 60, share});
        EXPECT_EQ(std::set<MeshEdge>(f.edges.begin(), f.edges.end()),
                  test::expected_without_strays(*d, all, share));
        expect_curves_partition(f);
      }
    }
  }
  // The default drops every 60-degree fold of the elephant (71 groups, the longest 15 %
  // of its diagonal) and keeps fandisk's and joint's creases whole.
  EXPECT_EQ(test::expected_features(*test::surface_file("elephant.off"), 60).size(), 167u);
  EXPECT_TRUE(detect_features(*test::surface_file("elephant.off")).edges.empty());
  for (const char* file : {"fandisk.off", "joint.off"}) {
    const auto d = test::surface_file(file);
    EXPECT_EQ(detect_features(*d).edges.size(), test::expected_features(*d, 60).size()) << file;
  }
  EXPECT_THROW(detect_features(*test::surface_file("sphere.off"), {60, 60, -0.1}), InvalidInput);
}

TEST(SurfaceFeatures, RealSurfacesMatchTheIndependentCountAtSeveralAngles) {
  for (const char* file : {"fandisk.off", "joint.off", "elephant.off", "mesh_with_border.off", "sphere.off"}) {
    const auto d = test::surface_file(file);
    for (const double angle : {20.0, 45.0, 60.0, 85.0, 100.0}) {  // none at a tie (CAD parts have many 90s)
      SCOPED_TRACE(std::string(file) + " at " + std::to_string(angle));
      const SurfaceFeatures f = detect_features(*d, {angle, 60, 0});  // every edge by the rule
      EXPECT_EQ(std::set<MeshEdge>(f.edges.begin(), f.edges.end()), test::expected_features(*d, angle));
      expect_curves_partition(f);
    }
  }
  // The smooth sphere has none at 60 degrees, the CAD part many.
  EXPECT_TRUE(detect_features(*test::surface_file("sphere.off")).edges.empty());
  EXPECT_GT(detect_features(*test::surface_file("fandisk.off")).curves.size(), 5u);
}

TEST(SurfaceFeatures, GivenEdgesAreChainedAndBadOnesRefused) {
  const auto box = test::box_surface({1, 1, 1}, {1, 1, 1});
  const SurfaceFeatures detected = detect_features(*box);
  std::vector<MeshEdge> reversed;
  for (const MeshEdge& e : detected.edges) reversed.push_back({e[1], e[0]});
  reversed.push_back(reversed.front());  // a repeat
  const SurfaceFeatures given = features_from_edges(*box, reversed);
  EXPECT_EQ(given.edges, detected.edges);
  EXPECT_EQ(given.corners, detected.corners);
  expect_curves_partition(given);
  EXPECT_THROW(features_from_edges(*box, {{0, 0}}), InvalidInput);
  EXPECT_THROW(features_from_edges(*box, {{0, 1000}}), InvalidInput);
  EXPECT_THROW(detect_features(*box, {0, 60}), InvalidInput);
  EXPECT_THROW(detect_features(*box, {180, 60}), InvalidInput);
  EXPECT_THROW(detect_features(*box, {60, 0}), InvalidInput);
  EXPECT_THROW(detect_features(*box, {std::nan(""), 60}), InvalidInput);
}

TEST(SurfaceFeatures, AFeatureMeetingAnOpenBoundaryEndsThere) {
  // The box without its top face: the four vertical edges run from a bottom corner to
  // the rim, where each ends.
  const auto box = test::box_surface({1, 1, 1}, {1, 1, 1});
  std::vector<SurfaceDomain::Triangle> kept;
  for (const auto& t : box->triangles()) {
    bool top = true;
    for (const std::size_t v : t) top = top && box->vertices()[v].z == 1;
    if (!top) kept.push_back(t);
  }
  const SurfaceDomain open(box->vertices(), kept);
  ASSERT_EQ(open.boundary_loops().size(), 1u);
  const SurfaceFeatures f = detect_features(open);
  EXPECT_EQ(f.edges.size(), 8u);  // the bottom square and the four vertical edges
  EXPECT_EQ(f.corners.size(), 8u);
  EXPECT_EQ(f.curves.size(), 8u);
  expect_curves_partition(f);
}

TEST(SurfaceFeatures, SetOnASurfaceTheyCutItIntoPatchesAndHoldFixedCurves) {
  SurfaceDomain box = *test::box_surface({1.84, 0.4, 0.2}, {4, 3, 2});
  EXPECT_EQ(box.patch_count(), 1u);  // no features: the components
  EXPECT_TRUE(box.fixed_curves().empty());
  const SurfaceFeatures f = detect_features(box);
  box.set_features(f);
  EXPECT_EQ(box.patch_count(), 6u);  // the faces
  EXPECT_EQ(box.fixed_curves().size(), 12u);
  // Each face's triangles share a patch, which no other face has (checked by the plane
  // each triangle lies in: one coordinate constant at 0 or at the box's size).
  std::map<std::pair<int, double>, std::set<std::uint32_t>> by_face;
  for (std::size_t t = 0; t < box.triangles().size(); ++t) {
    const auto& tri = box.triangles()[t];
    for (int axis = 0; axis < 3; ++axis) {
      const auto c = [&](std::size_t v) { return axis == 0 ? box.vertices()[v].x : axis == 1 ? box.vertices()[v].y : box.vertices()[v].z; };
      if (c(tri[0]) == c(tri[1]) && c(tri[1]) == c(tri[2])) by_face[{axis, c(tri[0])}].insert(box.triangle_patch()[t]);
    }
  }
  ASSERT_EQ(by_face.size(), 6u);
  std::set<std::uint32_t> all;
  for (const auto& [face, patches] : by_face) {
    EXPECT_EQ(patches.size(), 1u);
    all.insert(*patches.begin());
  }
  EXPECT_EQ(all.size(), 6u);
  // Bad features are refused: a curve along no feature edge, an open curve not ending at
  // corners, a missing vertex.
  SurfaceFeatures bad = f;
  bad.curves[0].vertices.back() = bad.curves[0].vertices.front();
  EXPECT_THROW(box.set_features(bad), InvalidInput);
  bad = f;
  bad.corners.clear();
  EXPECT_THROW(box.set_features(bad), InvalidInput);
  bad = f;
  bad.curves[0].vertices[0] = 1000000;
  EXPECT_THROW(box.set_features(bad), InvalidInput);
  EXPECT_EQ(box.patch_count(), 6u);  // unchanged by the refused ones
  EXPECT_EQ(box.fixed_curves().size(), 12u);
  box.set_features({});
  EXPECT_EQ(box.patch_count(), 1u);
  EXPECT_TRUE(box.fixed_curves().empty());
}

}  // namespace
}  // namespace disktune
