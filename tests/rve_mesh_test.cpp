// SPDX-License-Identifier: GPL-3.0-or-later
// The fiber RVE's periodic FE mesh (rve_mesh.h), checked by brute force here, not by the
// mesher's own code: triangles tile the cell (positive areas summing to W H, every edge
// in two triangles but those on the sides), the side nodes found by scanning all nodes
// pair up exactly across the period, every fiber-matrix interface node lies on its
// fiber's circle, each triangle's material agrees with where its centroid lies, and each
// fiber's triangles cover its disk but the polygon's sagitta. The .inp is read back by a
// small Abaqus reader written here, the .msh by Gmsh's own (rve_msh_gmsh_test.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "disktune/errors.h"
#include "disktune/rve.h"
#include "disktune/rve_mesh.h"

namespace disktune {
namespace {

constexpr double kPi = 3.14159265358979323846;

Rve make(double vf, std::uint64_t seed, double width = 8, double diameter = 1) {
  RveSpec spec;
  spec.width = spec.height = width;
  spec.diameter = diameter;
  spec.gap = 0.05 * diameter;
  spec.fiber_fraction = vf;
  spec.seed = seed;
  return make_rve(spec);
}

double periodic_distance(Vec2 a, Vec2 b, double w, double h) {
  double dx = a.x - b.x, dy = a.y - b.y;
  dx -= w * std::round(dx / w), dy -= h * std::round(dy / h);
  return std::hypot(dx, dy);
}

// Everything a mesh of `rve` must be, with `segments` per fiber boundary.
::testing::AssertionResult valid_mesh(const Rve& rve, const RveMesh& m, std::size_t segments) {
  const double w = rve.cell.width(), h = rve.cell.height();
  const auto radius = [&](std::size_t k) { return rve.diameters.at(k) / 2; };
  const double smallest = *std::min_element(rve.diameters.begin(), rve.diameters.end());
  if (m.triangles.size() != m.material.size()) return ::testing::AssertionFailure() << "material count";
  for (const Vec2 p : m.nodes) {
    if (!(p.x >= 0 && p.x <= w && p.y >= 0 && p.y <= h)) {
      return ::testing::AssertionFailure() << "node (" << p.x << ", " << p.y << ") outside the cell";
    }
  }
  // Areas: positive, summing to the cell; per fiber, its disk less at most the sagitta
  // strips of a polygon whose edges are no longer than 1.5 times the asked segment.
  std::vector<double> fiber_area(rve.centers.size() + 1, 0);
  double total = 0;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const auto& tri = m.triangles[t];
    const Vec2 a = m.nodes[tri[0]], b = m.nodes[tri[1]], c = m.nodes[tri[2]];
    const double area = cross(b - a, c - a) / 2;
    if (!(area > 0)) return ::testing::AssertionFailure() << "triangle " << t << " has area " << area;
    total += area;
    if (m.material[t] > rve.centers.size()) return ::testing::AssertionFailure() << "material " << m.material[t];
    fiber_area[m.material[t]] += area;
    // The centroid lies in its own fiber's disk; a matrix triangle's, in no fiber's
    // (but for the sliver between a chord and its arc).
    const Vec2 centroid{(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3};
    for (std::size_t k = 0; k < rve.centers.size(); ++k) {
      const double d = periodic_distance(centroid, rve.centers[k], w, h);
      if (m.material[t] == k + 1 && d > radius(k)) {
        return ::testing::AssertionFailure() << "triangle " << t << " of fiber " << k << " has its centroid " << d
                                             << " from its center, radius " << radius(k);
      }
      if (m.material[t] == 0 && d < 0.95 * radius(k)) {
        return ::testing::AssertionFailure() << "matrix triangle " << t << " lies inside fiber " << k;
      }
    }
  }
  if (std::abs(total - w * h) > 1e-9 * w * h) return ::testing::AssertionFailure() << "area " << total << " of " << w * h;
  // Segments of the smallest fiber's length, 1.5 times at most.
  const double longest = 1.5 * kPi * smallest / static_cast<double>(segments);
  for (std::size_t k = 1; k < fiber_area.size(); ++k) {
    const double chord_angle = 2 * std::asin(std::min(1.0, longest / (2 * radius(k - 1))));
    const double sagitta_share = 1 - std::sin(chord_angle) / chord_angle;  // an inscribed polygon's deficit
    const double disk = kPi * radius(k - 1) * radius(k - 1);
    if (!(fiber_area[k] <= disk * (1 + 1e-9) && fiber_area[k] >= disk * (1 - sagitta_share))) {
      return ::testing::AssertionFailure() << "fiber " << k - 1 << " has area " << fiber_area[k] << " for a disk of "
                                           << disk;
    }
  }
  // Edges: two triangles each, but boundary edges, which lie on a side; interface
  // edges (fiber against matrix) have both ends on their fiber's circle.
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> edges;
  for (std::uint32_t t = 0; t < m.triangles.size(); ++t) {
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = m.triangles[t][i], b = m.triangles[t][(i + 1) % 3];
      edges[{std::min(a, b), std::max(a, b)}].push_back(t);
    }
  }
  std::vector<std::size_t> interface_edges(fiber_area.size(), 0);
  std::size_t boundary_edges = 0;
  for (const auto& [e, tris] : edges) {
    const Vec2 a = m.nodes[e.first], b = m.nodes[e.second];
    if (tris.size() == 1) {
      ++boundary_edges;
      const bool on_side = (a.x == 0 && b.x == 0) || (a.x == w && b.x == w) || (a.y == 0 && b.y == 0) ||
                           (a.y == h && b.y == h);
      if (!on_side) return ::testing::AssertionFailure() << "a boundary edge inside the cell";
      continue;
    }
    if (tris.size() != 2) return ::testing::AssertionFailure() << "an edge of " << tris.size() << " triangles";
    const std::uint32_t m0 = m.material[tris[0]], m1 = m.material[tris[1]];
    if (m0 == m1) continue;
    if (m0 != 0 && m1 != 0) return ::testing::AssertionFailure() << "fibers " << m0 << " and " << m1 << " touch";
    const std::uint32_t fiber = std::max(m0, m1);
    ++interface_edges[fiber];
    for (const Vec2 p : {a, b}) {
      const double d = periodic_distance(p, rve.centers[fiber - 1], w, h);
      if (std::abs(d - radius(fiber - 1)) > 1e-6 * radius(fiber - 1)) {
        return ::testing::AssertionFailure() << "an interface node " << d << " from fiber " << fiber - 1;
      }
    }
  }
  for (std::size_t k = 1; k < interface_edges.size(); ++k) {
    // A fiber cut by a side has more pieces, each with its own ends.
    const double share = rve.diameters[k - 1] / smallest;  // larger fibers: more segments of that length
    if (interface_edges[k] < segments * 3 / 4 || interface_edges[k] > segments * 2 * share) {
      return ::testing::AssertionFailure() << "fiber " << k - 1 << " has " << interface_edges[k]
                                           << " boundary segments for " << segments;
    }
  }
  // The side nodes, found by scanning all nodes: pairs across the period, exactly.
  std::vector<std::uint32_t> left, right, bottom, top;
  for (std::uint32_t n = 0; n < m.nodes.size(); ++n) {
    const Vec2 p = m.nodes[n];
    const bool corner = (p.x == 0 || p.x == w) && (p.y == 0 || p.y == h);
    if (corner) continue;
    if (p.x == 0) left.push_back(n);
    if (p.x == w) right.push_back(n);
    if (p.y == 0) bottom.push_back(n);
    if (p.y == h) top.push_back(n);
  }
  const auto same_set = [](std::vector<std::uint32_t> a, std::vector<std::uint32_t> b) {
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    return a == b;
  };
  if (!same_set(left, m.left) || !same_set(right, m.right) || !same_set(bottom, m.bottom) || !same_set(top, m.top)) {
    return ::testing::AssertionFailure() << "the side lists are not the nodes on the sides";
  }
  if (m.left.size() != m.right.size() || m.bottom.size() != m.top.size()) {
    return ::testing::AssertionFailure() << "sides of " << m.left.size() << "/" << m.right.size() << " and "
                                         << m.bottom.size() << "/" << m.top.size() << " nodes";
  }
  for (std::size_t i = 0; i < m.left.size(); ++i) {
    if (m.nodes[m.left[i]].y != m.nodes[m.right[i]].y || (i > 0 && !(m.nodes[m.left[i]].y > m.nodes[m.left[i - 1]].y))) {
      return ::testing::AssertionFailure() << "left/right pair " << i << " differs";
    }
  }
  for (std::size_t i = 0; i < m.bottom.size(); ++i) {
    if (m.nodes[m.bottom[i]].x != m.nodes[m.top[i]].x ||
        (i > 0 && !(m.nodes[m.bottom[i]].x > m.nodes[m.bottom[i - 1]].x))) {
      return ::testing::AssertionFailure() << "bottom/top pair " << i << " differs";
    }
  }
  if (boundary_edges != 2 * (m.left.size() + 1) + 2 * (m.bottom.size() + 1)) {
    return ::testing::AssertionFailure() << boundary_edges << " boundary edges";
  }
  const Vec2 corner_at[4] = {{0, 0}, {w, 0}, {w, h}, {0, h}};
  for (int c = 0; c < 4; ++c) {
    if (!(m.nodes[m.corners[c]] == corner_at[c])) return ::testing::AssertionFailure() << "corner " << c;
  }
  // The reported shape, recomputed.
  double least = 180;
  for (const auto& tri : m.triangles) {
    for (int i = 0; i < 3; ++i) {
      const Vec2 p = m.nodes[tri[i]], u = m.nodes[tri[(i + 1) % 3]] - p, v = m.nodes[tri[(i + 2) % 3]] - p;
      least = std::min(least, std::acos(std::clamp(dot(u, v) / (norm(u) * norm(v)), -1.0, 1.0)) * 180 / kPi);
    }
  }
  if (std::abs(least - m.angles.min) > 1e-6) {
    return ::testing::AssertionFailure() << "smallest angle " << least << " reported as " << m.angles.min;
  }
  return ::testing::AssertionSuccess();
}

TEST(RveMesh, TilesTheCellWithMatchedSidesOverSeeds) {
  for (const double vf : {0.5, 0.65}) {
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
      const Rve rve = make(vf, seed);
      const RveMesh mesh = mesh_rve(rve);
      EXPECT_TRUE(valid_mesh(rve, mesh, 24)) << "vf " << vf << " seed " << seed;
      EXPECT_GT(mesh.angles.min, 15) << "vf " << vf << " seed " << seed;
      EXPECT_GE(mesh.radius_ratio.min, 1 - 1e-9);
    }
  }
}

