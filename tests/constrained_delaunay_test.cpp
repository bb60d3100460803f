// SPDX-License-Identifier: GPL-3.0-or-later
// The constrained Delaunay mesh of a packing in a domain with holes, checked by plain
// geometry written here (none of the library's): the triangles tile the domain (areas
// add up, centroids inside by an even-odd test), keep every boundary segment as an
// edge, turn counterclockwise, and have empty circumcircles wherever no constraint
// separates. Then the refusals, and the mesh files.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "disktune/errors.h"
#include "disktune/mesh.h"
#include "disktune/mesh_io.h"
#include "test_util.h"

namespace disktune {
namespace {

using Polygon = std::vector<Vec2>;
using Loops = std::vector<std::vector<DiskId>>;

double cross(Vec2 a, Vec2 b, Vec2 c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

/// Even-odd rule: a horizontal ray from p crosses the polygon an odd number of times.
bool inside(const Polygon& poly, Vec2 p) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Vec2 a = poly[i], b = poly[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) {
      in = !in;
    }
  }
  return in;
}

double polygon_area(const Polygon& poly) {
  double twice = 0;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    twice += poly[j].x * poly[i].y - poly[i].x * poly[j].y;
  }
  return std::abs(twice) / 2;
}

double segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double t =
      std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

/// The corners of a polygon with `per_side` - 1 extra points on each side, evenly spaced
/// (so consecutive boundary points are collinear).
Polygon subdivide(const Polygon& corners, int per_side) {
  Polygon out;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Vec2 a = corners[i], b = corners[(i + 1) % corners.size()];
    for (int k = 0; k < per_side; ++k) {
      const double t = static_cast<double>(k) / per_side;
      out.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
    }
  }
  return out;
}

/// A packing, the loops of disks on its boundary polygons, and those polygons.
struct Scene {
  Packing packing{Frame{{-0.5, -0.5}, {3, 3}, false}, 0.01};
  Loops loops;
  std::vector<Polygon> polygons;  // polygons[0] outer, the others holes

  void add_loop(const Polygon& poly) {
    polygons.push_back(poly);
    loops.emplace_back();
    for (const Vec2 p : poly) loops.back().push_back(packing.insert(p, 0.01, kFixed));
  }
  double boundary_distance(Vec2 p) const {
    double d = INFINITY;
    for (const Polygon& poly : polygons) {
      for (std::size_t i = 0; i < poly.size(); ++i) {
        d = std::min(d, segment_distance(p, poly[i], poly[(i + 1) % poly.size()]));
      }
    }
    return d;
  }
  /// `count` random disks in [lo, hi]^2 at least `gap` from the boundary: inside the
  /// domain, in the holes and outside, where they must stay out of every triangle.
  void scatter(int count, double lo, double hi, double gap, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    auto u = [&] { return lo + (hi - lo) * static_cast<double>(rng() >> 11) * 0x1.0p-53; };
    while (count > 0) {
      const Vec2 p{u(), u()};
      if (boundary_distance(p) < gap) continue;
      packing.insert(p, 0.01);
      --count;
    }
  }
  bool in_domain(Vec2 p) const {
    if (!inside(polygons[0], p)) return false;
    for (std::size_t k = 1; k < polygons.size(); ++k) {
      if (inside(polygons[k], p)) return false;
    }
    return true;
  }
  double domain_area() const {
    double a = polygon_area(polygons[0]);
    for (std::size_t k = 1; k < polygons.size(); ++k) a -= polygon_area(polygons[k]);
    return a;
  }
};

