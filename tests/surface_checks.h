// SPDX-License-Identifier: GPL-3.0-or-later
// Glue between surface packings and the independent surface oracle.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "disktune/surface_mesh.h"
#include "disktune/surface_packing.h"
#include "oracle/surface_oracle.h"

namespace disktune::test {

inline std::shared_ptr<const SurfaceDomain> surface_file(const std::string& name) {
  return std::make_shared<const SurfaceDomain>(read_surface(std::string(DISKTUNE_DATA_DIR) + "/surfaces/" + name));
}

inline oracle::SurfaceMeshInput oracle_surface(const SurfaceDomain& d) {
  oracle::SurfaceMeshInput m;
  for (const Vec3 v : d.vertices()) m.vertices.push_back({v.x, v.y, v.z});
  for (const auto& t : d.triangles()) m.triangles.push_back({t[0], t[1], t[2]});
  return m;
}

/// The surface of the box [0,lx] x [0,ly] x [0,lz], each face a grid of cells (n[k]
/// along axis k) split into two triangles: with one cell along an axis and several
/// across it, a CAD-like mesh of long slivers meeting at 90 degree edges.
inline std::shared_ptr<const SurfaceDomain> box_surface(const std::array<double, 3>& size,
                                                        const std::array<int, 3>& n) {
  std::vector<Vec3> vertices;
  std::vector<SurfaceDomain::Triangle> triangles;
  std::map<std::array<int, 3>, std::size_t> index;  // grid coordinates -> vertex
  auto vertex = [&](std::array<int, 3> g) {
    const auto [it, added] = index.emplace(g, vertices.size());
    if (added) vertices.push_back({size[0] * g[0] / n[0], size[1] * g[1] / n[1], size[2] * g[2] / n[2]});
    return it->second;
  };
  for (int fixed = 0; fixed < 3; ++fixed) {
    const int a = (fixed + 1) % 3, b = (fixed + 2) % 3;  // (a, b, fixed) is right-handed
    for (const int side : {0, n[fixed]})
      for (int u = 0; u < n[a]; ++u)
        for (int w = 0; w < n[b]; ++w) {
          auto at = [&](int du, int dw) {
            std::array<int, 3> g{};
            g[fixed] = side, g[a] = u + du, g[b] = w + dw;
            return vertex(g);
          };
          std::array<std::size_t, 4> q{at(0, 0), at(1, 0), at(1, 1), at(0, 1)};
          if (side == 0) std::swap(q[1], q[3]);  // normals point out of the box
          triangles.push_back({q[0], q[1], q[2]});
          triangles.push_back({q[0], q[2], q[3]});
        }
  }
  return std::make_shared<const SurfaceDomain>(std::move(vertices), std::move(triangles));
}

/// The triangles at each edge, by brute force over a map of vertex pairs.
inline std::map<MeshEdge, std::vector<std::size_t>> edge_sides(const SurfaceDomain& d) {
  std::map<MeshEdge, std::vector<std::size_t>> sides;
  for (std::size_t t = 0; t < d.triangles().size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const std::size_t a = d.triangles()[t][k], b = d.triangles()[t][(k + 1) % 3];
      sides[{std::min(a, b), std::max(a, b)}].push_back(t);
    }
  return sides;
}

/// The interior edges whose triangles' normals are more than `degrees` apart, computed
// apart from the library: normals from the right-hand rule, angle by atan2.
inline std::set<MeshEdge> expected_features(const SurfaceDomain& d, double degrees) {
  const auto sides = edge_sides(d);
  const auto normal = [&](std::size_t t) {
    const auto& v = d.vertices();
    const auto& tri = d.triangles()[t];
    return cross(v[tri[1]] - v[tri[0]], v[tri[2]] - v[tri[0]]);
  };
  std::set<MeshEdge> out;
  for (const auto& [edge, tris] : sides) {
    if (tris.size() != 2) continue;
    const Vec3 m = normal(tris[0]), n = normal(tris[1]);
    const double angle = std::atan2(norm(cross(m, n)), dot(m, n)) * 180 / 3.14159265358979323846;
    if (angle > degrees) out.insert(edge);
  }
  return out;
}

/// The patches the edges in `cuts` divide the surface into, as a label per triangle
/// (brute force: triangles joined across every other edge they share).
inline std::vector<std::size_t> expected_patches(const SurfaceDomain& d, const std::set<MeshEdge>& cuts) {
  const auto sides = edge_sides(d);
  std::vector<std::size_t> label(d.triangles().size(), d.triangles().size());
  std::vector<std::vector<std::size_t>> next(d.triangles().size());
  for (const auto& [edge, tris] : sides)
    if (tris.size() == 2 && !cuts.count(edge)) next[tris[0]].push_back(tris[1]), next[tris[1]].push_back(tris[0]);
  for (std::size_t t = 0; t < label.size(); ++t) {
    if (label[t] != label.size()) continue;
    std::vector<std::size_t> stack{t};
    label[t] = t;
    while (!stack.empty()) {
      const std::size_t u = stack.back();
      stack.pop_back();
      for (const std::size_t w : next[u])
        if (label[w] == label.size()) label[w] = t, stack.push_back(w);
    }
  }
  return label;
}

/// The point of the surface nearest p (brute force), as a surface point for insert().
inline SurfacePoint nearest_surface_point(const SurfacePacking& packing, Vec3 p) {
  SurfacePoint best{p, 0};
  double best_d2 = std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t < packing.domain().triangles().size(); ++t) {
    const Vec3 q = packing.index().closest_point(t, p);
    if (squared_norm(q - p) < best_d2) best = {q, static_cast<std::uint32_t>(t)}, best_d2 = squared_norm(q - p);
  }
  return best;
}