TEST(RveMesh, UnequalFibersEachOnTheirOwnCircle) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    RveSpec spec;
    spec.width = spec.height = 8, spec.diameter = 1, spec.gap = 0.05, spec.diameter_cv = 0.1;
    spec.fiber_fraction = 0.65, spec.seed = seed;
    const Rve rve = make_rve(spec);
    const RveMesh mesh = mesh_rve(rve);
    EXPECT_TRUE(valid_mesh(rve, mesh, 24)) << "seed " << seed;
    EXPECT_GT(mesh.angles.min, 15) << "seed " << seed;
  }
}

TEST(RveMesh, SegmentsElementSizeAndUnits) {
  // Fibers of 7 micrometres in metres: Gmsh meshes in units of the diameter.
  const Rve micro = make(0.6, 5, 8 * 7e-6, 7e-6);
  RveMeshSpec spec;
  spec.fiber_segments = 40;
  const RveMesh fine = mesh_rve(micro, spec);
  EXPECT_TRUE(valid_mesh(micro, fine, 40));
  spec.fiber_segments = 12;
  spec.element_size = 0.5 * 7e-6;
  const RveMesh coarse = mesh_rve(micro, spec);
  EXPECT_TRUE(valid_mesh(micro, coarse, 12));
  EXPECT_LT(coarse.triangles.size() * 4, fine.triangles.size());
}

