// SPDX-License-Identifier: GPL-3.0-or-later
// The edges of a triangle mesh, each side once, and the fans around a vertex (internal):
// what the planar domain reader, the surface domain and the surface mesh check test
// manifoldness, orientation and boundaries with.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <numeric>
#include <tuple>
#include <vector>

#include "union_find.h"

namespace disktune::detail {

/// One side of an edge: the triangle that holds it and which way it runs there.
struct HalfEdge {
  std::size_t lo, hi, tri;
  bool forward;  // runs lo -> hi in its triangle
};

/// Every triangle's three edges, sorted so that the sides of one edge are adjacent (by
/// lo, hi, then triangle). Bucketed by lo first, so the sort only orders the few
/// half-edges of each vertex: a restricted Delaunay mesh's check sorted 6·10^4 of them
/// whole each time.
template <class Index>
std::vector<HalfEdge> sorted_half_edges(const std::vector<std::array<Index, 3>>& tris) {
  std::vector<HalfEdge> out(3 * tris.size());
  const auto before = [](const HalfEdge& p, const HalfEdge& q) {
    return std::tie(p.lo, p.hi, p.tri) < std::tie(q.lo, q.hi, q.tri);
  };
  std::size_t top = 0;
  for (const auto& t : tris)
    top = std::max({top, std::size_t{t[0]}, std::size_t{t[1]}, std::size_t{t[2]}});
  // Where the indices are sparse (a few triangles naming far vertices), one plain sort.
  const bool bucketed = top <= 4 * out.size();
  std::vector<std::size_t> start(bucketed ? top + 2 : 0, 0);
  for (std::size_t t = 0; t < tris.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const std::size_t a = tris[t][k], b = tris[t][(k + 1) % 3];
      out[3 * t + k] = {std::min(a, b), std::max(a, b), t, a < b};
      if (bucketed) ++start[std::min(a, b) + 1];
    }
  }
  if (!bucketed) {
    std::sort(out.begin(), out.end(), before);
    return out;
  }
  for (std::size_t v = 1; v < start.size(); ++v) start[v] += start[v - 1];
  std::vector<HalfEdge> sorted(out.size());
  std::vector<std::size_t> next(start.begin(), start.end() - 1);
  for (const HalfEdge& e : out) sorted[next[e.lo]++] = e;
  for (std::size_t v = 0; v + 1 < start.size(); ++v)
    std::sort(sorted.begin() + static_cast<std::ptrdiff_t>(start[v]),
              sorted.begin() + static_cast<std::ptrdiff_t>(start[v + 1]), before);
  return sorted;
}

/// Calls f(first, last) for each run [first, last) of sorted half-edges on one edge.
template <class F>
void for_each_edge(const std::vector<HalfEdge>& half, F&& f) {
  for (std::size_t i = 0; i < half.size();) {
    std::size_t j = i + 1;
    while (j < half.size() && half[j].lo == half[i].lo && half[j].hi == half[i].hi) ++j;
    f(i, j);
    i = j;
  }
}

/// The triangles around each vertex in one array: vertex v's are
/// by_vertex[start[v], start[v + 1]), in increasing order (a vector per vertex cost a
/// mesh check 10^4 allocations).
struct VertexTriangles {
  std::vector<std::size_t> start, by_vertex;
};

template <class Index>
VertexTriangles triangles_by_vertex(const std::vector<std::array<Index, 3>>& tris,
                                    std::size_t vertex_count) {
  VertexTriangles out{std::vector<std::size_t>(vertex_count + 1, 0),
                      std::vector<std::size_t>(3 * tris.size())};
  for (const auto& t : tris)
    for (const Index v : t) ++out.start[v + 1];
  for (std::size_t v = 0; v < vertex_count; ++v) out.start[v + 1] += out.start[v];
  std::vector<std::size_t> next(out.start.begin(), out.start.end() - 1);
  for (std::size_t t = 0; t < tris.size(); ++t)
    for (const Index v : tris[t]) out.by_vertex[next[v]++] = t;
  return out;
}

/// Whether some edge lies in more than two of the triangles (vertices below
/// `vertex_count`), read around each vertex: each edge ab, a < b, once per triangle at a.
template <class Index>
bool some_edge_in_three(const std::vector<std::array<Index, 3>>& tris, std::size_t vertex_count) {
  const VertexTriangles around = triangles_by_vertex(tris, vertex_count);
  std::vector<Index> ends;
  for (std::size_t a = 0; a < vertex_count; ++a) {
    ends.clear();
    for (std::size_t k = around.start[a]; k < around.start[a + 1]; ++k)
      for (const Index b : tris[around.by_vertex[k]])
        if (b > a) ends.push_back(b);
    std::sort(ends.begin(), ends.end());
    for (std::size_t i = 0; i + 2 < ends.size(); ++i)
      if (ends[i] == ends[i + 2]) return true;
  }
  return false;
}

/// How many fans the triangles around[0, count) of vertex v form: v is a manifold vertex
/// iff its link (the edges opposite v) is connected, one piece. Scratch kept per thread:
/// a mesh check asks this of every vertex.
inline std::size_t fan_count(std::size_t v, const std::size_t* around, std::size_t count,
                             const std::vector<std::array<std::size_t, 3>>& tris) {
  thread_local std::vector<std::size_t> nb;
  thread_local UnionFind link(0);
  nb.clear();
  for (std::size_t i = 0; i < count; ++i) {
    for (const std::size_t w : tris[around[i]]) {
      if (w != v) nb.push_back(w);
    }
  }
  std::sort(nb.begin(), nb.end());
  nb.erase(std::unique(nb.begin(), nb.end()), nb.end());
  const auto local = [&](std::size_t w) {
    return static_cast<std::size_t>(std::lower_bound(nb.begin(), nb.end(), w) - nb.begin());
  };
  link.parent.resize(nb.size());
  std::iota(link.parent.begin(), link.parent.end(), std::size_t{0});
  std::size_t pieces = nb.size();
  for (std::size_t i = 0; i < count; ++i) {
    std::size_t other[2], n = 0;
    for (const std::size_t w : tris[around[i]]) {
      if (w != v) other[n++] = w;
    }
    if (link.unite(local(other[0]), local(other[1]))) --pieces;
  }
  return pieces;
}

inline std::size_t fan_count(std::size_t v, const std::vector<std::size_t>& around,
                             const std::vector<std::array<std::size_t, 3>>& tris) {
  return fan_count(v, around.data(), around.size(), tris);
}

}  // namespace disktune::detail
