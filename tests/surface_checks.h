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

/// `edges` less the stray folds (FeatureOptions::stray_length), by brute force: each
/// edge's group found by a flood over edges that share a vertex, its length summed and
/// its vertices on one edge of the set looked for on the open boundary.
inline std::set<MeshEdge> expected_without_strays(const SurfaceDomain& d,
                                                  const std::set<MeshEdge>& edges, double share) {
  std::map<std::size_t, std::vector<MeshEdge>> at;
  for (const MeshEdge& e : edges) at[e[0]].push_back(e), at[e[1]].push_back(e);
  std::set<std::size_t> boundary;
  for (const auto& [edge, tris] : edge_sides(d))
    if (tris.size() == 1) boundary.insert(edge[0]), boundary.insert(edge[1]);
  const Vec3 span = d.bbox_max() - d.bbox_min();
  const double limit = share * std::sqrt(dot(span, span));
  std::set<MeshEdge> kept, seen;
  for (const MeshEdge& first : edges) {
    if (seen.count(first)) continue;
    std::vector<MeshEdge> group{first}, stack{first};
    seen.insert(first);
    while (!stack.empty()) {
      const MeshEdge e = stack.back();
      stack.pop_back();
      for (const std::size_t v : e)
        for (const MeshEdge& f : at[v])
          if (seen.insert(f).second) group.push_back(f), stack.push_back(f);
    }
    double length = 0;
    bool loose = false;
    for (const MeshEdge& e : group) {
      const Vec3 a = d.vertices()[e[0]], b = d.vertices()[e[1]];
      length += std::sqrt(dot(b - a, b - a));
      for (const std::size_t v : e) loose = loose || (at[v].size() == 1 && !boundary.count(v));
    }
    if (!loose || length >= limit) kept.insert(group.begin(), group.end());
  }
  return kept;
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

/// The surface's feature edges as the domain holds them (input data, like the triangles).
inline std::set<MeshEdge> feature_cuts(const SurfaceDomain& d) {
  std::set<MeshEdge> cuts;
  for (const auto& e : d.features().edges) cuts.insert(e);
  return cuts;
}

/// Adds a patch's verdict to the whole one; `global` maps the patch's disk numbers to
/// the packing's (in ids() order).
inline void merge_report(oracle::SurfaceReport& all, const oracle::SurfaceReport& part,
                         const std::vector<std::size_t>& global) {
  all.on_surface_checked = all.on_surface_checked && part.on_surface_checked;
  all.conflicts_checked = all.conflicts_checked && part.conflicts_checked;
  all.maximality_checked = all.maximality_checked && part.maximality_checked;
  all.boundary_checked = all.boundary_checked && part.boundary_checked;
  all.triangles += part.triangles;
  all.boundary_edges += part.boundary_edges;
  all.boundary_count += part.boundary_count;
  all.tol = part.tol;
  for (auto o : part.off_surface) o.i = global[o.i], all.off_surface.push_back(o);
  all.off_surface_count += part.off_surface_count;
  for (auto c : part.conflicts) c.i = global[c.i], c.j = global[c.j], all.conflicts.push_back(c);
  all.conflict_count += part.conflict_count;
  for (auto c : part.covered_centers) c.i = global[c.i], c.j = global[c.j], all.covered_centers.push_back(c);
  all.covered_center_count += part.covered_center_count;
  all.uncovered.insert(all.uncovered.end(), part.uncovered.begin(), part.uncovered.end());
  all.uncovered_count += part.uncovered_count;
  for (auto o : part.off_boundary) o.i = global[o.i], all.off_boundary.push_back(o);
  all.off_boundary_count += part.off_boundary_count;
  all.boundary_gaps.insert(all.boundary_gaps.end(), part.boundary_gaps.begin(), part.boundary_gaps.end());
  all.boundary_gap_count += part.boundary_gap_count;
  all.min_distance = std::min(all.min_distance, part.min_distance);
  all.max_probe_gap = std::max(all.max_probe_gap, part.max_probe_gap);
  all.probes += part.probes;
  all.candidates += part.candidates;
}

/// The labels (of `label`, one per triangle) of the triangles of `among` within tol of
/// c: the patches a point lies on (brute force, a bounding-ball test first).
inline std::set<std::size_t> patches_at(const SurfaceDomain& d, const std::vector<std::size_t>& label, Vec3 c,
                                        double tol, const std::vector<std::size_t>& among) {
  std::set<std::size_t> on;
  for (const std::size_t t : among) {
    if (on.count(label[t])) continue;
    const auto& tri = d.triangles()[t];
    const Vec3 a = d.vertices()[tri[0]], b = d.vertices()[tri[1]], e = d.vertices()[tri[2]];
    const double reach = std::max(norm(b - a), norm(e - a)) + tol;
    if (squared_norm(c - a) > reach * reach) continue;
    const oracle::SurfaceMeshInput one{{{a.x, a.y, a.z}, {b.x, b.y, b.z}, {e.x, e.y, e.z}}, {{0, 1, 2}}};
    if (oracle::distance_to_surface(one, {c.x, c.y, c.z}) <= tol) on.insert(label[t]);
  }
  return on;
}

/// The same among all triangles.
inline std::set<std::size_t> patches_at(const SurfaceDomain& d, const std::vector<std::size_t>& label, Vec3 c,
                                        double tol) {
  std::vector<std::size_t> all(d.triangles().size());
  for (std::size_t t = 0; t < all.size(); ++t) all[t] = t;
  return patches_at(d, label, c, tol, all);
}

/// The same for a point said to lie in triangle t: among the triangles sharing a vertex
/// with t (`at_vertex`: the triangles at each vertex), or all where none is in reach;
/// t's alone where none is (the oracle then judges how far off the surface it is).
inline std::set<std::size_t> patches_at(const SurfaceDomain& d, const std::vector<std::size_t>& label, Vec3 c,
                                        double tol, std::size_t t,
                                        const std::vector<std::vector<std::size_t>>& at_vertex) {
  std::vector<std::size_t> among;
  for (const std::size_t v : d.triangles()[t]) among.insert(among.end(), at_vertex[v].begin(), at_vertex[v].end());
  std::set<std::size_t> on = patches_at(d, label, c, tol, among);
  if (on.empty()) on = patches_at(d, label, c, tol);
  if (on.empty()) on.insert(label[t]);
  return on;
}

/// The patches sharp features cut the surface into, as a label per triangle (found from
/// the domain's feature edges, apart from the library); one label without features.
inline std::vector<std::size_t> patch_labels(const SurfaceDomain& d) {
  return d.features().edges.empty() ? std::vector<std::size_t>(d.triangles().size(), 0)
                                    : expected_patches(d, feature_cuts(d));
}

/// The oracle's verdict on disks (centers, radii; `fixed` flags the disks on feature
/// curves and open boundaries) that lie on the patches `on` of the surface, patch by
/// patch, as the packing's rule is (surface_packing.h: a disk covers and conflicts only
/// on the patches it counts on): each patch is checked alone, with its triangles and
/// the disks on it. The fixed disks on an open boundary edge are the boundary disks
/// (which must cover it); `check_boundary` false skips that check (for disks whose flags
/// are not known). Feature curves are the rim of their patches, but a curve near an
/// acute corner may be held by the disks of the other curve there, so their holding is
/// checked apart (surface_feature_sampling_test.cpp, `unheld_edges`).
inline oracle::SurfaceReport patch_report(const SurfaceDomain& d, const std::vector<std::size_t>& label,
                                          const std::vector<Vec3>& centers_in, const std::vector<double>& radii_in,
                                          const std::vector<bool>& fixed,
                                          const std::vector<std::set<std::size_t>>& on,
                                          std::size_t probes_per_triangle = 8, bool check_boundary = true) {
  const bool features = !d.features().edges.empty();
  std::map<std::size_t, std::vector<std::size_t>> patches;  // label -> its triangles
  for (std::size_t t = 0; t < label.size(); ++t) patches[label[t]].push_back(t);
  const oracle::SurfaceMeshInput whole = oracle_surface(d);
  oracle::SurfaceReport all;
  all.on_surface_checked = all.conflicts_checked = all.maximality_checked = all.boundary_checked = true;
  all.n = centers_in.size();
  all.r = radii_in.empty() ? 0 : *std::max_element(radii_in.begin(), radii_in.end());
  all.r_min = radii_in.empty() ? 0 : *std::min_element(radii_in.begin(), radii_in.end());
  for (const auto& [name, triangles] : patches) {
    oracle::SurfaceMeshInput part{whole.vertices, {}};
    for (const std::size_t t : triangles) part.triangles.push_back(whole.triangles[t]);
    std::vector<oracle::Point3> centers;
    std::vector<double> radii;
    std::vector<std::size_t> global;
    oracle::SurfaceOptions options;
    options.probes_per_triangle = probes_per_triangle;
    for (std::size_t i = 0; i < centers_in.size(); ++i) {
      if (!on[i].count(name)) continue;
      const Vec3 c = centers_in[i];
      centers.push_back({c.x, c.y, c.z});
      radii.push_back(radii_in[i]);
      global.push_back(i);
      const bool boundary = fixed[i] && (!features || on_open_boundary(d, c, 1e-9 * radii_in[i]));
      options.boundary_flags.push_back(boundary ? 1 : 0);
    }
    if (d.is_closed() || !check_boundary) options.boundary_flags.clear();
    if (centers.empty()) {  // nothing covers this patch
      ++all.uncovered_count;
      const Vec3 v = d.vertices()[d.triangles()[triangles.front()][0]];
      all.uncovered.push_back({v.x, v.y, v.z, triangles.front(), "a patch without a disk on it"});
      continue;
    }
    merge_report(all, oracle::check_surface(part, centers, radii, options), global);
  }
  return all;
}

/// The patches each disk lies on, as the packing's rule has it: a free disk on the patch
/// of its triangle (`triangles`), a fixed disk on those of the triangles within 1e-9
/// r_max of its center (r_max the largest radius: the library's tolerance).
inline std::vector<std::set<std::size_t>> disk_patches(const SurfaceDomain& d, const std::vector<std::size_t>& label,
                                                       const std::vector<Vec3>& centers,
                                                       const std::vector<std::uint32_t>& triangles,
                                                       const std::vector<bool>& fixed, double r_max) {
  const bool features = !d.features().edges.empty();
  std::vector<std::vector<std::size_t>> at_vertex(d.vertices().size());
  if (features)
    for (std::size_t t = 0; t < d.triangles().size(); ++t)
      for (const std::size_t v : d.triangles()[t]) at_vertex[v].push_back(t);
  std::vector<std::set<std::size_t>> on;
  for (std::size_t i = 0; i < centers.size(); ++i) {
    if (features && fixed[i]) {
      on.push_back(patches_at(d, label, centers[i], 1e-9 * r_max, triangles[i], at_vertex));
    } else {
      on.push_back({label[triangles[i]]});
    }
  }
  return on;
}

/// The oracle's verdict on a surface packing, patch by patch (patch_report, disk_patches).
/// The fixed disks are the boundary disks.
inline oracle::SurfaceReport surface_report(const SurfacePacking& packing, std::size_t probes_per_triangle = 8) {
  const SurfaceDomain& d = packing.domain();
  const std::vector<std::size_t> label = patch_labels(d);
  std::vector<Vec3> centers;
  std::vector<double> radii;
  std::vector<std::uint32_t> triangles;
  std::vector<bool> fixed;
  for (const DiskId id : packing.ids()) {
    centers.push_back(packing.center(id));
    radii.push_back(packing.radius(id));
    triangles.push_back(packing.point(id).triangle);
    fixed.push_back(packing.flags(id) & kFixed);
  }
  const auto on = disk_patches(d, label, centers, triangles, fixed, packing.max_radius());
  return patch_report(d, label, centers, radii, fixed, on, probes_per_triangle);
}

/// The same for the vertices of a remeshed surface (RemeshResult: the mesh's vertices,
/// their radii, input triangles and flags).
template <class Result>
oracle::SurfaceReport remesh_report(const SurfaceDomain& d, const Result& r) {
  const std::vector<std::size_t> label = patch_labels(d);
  const double r_max = r.radii.empty() ? 0 : *std::max_element(r.radii.begin(), r.radii.end());
  const auto on = disk_patches(d, label, r.mesh.vertices, r.input_triangles, r.on_curves, r_max);
  return patch_report(d, label, r.mesh.vertices, r.radii, r.on_curves, on);
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