/// Every property the mesh must have, checked from the scene alone. At least
/// `free_share` of the triangles must be far enough from the boundary for the
/// plain empty-circle test.
void expect_valid(const Scene& s, const PlanarMesh& m, double free_share = 0.25) {
  // Vertices: the live disks, in increasing id order.
  const std::vector<DiskId> ids = s.packing.ids();
  ASSERT_EQ(m.vertex_disk, ids);
  ASSERT_EQ(m.vertices.size(), ids.size());
  for (std::size_t i = 0; i < ids.size(); ++i) EXPECT_EQ(m.vertices[i], s.packing.center(ids[i]));
  ASSERT_FALSE(m.triangles.empty());

  double area = 0;
  std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (const auto& t : m.triangles) {
    for (const std::uint32_t v : t) ASSERT_LT(v, m.vertices.size());
    const Vec2 a = m.vertices[t[0]], b = m.vertices[t[1]], c = m.vertices[t[2]];
    const double twice = cross(a, b, c);
    EXPECT_GT(twice, 0) << "triangle not counterclockwise";
    area += twice / 2;
    const Vec2 g{(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3};
    EXPECT_TRUE(s.in_domain(g)) << "centroid (" << g.x << ", " << g.y << ") outside the domain";
    for (int k = 0; k < 3; ++k) {
      edges.insert(std::minmax(t[k], t[(k + 1) % 3]));
    }
  }
  EXPECT_NEAR(area, s.domain_area(), 1e-12 * s.domain_area());

  // Each id's vertex index, to name the constrained pairs.
  std::vector<std::uint32_t> vertex_of(s.packing.id_bound(), UINT32_MAX);
  for (std::size_t i = 0; i < ids.size(); ++i) vertex_of[ids[i]] = static_cast<std::uint32_t>(i);
  std::vector<std::pair<Vec2, Vec2>> segments;
  for (const auto& loop : s.loops) {
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const DiskId a = loop[i], b = loop[(i + 1) % loop.size()];
      EXPECT_TRUE(edges.count(std::minmax(vertex_of[a], vertex_of[b])))
          << "boundary segment " << a << "-" << b << " is not a mesh edge";
      segments.emplace_back(s.packing.center(a), s.packing.center(b));
    }
  }

  // Delaunay where no constraint is near: a circumcircle that meets no boundary segment
  // sees every center inside it, so none may be strictly inside.
  std::size_t checked = 0;
  for (const auto& t : m.triangles) {
    const Vec2 a = m.vertices[t[0]], b = m.vertices[t[1]], c = m.vertices[t[2]];
    const double bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y;
    const double d = 2 * (bx * cy - by * cx);
    const double ux = (cy * (bx * bx + by * by) - by * (cx * cx + cy * cy)) / d;
    const double uy = (bx * (cx * cx + cy * cy) - cx * (bx * bx + by * by)) / d;
    const Vec2 o{a.x + ux, a.y + uy};
    const double R = std::hypot(ux, uy);
    const bool meets = std::any_of(segments.begin(), segments.end(), [&](const auto& seg) {
      return segment_distance(o, seg.first, seg.second) <= R * (1 + 1e-9);
    });
    if (meets) continue;
    ++checked;
    for (const Vec2 p : m.vertices) {
      EXPECT_FALSE(std::hypot(p.x - o.x, p.y - o.y) < R * (1 - 1e-9))
          << "(" << p.x << ", " << p.y << ") inside the circumcircle of a triangle";
    }
  }
  EXPECT_GE(checked, free_share * m.triangles.size()) << "too few triangles away from the boundary";
}

