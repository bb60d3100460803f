// SPDX-License-Identifier: GPL-3.0-or-later
// Feature edges by the angle between the normals of their two triangles, less stray
// folds (short groups with a loose end), then chained:
// corners first (where the curve cannot go on in one way), each curve walked from a
// corner to the next, and what is left forms closed loops.
#include "disktune/surface_features.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "disktune/errors.h"
#include "half_edges.h"
#include "union_find.h"

namespace disktune {
namespace {

constexpr double kDegree = 3.14159265358979323846 / 180;

Vec3 unit_normal(const SurfaceDomain& d, std::size_t t) {
  const auto& tri = d.triangles()[t];
  const Vec3 a = d.vertices()[tri[0]];
  const Vec3 n = cross(d.vertices()[tri[1]] - a, d.vertices()[tri[2]] - a);
  return n * (1 / norm(n));
}

void check_angles(const FeatureOptions& o, bool need_angle) {
  if (need_angle && !(o.angle > 0 && o.angle < 180)) {
    std::ostringstream msg;
    msg << "feature angle must lie strictly between 0 and 180 degrees, got " << o.angle;
    throw InvalidInput(msg.str());
  }
  if (!(o.corner_angle > 0 && o.corner_angle <= 180)) {
    std::ostringstream msg;
    msg << "feature corner angle must lie in (0, 180] degrees, got " << o.corner_angle;
    throw InvalidInput(msg.str());
  }
  if (!(o.stray_length >= 0)) {
    std::ostringstream msg;
    msg << "feature stray length must be at least 0 (a share of the bounding-box diagonal), got "
        << o.stray_length;
    throw InvalidInput(msg.str());
  }
}

// 1 for each vertex on an open boundary.
std::vector<char> vertices_on_boundary(const SurfaceDomain& d) {
  std::vector<char> on(d.vertices().size(), 0);
  for (const auto& loop : d.boundary_loops())
    for (const std::size_t v : loop) on[v] = 1;
  return on;
}

// `edges` less the groups (connected through shared vertices) that have a loose end and
// are shorter than o.stray_length times the bounding-box diagonal.
std::vector<MeshEdge> without_stray_folds(const SurfaceDomain& d, std::vector<MeshEdge> edges,
                                          const FeatureOptions& o) {
  if (o.stray_length <= 0 || edges.empty()) return edges;
  const std::size_t n = d.vertices().size();
  std::vector<std::size_t> edges_at(n, 0);
  detail::UnionFind groups(n);
  for (const MeshEdge& e : edges) {
    ++edges_at[e[0]], ++edges_at[e[1]];
    groups.unite(e[0], e[1]);
  }
  const std::vector<char> on_boundary = vertices_on_boundary(d);
  std::vector<double> length(n, 0);
  std::vector<char> loose(n, 0);
  for (const MeshEdge& e : edges) {
    const std::size_t g = groups.find(e[0]);
    length[g] += norm(d.vertices()[e[1]] - d.vertices()[e[0]]);
    for (const std::size_t v : e)
      if (edges_at[v] == 1 && !on_boundary[v]) loose[g] = 1;
  }
  const double limit = o.stray_length * norm(d.bbox_max() - d.bbox_min());
  std::vector<MeshEdge> kept;
  for (const MeshEdge& e : edges) {
    const std::size_t g = groups.find(e[0]);
    if (!loose[g] || length[g] >= limit) kept.push_back(e);
  }
  return kept;
}

// Corners and curves of a set of feature edges (sorted, each once, all interior edges).
SurfaceFeatures chain(const SurfaceDomain& d, std::vector<MeshEdge> edges, const FeatureOptions& o) {
  SurfaceFeatures f;
  f.edges = std::move(edges);
  const std::size_t n = d.vertices().size();
  // Each vertex's feature edges (by index into f.edges).
  std::vector<std::vector<std::size_t>> at(n);
  for (std::size_t e = 0; e < f.edges.size(); ++e)
    for (const std::size_t v : f.edges[e]) at[v].push_back(e);
  const std::vector<char> on_boundary = vertices_on_boundary(d);
  const auto other = [&](std::size_t e, std::size_t v) { return f.edges[e][0] == v ? f.edges[e][1] : f.edges[e][0]; };
  std::vector<char> corner(n, 0);
  const double straight = std::cos(o.corner_angle * kDegree);
  for (std::size_t v = 0; v < n; ++v) {
    if (at[v].empty()) continue;
    bool is_corner = at[v].size() != 2 || on_boundary[v];
    if (!is_corner) {
      const Vec3 p = d.vertices()[v];
      const Vec3 in = p - d.vertices()[other(at[v][0], v)], out = d.vertices()[other(at[v][1], v)] - p;
      is_corner = dot(in, out) < straight * norm(in) * norm(out);  // turns by more than corner_angle
    }
    if (is_corner) {
      corner[v] = 1;
      f.corners.push_back(v);
    }
  }
  std::vector<char> used(f.edges.size(), 0);
  // Walks from v along edge e until a corner, or back to the start of a loop.
  const auto walk = [&](std::size_t v, std::size_t e) {
    SurfaceCurve c;
    const std::size_t start = v;
    c.vertices.push_back(v);
    for (;;) {
      used[e] = 1;
      v = other(e, v);
      if (v == start && !corner[v]) {  // a loop with no corner
        c.closed = true;
        break;
      }
      c.vertices.push_back(v);
      if (corner[v]) break;
      e = at[v][0] == e ? at[v][1] : at[v][0];  // two feature edges at a non-corner
    }
    f.curves.push_back(std::move(c));
  };
  for (const std::size_t v : f.corners)
    for (const std::size_t e : at[v])
      if (!used[e]) walk(v, e);
  for (std::size_t e = 0; e < f.edges.size(); ++e)
    if (!used[e]) walk(f.edges[e][0], e);
  return f;
}

}  // namespace

SurfaceFeatures detect_features(const SurfaceDomain& domain, const FeatureOptions& options) {
  check_angles(options, true);
  const double limit = std::cos(options.angle * kDegree);
  const auto half = detail::sorted_half_edges(domain.triangles());
  std::vector<MeshEdge> edges;
  detail::for_each_edge(half, [&](std::size_t first, std::size_t last) {
    if (last - first != 2) return;  // a boundary edge
    // The normals differ by more than the angle: their cosine is below its cosine.
    if (dot(unit_normal(domain, half[first].tri), unit_normal(domain, half[first + 1].tri)) < limit)
      edges.push_back({half[first].lo, half[first].hi});
  });
  return chain(domain, without_stray_folds(domain, std::move(edges), options), options);
}

SurfaceFeatures features_from_edges(const SurfaceDomain& domain, std::vector<MeshEdge> edges,
                                    const FeatureOptions& options) {
  check_angles(options, false);
  for (MeshEdge& e : edges)
    if (e[0] > e[1]) std::swap(e[0], e[1]);
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  const auto half = detail::sorted_half_edges(domain.triangles());
  std::vector<MeshEdge> interior;
  detail::for_each_edge(half, [&](std::size_t first, std::size_t last) {
    if (last - first == 2) interior.push_back({half[first].lo, half[first].hi});
  });  // sorted, as the half-edges are
  for (const MeshEdge& e : edges) {
    if (!std::binary_search(interior.begin(), interior.end(), e)) {
      std::ostringstream msg;
      msg << "feature edge (" << e[0] << ", " << e[1] << ") is not an edge between two triangles of the surface"
          << " (vertices are numbered from 0; boundary edges are boundaries already)";
      throw InvalidInput(msg.str());
    }
  }
  return chain(domain, std::move(edges), options);
}

}  // namespace disktune