TEST(RveMesh, SameFibersSameMesh) {
  const Rve rve = make(0.6, 9);
  const RveMesh a = mesh_rve(rve), b = mesh_rve(rve);
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  EXPECT_TRUE(std::equal(a.nodes.begin(), a.nodes.end(), b.nodes.begin()));
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.material, b.material);
}

TEST(RveMesh, SidesAndCornersKeepClearOfFibers) {
  // make_rve translates the arrangement so that the sides keep clear of the lines where
  // a fiber would touch them, and the corner of every fiber boundary. Over 2N tangent
  // lines per direction the widest gap is at least W / (2N); measured here, the sides
  // and the corner keep at least a quarter of that.
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const Rve rve = make(0.65, seed);
    const double w = rve.cell.width(), radius = rve.diameter / 2;
    double sides = INFINITY, corner = INFINITY;
    for (const Vec2 c : rve.centers) {
      for (const double along : {c.x, c.y}) sides = std::min(sides, std::abs(std::min(along, w - along) - radius));
      corner = std::min(corner, std::abs(periodic_distance(c, {0, 0}, w, w) - radius));
    }
    const double n = static_cast<double>(rve.centers.size());
    EXPECT_GE(sides, w / (8 * n)) << "seed " << seed;
    EXPECT_GE(corner, w / (8 * n)) << "seed " << seed;
    EXPECT_EQ(mesh_rve(rve).side_clearance, sides);
  }
}