Scene square_with_square_hole(bool hole_clockwise) {
  Scene s;
  s.add_loop(subdivide({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 20));
  Polygon hole{{0.4, 0.4}, {0.6, 0.4}, {0.6, 0.6}, {0.4, 0.6}};
  if (hole_clockwise) std::reverse(hole.begin(), hole.end());
  s.add_loop(subdivide(hole, 4));
  // Random disks in and around the domain (some in the hole, some outside).
  s.scatter(400, -0.2, 1.2, 0.01, 7);
  return s;
}

TEST(ConstrainedDelaunay, SquareWithHoleTilesTheDomain) {
  for (const bool clockwise : {true, false}) {  // the hole's orientation does not matter
    const Scene s = square_with_square_hole(clockwise);
    const PlanarMesh m = constrained_delaunay(s.packing, s.loops);
    EXPECT_NEAR(s.domain_area(), 0.96, 1e-15);
    expect_valid(s, m);
  }
}

TEST(ConstrainedDelaunay, VerticesAreTheLiveDisksAroundRemovedIds) {
  Scene s;
  const DiskId gone = s.packing.insert({0.5, 0.5}, 0.01);
  s.add_loop(subdivide({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 5));
  s.scatter(50, 0, 1, 0.02, 3);
  s.packing.remove(gone);  // ids no longer 0..n-1
  expect_valid(s, constrained_delaunay(s.packing, s.loops));
}

TEST(ConstrainedDelaunay, NonConvexLShapeWithCollinearBoundaryPoints) {
  Scene s;
  s.add_loop(subdivide({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, 4));
  {
    // The boundary alone: the hull's notch at the reflex corner must stay empty. (Every
    // triangle touches the boundary, so no circumcircle is free of it.)
    const PlanarMesh m = constrained_delaunay(s.packing, s.loops);
    expect_valid(s, m, 0);
  }
  s.scatter(300, -0.3, 2.3, 0.02, 11);
  const PlanarMesh m = constrained_delaunay(s.packing, s.loops);
  EXPECT_DOUBLE_EQ(s.domain_area(), 3);
  expect_valid(s, m);
}

TEST(ConstrainedDelaunay, CocircularLatticeAndAnIsland) {
  // A square lattice (four centers on every circle) with the loops on lattice points:
  // an outer square, a hole, and an island inside the hole (odd nesting level again).
  Scene s;
  const int n = 17;  // points per side, spacing 1/16
  const double h = 1.0 / (n - 1);
  std::vector<std::vector<DiskId>> at(n, std::vector<DiskId>(n));
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) at[j][i] = s.packing.insert({i * h, j * h}, 0.01);
  }
  auto ring = [&](int i0, int i1) {  // the lattice square [i0, i1]^2, counterclockwise
    std::vector<DiskId> loop;
    Polygon poly;
    auto add = [&](int i, int j) {
      loop.push_back(at[j][i]);
      poly.push_back({i * h, j * h});
    };
    for (int i = i0; i < i1; ++i) add(i, i0);
    for (int j = i0; j < i1; ++j) add(i1, j);
    for (int i = i1; i > i0; --i) add(i, i1);
    for (int j = i1; j > i0; --j) add(i0, j);
    s.loops.push_back(loop);
    s.polygons.push_back(poly);
  };
  ring(0, 16);
  ring(4, 12);
  const PlanarMesh m1 = constrained_delaunay(s.packing, s.loops);
  expect_valid(s, m1);
  EXPECT_EQ(m1.triangles.size(), 2u * (16 * 16 - 8 * 8));

  ring(6, 10);  // an island in the hole: in_domain() below counts it in by hand
  const PlanarMesh m2 = constrained_delaunay(s.packing, s.loops);
  EXPECT_EQ(m2.triangles.size(), 2u * (16 * 16 - 8 * 8 + 4 * 4));
  double area = 0;
  for (const auto& t : m2.triangles) {
    area += cross(m2.vertices[t[0]], m2.vertices[t[1]], m2.vertices[t[2]]) / 2;
  }
  EXPECT_NEAR(area, (256.0 - 64 + 16) * h * h, 1e-12);
}

TEST(ConstrainedDelaunay, ManyPointsAndARoundHole) {
  // 2e5 disks: range insertion must keep this well under a second.
  Scene s;
  s.add_loop(subdivide({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 400));
  Polygon circle;
  for (int k = 0; k < 500; ++k) {
    const double a = 2 * 3.14159265358979323846 * k / 500;
    circle.push_back({0.5 + 0.25 * std::cos(a), 0.5 + 0.25 * std::sin(a)});
  }
  s.add_loop(circle);
  // Scattered here: Scene::scatter's brute-force distance is too slow for this many.
  std::mt19937_64 rng(5);
  auto u = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  for (int count = 200000; count > 0;) {
    const Vec2 p{u(), u()};
    const double to_square = std::min({p.x, p.y, 1 - p.x, 1 - p.y});
    if (to_square < 1e-3 || std::abs(std::hypot(p.x - 0.5, p.y - 0.5) - 0.25) < 1e-3) continue;
    s.packing.insert(p, 0.01);
    --count;
  }
  const PlanarMesh m = constrained_delaunay(s.packing, s.loops);
  double area = 0;
  std::size_t wrong_side = 0;
  for (const auto& t : m.triangles) {
    const Vec2 a = m.vertices[t[0]], b = m.vertices[t[1]], c = m.vertices[t[2]];
    ASSERT_GT(cross(a, b, c), 0);
    area += cross(a, b, c) / 2;
    const Vec2 g{(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3};
    wrong_side += std::hypot(g.x - 0.5, g.y - 0.5) < 0.25 * std::cos(3.14159265358979 / 500);
  }
  EXPECT_NEAR(area, s.domain_area(), 1e-12 * s.domain_area());
  EXPECT_EQ(wrong_side, 0u);
}

void expect_refused(const Packing& packing, const Loops& loops, const std::string& words) {
  try {
    constrained_delaunay(packing, loops);
    ADD_FAILURE() << "accepted; expected an error with '" << words << "'";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(ConstrainedDelaunay, RefusesBadLoops) {
  Scene s;
  s.add_loop({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  const Loops& sq = s.loops;
  expect_refused(s.packing, {}, "no boundary loops");
  expect_refused(s.packing, {{sq[0][0], sq[0][1]}}, "loop 0 has 2 disks");
  expect_refused(s.packing, {sq[0], {sq[0][0], sq[0][1]}}, "loop 1 has 2 disks");
  expect_refused(s.packing, {{sq[0][0], sq[0][2], 99}}, "disk 99");
  const DiskId dead = s.packing.insert({0.5, 0.5}, 0.01);
  s.packing.remove(dead);
  expect_refused(s.packing, {{sq[0][0], sq[0][1], dead}}, "not a live disk");
  expect_refused(s.packing, {sq[0], {sq[0][1], sq[0][2], sq[0][3]}}, "appears twice");

  // A second square overlapping the first: their edges cross.
  Scene x = s;
  x.add_loop({{0.5, 0.5}, {1.5, 0.5}, {1.5, 1.5}, {0.5, 1.5}});
  expect_refused(x.packing, x.loops, "boundary loops cross");
  // A hole whose corner pokes out through the outer edge.
  Scene y = s;
  y.add_loop({{0.4, 0.4}, {1.2, 0.5}, {0.5, 0.6}});
  expect_refused(y.packing, y.loops, "boundary loops cross");
  // A loop crossing itself (a bow tie).
  Scene z;
  z.add_loop({{0, 0}, {1, 1}, {1, 0}, {0, 1}});
  expect_refused(z.packing, z.loops, "boundary loops cross");
  // A segment through a disk that is not on the loop.
  Scene w = s;
  w.packing.insert({0.5, 0}, 0.01);
  expect_refused(w.packing, w.loops, "passes through");
  // Two disks at one point.
  Scene v = s;
  v.packing.insert({0.3, 0.3}, 0.01);
  v.packing.insert({0.3, 0.3}, 0.01);
  expect_refused(v.packing, v.loops, "the same center");
}

TEST(MeshIo, PlanarMeshInEveryFormat) {
  test::TempDir dir;
  const Scene s = square_with_square_hole(true);
  const PlanarMesh m = constrained_delaunay(s.packing, s.loops);
  for (const char* name : {"m.off", "m.obj", "m.vtk"}) write_mesh(dir.file(name), m);
  write_mesh_svg(dir.file("m.svg"), m, s.packing);

  std::ifstream off(dir.file("m.off"));
  std::string magic;
  std::size_t nv = 0, nf = 0, ne = 1;
  off >> magic >> nv >> nf >> ne;
  EXPECT_EQ(magic, "OFF");
  EXPECT_EQ(nv, m.vertices.size());
  EXPECT_EQ(nf, m.triangles.size());
  EXPECT_EQ(ne, 0u);

  auto text = [&](const char* name) {
    std::ifstream in(dir.file(name));
    std::stringstream all;
    all << in.rdbuf();
    return all.str();
  };
  const std::string obj = text("m.obj");
  std::size_t faces = 0;
  for (std::size_t at = obj.find("\nf "); at != std::string::npos; at = obj.find("\nf ", at + 1)) {
    ++faces;
  }
  EXPECT_EQ(faces, m.triangles.size());
  // The triangles, then the boundary edges as lines (one per disk on a boundary loop).
  std::size_t on_loops = 0;
  for (const auto& loop : s.loops) on_loops += loop.size();
  ASSERT_EQ(m.boundary_edges.size(), on_loops);
  const std::size_t nt = m.triangles.size();
  const std::string vtk = text("m.vtk");
  EXPECT_NE(vtk.find("CELLS " + std::to_string(nt + on_loops) + " " +
                     std::to_string(4 * nt + 3 * on_loops) + "\n"),
            std::string::npos);
  EXPECT_EQ(std::count(obj.begin(), obj.end(), '\n') - std::count(obj.begin(), obj.end(), '#'),
            static_cast<std::ptrdiff_t>(m.vertices.size() + nt + on_loops));  // v, f and l lines
  EXPECT_NE(vtk.find("SCALARS disk_id unsigned_int 1\nLOOKUP_TABLE default\n"), std::string::npos);
  const std::string svg = text("m.svg");
  EXPECT_NE(svg.find("<circle"), std::string::npos);
  EXPECT_NE(svg.find("fill=\"#f0a0a0\""), std::string::npos);  // the fixed boundary disks
  EXPECT_NE(svg.find("<path fill=\"none\""), std::string::npos);
  EXPECT_EQ(svg.substr(svg.size() - 7), "</svg>\n");
}

}  // namespace
}  // namespace disktune
