// SPDX-License-Identifier: GPL-3.0-or-later
// The topology of a surface mesh, counted rather than thrown on (SurfaceDomain refuses
// the first defect; a resampled mesh is reported on whole).
#include <string>
#include <vector>

#include "../domain/half_edges.h"
#include "disktune/errors.h"
#include "disktune/surface_mesh.h"

namespace disktune {
namespace {

using detail::HalfEdge;
using detail::UnionFind;
using Tri = std::array<std::size_t, 3>;

std::vector<Tri> checked_triangles(const SurfaceMesh& mesh) {
  std::vector<Tri> tris;
  tris.reserve(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    for (const std::uint32_t v : tri) {
      if (v >= mesh.vertices.size()) {
        throw InvalidInput("check_surface_mesh: triangle " + std::to_string(t) + " names vertex " +
                           std::to_string(v) + ", but there are only " +
                           std::to_string(mesh.vertices.size()) + " vertices");
      }
    }
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0]) {
      throw InvalidInput("check_surface_mesh: triangle " + std::to_string(t) +
                         " repeats a vertex");
    }
    tris.push_back({tri[0], tri[1], tri[2]});
  }
  return tris;
}

std::string problem_sentence(const SurfaceMeshCheck& c) {
  std::vector<std::string> parts;
  const auto count = [&](std::size_t n, const std::string& what) {
    if (n > 0) parts.push_back(std::to_string(n) + " " + what);
  };
  count(c.non_manifold_edges, "edge(s) in more than two triangles");
  count(c.non_manifold_vertices, "vertex(es) whose triangles form more than one fan (bow ties)");
  if (!c.oriented) parts.push_back("triangles that disagree on orientation across an edge");
  count(c.isolated_vertices, "vertex(es) in no triangle");
  if (parts.empty()) return "";
  std::string s = "the mesh is not a clean surface: ";
  for (std::size_t i = 0; i < parts.size(); ++i) s += (i > 0 ? "; " : "") + parts[i];
  return s +
         ". For a restricted Delaunay mesh this means the samples are too sparse for the "
         "surface's features: sample more densely (a smaller radius)";
}

}  // namespace

SurfaceMeshCheck check_surface_mesh(const SurfaceMesh& mesh) {
  const std::vector<Tri> tris = checked_triangles(mesh);
  const std::size_t nv = mesh.vertices.size();
  const std::vector<HalfEdge> half = detail::sorted_half_edges(tris);
  SurfaceMeshCheck c;
  c.oriented = true;

  // Edges: runs of half-edges on one vertex pair. Boundary edges also join their ends,
  // so each boundary loop becomes one set.
  std::size_t edge_count = 0;
  UnionFind boundary(nv);
  std::vector<char> on_boundary(nv, 0);
  std::vector<std::size_t> edge_lo;  // one end of each edge, to find its component
  detail::for_each_edge(half, [&](std::size_t i, std::size_t j) {
    ++edge_count;
    edge_lo.push_back(half[i].lo);
    if (j - i == 1) {
      ++c.boundary_edges;
      boundary.unite(half[i].lo, half[i].hi);
      on_boundary[half[i].lo] = on_boundary[half[i].hi] = 1;
    } else if (j - i == 2) {
      if (half[i].forward == half[i + 1].forward) c.oriented = false;
    } else {
      ++c.non_manifold_edges;
    }
  });

  const detail::VertexTriangles around = detail::triangles_by_vertex(tris, nv);
  const std::vector<std::size_t>& first = around.start;
  const auto lonely = [&](std::size_t v) { return first[v] == first[v + 1]; };
  for (std::size_t v = 0; v < nv; ++v) {
    if (lonely(v)) {
      ++c.isolated_vertices;
    } else if (detail::fan_count(v, &around.by_vertex[first[v]], first[v + 1] - first[v], tris) >
               1) {
      ++c.non_manifold_vertices;
    }
  }
  c.manifold = c.non_manifold_edges == 0 && c.non_manifold_vertices == 0;

  // Components through triangles, then Euler's formula in each.
  UnionFind uf(nv);
  for (const Tri& t : tris) uf.unite(t[0], t[1]), uf.unite(t[1], t[2]);
  constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  std::vector<std::size_t> comp_of_root(nv, kNone);
  for (std::size_t v = 0; v < nv; ++v) {
    if (!lonely(v) && comp_of_root[uf.find(v)] == kNone) comp_of_root[uf.find(v)] = c.components++;
  }
  const auto comp = [&](std::size_t v) { return comp_of_root[uf.find(v)]; };
  std::vector<long long> euler(c.components, 0), loops(c.components, 0);
  for (std::size_t v = 0; v < nv; ++v) {
    if (lonely(v)) continue;
    ++euler[comp(v)];
    if (on_boundary[v] && boundary.find(v) == v) ++loops[comp(v)], ++c.boundary_loops;  // one root per loop
  }
  for (const std::size_t v : edge_lo) --euler[comp(v)];
  for (const Tri& t : tris) ++euler[comp(t[0])];
  if (c.manifold) {
    long long genus = 0;
    for (std::size_t k = 0; k < c.components; ++k) genus += (2 - loops[k] - euler[k]) / 2;
    c.genus = static_cast<int>(genus);
  }
  c.problems = problem_sentence(c);
  return c;
}

}  // namespace disktune