/// True when p lies within tol of an edge of an open boundary loop (brute force).
inline bool on_open_boundary(const SurfaceDomain& d, Vec3 p, double tol) {
  for (const auto& loop : d.boundary_loops())
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const Vec3 a = d.vertices()[loop[k]], e = d.vertices()[loop[(k + 1) % loop.size()]] - a;
      const double t = std::clamp(dot(p - a, e) / dot(e, e), 0.0, 1.0);
      if (norm(p - (a + e * t)) <= tol) return true;
    }
  return false;
}

/// The oracle's verdict on a surface packing; the fixed disks are the boundary disks
/// (with sharp features, those of them on an open boundary edge).
inline oracle::SurfaceReport surface_report(const SurfacePacking& packing, std::size_t probes_per_triangle = 8) {
  std::vector<oracle::Point3> centers;
  std::vector<double> radii;
  oracle::SurfaceOptions options;
  options.probes_per_triangle = probes_per_triangle;
  const bool features = !packing.domain().features().curves.empty();
  for (const DiskId id : packing.ids()) {
    const Vec3 c = packing.center(id);
    centers.push_back({c.x, c.y, c.z});
    radii.push_back(packing.radius(id));
    bool boundary = packing.flags(id) & kFixed;
    if (boundary && features) boundary = on_open_boundary(packing.domain(), c, 1e-9 * packing.radius(id));
    options.boundary_flags.push_back(boundary ? 1 : 0);
  }
  if (packing.domain().is_closed()) options.boundary_flags.clear();
  return oracle::check_surface(oracle_surface(packing.domain()), centers, radii, options);
}

/// The share of a mesh's angles within [50, 70] degrees and of its triangles with an
/// angle above 90, from the vertex coordinates by the law of cosines (the library uses
/// another formula).
struct AngleShares {
  double near_60 = 0, obtuse = 0;
};
inline AngleShares angle_shares(const SurfaceMesh& m) {
  std::size_t near = 0, obtuse = 0;
  for (const auto& t : m.triangles) {
    bool wide = false;
    for (int k = 0; k < 3; ++k) {
      const Vec3 p = m.vertices[t[k]], q = m.vertices[t[(k + 1) % 3]], s = m.vertices[t[(k + 2) % 3]];
      const double a2 = squared_norm(q - s), b2 = squared_norm(p - q), c2 = squared_norm(p - s);
      const double degrees = std::acos((b2 + c2 - a2) / (2 * std::sqrt(b2 * c2))) * 180 / 3.14159265358979323846;
      near += degrees >= 50 && degrees <= 70;
      wide = wide || degrees > 90;
    }
    obtuse += wide;
  }
  const double n = static_cast<double>(m.triangles.size());
  return {static_cast<double>(near) / (3 * n), static_cast<double>(obtuse) / n};
}

/// Checks the oracle's verdict, with its summary as the failure message.
#define EXPECT_SURFACE_OK(packing)                                   \
  do {                                                               \
    const auto report_ = ::disktune::test::surface_report(packing); \
    EXPECT_TRUE(report_.ok()) << report_.summary();                  \
  } while (0)

}  // namespace disktune::test
