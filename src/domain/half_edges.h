// SPDX-License-Identifier: GPL-3.0-or-later
// The edges of a triangle mesh, each side once, and the fans around a vertex (internal):
// what the planar domain reader, the surface domain and the surface mesh check test
// manifoldness, orientation and boundaries with.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <tuple>
#include <vector>

#include "union_find.h"

namespace disktune::detail {

/// One side of an edge: the triangle that holds it and which way it runs there.
struct HalfEdge {
  std::size_t lo, hi, tri;
  bool forward;  // runs lo -> hi in its triangle
};

/// Every triangle's three edges, sorted so that the sides of one edge are adjacent.
inline std::vector<HalfEdge> sorted_half_edges(const std::vector<std::array<std::size_t, 3>>& tris) {
  std::vector<HalfEdge> out;
  out.reserve(3 * tris.size());
  for (std::size_t t = 0; t < tris.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const std::size_t a = tris[t][k], b = tris[t][(k + 1) % 3];
      out.push_back({std::min(a, b), std::max(a, b), t, a < b});
    }
  }
  std::sort(out.begin(), out.end(), [](const HalfEdge& p, const HalfEdge& q) {
    return std::tie(p.lo, p.hi, p.tri) < std::tie(q.lo, q.hi, q.tri);
  });
  return out;
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

/// How many fans the triangles `around` vertex v form: v is a manifold vertex iff its
/// link (the edges opposite v) is connected, one piece.
inline std::size_t fan_count(std::size_t v, const std::vector<std::size_t>& around,
                             const std::vector<std::array<std::size_t, 3>>& tris) {
  std::vector<std::size_t> nb;
  for (const std::size_t t : around) {
    for (const std::size_t w : tris[t]) {
      if (w != v) nb.push_back(w);
    }
  }
  std::sort(nb.begin(), nb.end());
  nb.erase(std::unique(nb.begin(), nb.end()), nb.end());
  const auto local = [&](std::size_t w) {
    return static_cast<std::size_t>(std::lower_bound(nb.begin(), nb.end(), w) - nb.begin());
  };
  UnionFind link(nb.size());
  std::size_t pieces = nb.size();
  for (const std::size_t t : around) {
    std::size_t other[2], n = 0;
    for (const std::size_t w : tris[t]) {
      if (w != v) other[n++] = w;
    }
    if (link.unite(local(other[0]), local(other[1]))) --pieces;
  }
  return pieces;
}

}  // namespace disktune::detail
