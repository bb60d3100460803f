// SPDX-License-Identifier: GPL-3.0-or-later
#include "oracle/mesh_topology.h"

#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace oracle {
namespace {

struct Sets {  // union-find with path halving
  std::vector<std::size_t> parent;
  explicit Sets(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  std::size_t find(std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void join(std::size_t a, std::size_t b) { parent[find(a)] = find(b); }
};

}  // namespace

std::string TopologyReport::summary() const {
  std::ostringstream s;
  s << "non-manifold edges " << non_manifold_edges << ", bow-tie vertices " << bow_tie_vertices
    << ", misoriented edges " << misoriented_edges << ", degenerate triangles " << degenerate_triangles
    << ", boundary edges " << boundary_edges << " in " << boundary_loops << " loops, components " << components
    << ", genus " << genus;
  return s.str();
}

TopologyReport check_topology(std::size_t vertex_count, const std::vector<std::array<std::size_t, 3>>& triangles) {
  TopologyReport r;
  // Each undirected edge: the triangles using it and the direction each runs it.
  std::map<std::pair<std::size_t, std::size_t>, std::vector<std::pair<std::size_t, bool>>> edges;
  std::vector<std::vector<std::size_t>> at(vertex_count);  // triangles at each vertex
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const auto& tri = triangles[t];
    for (const std::size_t v : tri)
      if (v >= vertex_count) throw std::invalid_argument("check_topology: a triangle names a missing vertex");
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0]) {
      ++r.degenerate_triangles;
      continue;
    }
    for (int k = 0; k < 3; ++k) {
      const std::size_t a = tri[k], b = tri[(k + 1) % 3];
      edges[{std::min(a, b), std::max(a, b)}].push_back({t, a < b});
      at[a].push_back(t);
    }
  }
  Sets parts(triangles.size());
  for (const auto& [e, uses] : edges) {
    if (uses.size() > 2) ++r.non_manifold_edges;
    if (uses.size() == 1) ++r.boundary_edges;
    if (uses.size() == 2 && uses[0].second == uses[1].second) ++r.misoriented_edges;
    for (std::size_t k = 1; k < uses.size(); ++k) parts.join(uses[0].first, uses[k].first);
  }
  // Fans: the triangles at v joined when they share an edge at v.
  for (std::size_t v = 0; v < vertex_count; ++v) {
    if (at[v].size() < 2) continue;
    std::map<std::size_t, std::size_t> index;
    for (const std::size_t t : at[v]) index.emplace(t, index.size());
    Sets fans(index.size());
    for (const std::size_t t : at[v])
      for (const std::size_t w : triangles[t]) {
        if (w == v) continue;
        for (const auto& [u, dir] : edges.at({std::min(v, w), std::max(v, w)})) fans.join(index.at(t), index.at(u));
      }
    std::set<std::size_t> roots;
    for (std::size_t i = 0; i < index.size(); ++i) roots.insert(fans.find(i));
    if (roots.size() > 1) ++r.bow_tie_vertices;
  }
  // Components, and per component V - E + F and its boundary loops.
  std::map<std::size_t, long> euler;
  std::map<std::size_t, std::size_t> loops;
  std::vector<std::size_t> component_of_vertex(vertex_count, triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const auto& tri = triangles[t];
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0]) continue;
    const std::size_t c = parts.find(t);
    euler[c] += 1;
    for (const std::size_t v : tri) component_of_vertex[v] = c;
  }
  for (std::size_t v = 0; v < vertex_count; ++v)
    if (component_of_vertex[v] < triangles.size()) euler[component_of_vertex[v]] += 1;
  Sets boundary(vertex_count);
  std::set<std::size_t> on_boundary;
  for (const auto& [e, uses] : edges) {
    euler[parts.find(uses[0].first)] -= 1;
    if (uses.size() == 1) boundary.join(e.first, e.second), on_boundary.insert(e.first), on_boundary.insert(e.second);
  }
  std::set<std::size_t> loop_roots;
  for (const std::size_t v : on_boundary)
    if (loop_roots.insert(boundary.find(v)).second) ++loops[component_of_vertex[v]];
  r.boundary_loops = loop_roots.size();
  r.components = euler.size();
  if (r.manifold()) {
    long twice = 0;
    for (const auto& [c, chi] : euler) twice += 2 - chi - static_cast<long>(loops[c]);
    r.genus = static_cast<int>(twice / 2);
  }
  return r;
}

}  // namespace oracle
