// SPDX-License-Identifier: GPL-3.0-or-later
// The edges of a triangle mesh, each side once (internal): what the planar domain
// reader and the surface domain check manifoldness, orientation and boundaries with.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <tuple>
#include <vector>

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

}  // namespace disktune::detail
