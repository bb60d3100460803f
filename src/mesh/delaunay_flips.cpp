// SPDX-License-Identifier: GPL-3.0-or-later
#include "delaunay_flips.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>

#include "../domain/half_edges.h"
#include "disktune/errors.h"

namespace disktune::detail {
namespace {

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  return a < b ? std::uint64_t{a} << 32 | b : std::uint64_t{b} << 32 | a;
}

// Whether the angles at c and d facing edge ab sum to more than 180 degrees: the sine of
// their sum, times the four edges' lengths, is negative (by more than rounding, so that
// four points on one circle do not flip back and forth).
bool facing_angles_obtuse(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const Vec3 ca = a - c, cb = b - c, da = a - d, db = b - d;
  const double sin_sum = norm(cross(ca, cb)) * dot(da, db) + dot(ca, cb) * norm(cross(da, db));
  return sin_sum < -1e-12 * norm(ca) * norm(cb) * norm(da) * norm(db);
}

}  // namespace

std::size_t flip_toward_delaunay(SurfaceMesh& mesh, const std::vector<Vec3>& now) {
  const std::size_t n = mesh.vertices.size();
  if (now.size() != n) {
    throw InvalidInput("flip_toward_delaunay: " + std::to_string(now.size()) +
                       " points for a mesh of " + std::to_string(n) +
                       " vertices; give one per vertex");
  }
  std::vector<char> dirty(n, 0);
  for (std::size_t v = 0; v < n; ++v) dirty[v] = !(now[v] == mesh.vertices[v]);
  mesh.vertices = now;
  std::vector<std::uint64_t> features;
  for (const auto& e : mesh.feature_edges) features.push_back(edge_key(e[0], e[1]));
  std::sort(features.begin(), features.end());
  const auto holds = [](const std::array<std::uint32_t, 3>& t, std::uint32_t v) {
    return t[0] == v || t[1] == v || t[2] == v;
  };
  auto& tris = mesh.triangles;
  std::size_t flips = 0;
  for (int round = 0; round < 8; ++round) {
    const VertexTriangles around = triangles_by_vertex(tris, n);
    // The corners of a flipped quad are locked for the rest of the round, so the lists
    // around every vertex a later flip reads are still true; they are looked at again
    // in the next round.
    std::vector<char> locked(n, 0), next(n, 0);
    std::size_t made = 0;
    for (std::uint32_t v = 0; v < n; ++v) {
      if (!dirty[v]) continue;
      for (std::size_t i = around.start[v]; i < around.start[v + 1] && !locked[v]; ++i) {
        const std::size_t t = around.by_vertex[i];
        for (int k = 0; k < 3; ++k) {
          const std::uint32_t a = tris[t][k], b = tris[t][(k + 1) % 3], c = tris[t][(k + 2) % 3];
          std::size_t other = t, count = 0;
          for (std::size_t j = around.start[a]; j < around.start[a + 1]; ++j) {
            const std::size_t u = around.by_vertex[j];
            if (u != t && holds(tris[u], b)) other = u, ++count;
          }
          if (count != 1) continue;  // a boundary or a non-manifold edge
          const auto& o = tris[other];
          const int at_b = o[0] == b ? 0 : o[1] == b ? 1 : 2;
          if (o[(at_b + 1) % 3] != a) continue;  // run the same way in both
          const std::uint32_t d = o[(at_b + 2) % 3];
          if (locked[a] || locked[b] || locked[c] || locked[d]) {
            next[v] = 1;
            continue;
          }
          if (c == d || std::binary_search(features.begin(), features.end(), edge_key(a, b)))
            continue;
          const Vec3 pa = now[a], pb = now[b], pc = now[c], pd = now[d];
          if (!facing_angles_obtuse(pa, pb, pc, pd)) continue;
          bool repeated = false;  // cd is an edge already
          for (std::size_t j = around.start[c]; j < around.start[c + 1] && !repeated; ++j)
            repeated = holds(tris[around.by_vertex[j]], d);
          const Vec3 up = cross(pb - pa, pc - pa) + cross(pa - pb, pd - pb);
          if (repeated || !(dot(cross(pa - pc, pd - pc), up) > 0) ||
              !(dot(cross(pb - pd, pc - pd), up) > 0))
            continue;
          tris[t] = {c, a, d};
          tris[other] = {d, b, c};
          for (const std::uint32_t w : {a, b, c, d}) locked[w] = next[w] = 1;
          ++made;
          break;  // t is no longer what this loop read
        }
      }
    }
    flips += made;
    if (made == 0) break;
    dirty.swap(next);
  }
  return flips;
}

}  // namespace disktune::detail