TEST(RveMesh, RefusesWhatItCannotMesh) {
  Rve rve = make(0.5, 2);
  const auto refused = [](const Rve& r, const RveMeshSpec& spec, const std::string& says) {
    try {
      mesh_rve(r, spec);
    } catch (const InvalidInput& e) {
      return std::string(e.what()).find(says) != std::string::npos ? ::testing::AssertionSuccess()
                                                                    : ::testing::AssertionFailure() << e.what();
    }
    return ::testing::AssertionFailure() << "accepted";
  };
  RveMeshSpec spec;
  spec.fiber_segments = 5;
  EXPECT_TRUE(refused(rve, spec, "segments"));
  spec = {};
  spec.element_size = 1e-4;
  EXPECT_TRUE(refused(rve, spec, "element size"));
  spec.element_size = NAN;
  EXPECT_TRUE(refused(rve, spec, "element size"));
  spec = {};
  spec.max_memory = 1e5;
  try {
    mesh_rve(rve, spec);
    ADD_FAILURE() << "accepted";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.remedy(), InvalidInput::Remedy::memory) << e.what();
  }
  Rve touching = rve;
  touching.gap = 0;
  EXPECT_TRUE(refused(touching, {}, "gap"));
  Rve at_side = rve;
  at_side.centers[0].x = at_side.diameter / 2;  // tangent to the left side
  EXPECT_TRUE(refused(at_side, {}, "touches a side"));
  Rve unsized = rve;
  unsized.diameters.pop_back();
  EXPECT_TRUE(refused(unsized, {}, "one diameter per fiber"));
  RveSpec asked;
  asked.width = asked.height = 8;
  asked.diameter = 1;
  asked.fiber_fraction = 0.5;
  EXPECT_THROW(check_rve_mesh(asked, {}), InvalidInput);  // gap 0
  asked.gap = 0.02;
  EXPECT_NO_THROW(check_rve_mesh(asked, {}));
}

// The .inp by a reader written here: every node and element, the sets' sizes, and the
// pairs of LEFT and RIGHT at equal y.
TEST(RveMesh, AbaqusInputHoldsTheSets) {
  const Rve rve = make(0.6, 4);
  const RveMesh mesh = mesh_rve(rve);
  const std::string path = (std::filesystem::temp_directory_path() / "disktune_rve_mesh_test.inp").string();
  write_rve_inp(path, mesh);
  std::ifstream in(path);
  std::map<std::string, std::vector<long>> sets;
  std::map<long, std::pair<double, double>> node_at;
  std::size_t elements = 0;
  std::string line, section, name;
  while (std::getline(in, line)) {
    if (line.rfind("**", 0) == 0) continue;
    if (line[0] == '*') {
      section = line.substr(0, line.find(','));
      const auto eq = line.find('=');
      name = eq == std::string::npos ? "" : line.substr(eq + 1, line.find(',', eq) - eq - 1);
      continue;
    }
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream row(line);
    if (section == "*Node") {
      long id;
      double x, y;
      row >> id >> x >> y;
      node_at[id] = {x, y};
    } else if (section == "*Element") {
      ++elements;
    } else {
      for (long id; row >> id;) sets[name].push_back(id);
    }
  }
  EXPECT_EQ(node_at.size(), mesh.nodes.size());
  EXPECT_EQ(elements, mesh.triangles.size());
  EXPECT_EQ(sets["MATRIX"].size() + sets["FIBERS"].size(), mesh.triangles.size());
  std::size_t per_fiber = 0;
  for (std::size_t k = 1; k <= rve.centers.size(); ++k) per_fiber += sets["FIBER-" + std::to_string(k)].size();
  EXPECT_EQ(per_fiber, sets["FIBERS"].size());
  ASSERT_EQ(sets["LEFT"].size(), sets["RIGHT"].size());
  ASSERT_EQ(sets["BOTTOM"].size(), sets["TOP"].size());
  for (std::size_t i = 0; i < sets["LEFT"].size(); ++i) {
    EXPECT_EQ(node_at[sets["LEFT"][i]].first, 0.0);
    EXPECT_EQ(node_at[sets["RIGHT"][i]].first, mesh.width);
    EXPECT_EQ(node_at[sets["LEFT"][i]].second, node_at[sets["RIGHT"][i]].second);
  }
  for (std::size_t i = 0; i < sets["BOTTOM"].size(); ++i) {
    EXPECT_EQ(node_at[sets["BOTTOM"][i]].first, node_at[sets["TOP"][i]].first);
  }
  for (int c = 1; c <= 4; ++c) EXPECT_EQ(sets["CORNER-" + std::to_string(c)].size(), 1u);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace disktune
