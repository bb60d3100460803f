// SPDX-License-Identifier: GPL-3.0-or-later
#include "bow_tie_caps.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "../domain/half_edges.h"

namespace disktune::detail {
namespace {

using Tri = std::array<std::uint32_t, 3>;

std::pair<std::uint32_t, std::uint32_t> edge(std::uint32_t a, std::uint32_t b) { return std::minmax(a, b); }

// One fan of vertex v: its triangles (v, rim[i], rim[i + 1]) around a closed rim.
struct Fan {
  std::vector<std::size_t> triangles;
  std::vector<std::uint32_t> rim;
};

// The fans of v: the link edges a -> b (triangle (v, a, b) in its own order) split into
// closed cycles. Two fans may touch at a link vertex, which is then left twice (a pinch:
// the fans share the edge from v to it); walks start at pinches and close on coming back.
// Empty unless every link edge lies on a simple closed cycle.
std::vector<Fan> closed_fans(const SurfaceMesh& mesh, std::uint32_t v, const std::vector<std::size_t>& around) {
  std::multimap<std::uint32_t, std::size_t> from;  // link edges a -> b, by a: their triangles
  std::map<std::uint32_t, int> balance;            // edges out less edges in, per link vertex
  const auto link = [&](std::size_t t) {
    const Tri& tri = mesh.triangles[t];
    const int k = static_cast<int>(std::find(tri.begin(), tri.end(), v) - tri.begin());
    return std::pair<std::uint32_t, std::uint32_t>{tri[(k + 1) % 3], tri[(k + 2) % 3]};
  };
  for (const std::size_t t : around) {
    const auto [a, b] = link(t);
    from.emplace(a, t);
    ++balance[a], --balance[b];
  }
  for (const auto& [a, n] : balance)
    if (n != 0 || from.count(a) > 2) return {};  // open, or more than two fans at one vertex
  std::vector<std::uint32_t> starts;  // pinches first
  for (const auto& [a, unused] : balance) starts.push_back(a);
  std::stable_partition(starts.begin(), starts.end(), [&](std::uint32_t a) { return from.count(a) == 2; });
  std::set<std::size_t> used;
  const auto next_edge = [&](std::uint32_t a) {
    const auto range = from.equal_range(a);
    for (auto it = range.first; it != range.second; ++it)
      if (!used.count(it->second)) return it->second;
    return mesh.triangles.size();
  };
  std::vector<Fan> fans;
  for (const std::uint32_t start : starts)
    while (next_edge(start) != mesh.triangles.size()) {
      Fan fan;
      std::set<std::uint32_t> on_rim;
      for (std::uint32_t a = start;;) {
        const std::size_t t = next_edge(a);
        if (t == mesh.triangles.size() || !on_rim.insert(a).second) return {};  // stuck, or not simple
        used.insert(t);
        fan.triangles.push_back(t);
        fan.rim.push_back(a);
        a = link(t).second;
        if (a == start) break;
      }
      fans.push_back(std::move(fan));
    }
  return fans;
}

// Whether v's link edges a -> b close into one simple cycle: the common case, settled
// without the maps closed_fans needs.
bool one_closed_fan(const SurfaceMesh& mesh, std::uint32_t v, const std::vector<std::size_t>& around) {
  std::vector<std::array<std::uint32_t, 2>> link;
  for (const std::size_t t : around) {
    const Tri& tri = mesh.triangles[t];
    const int k = static_cast<int>(std::find(tri.begin(), tri.end(), v) - tri.begin());
    link.push_back({tri[(k + 1) % 3], tri[(k + 2) % 3]});
  }
  std::size_t steps = 1;
  for (std::uint32_t at = link[0][1]; at != link[0][0]; ++steps) {
    std::size_t next = link.size(), found = 0;
    for (std::size_t i = 0; i < link.size(); ++i)
      if (link[i][0] == at) next = i, ++found;
    if (found != 1 || steps == link.size()) return false;
    at = link[next][1];
  }
  return steps == link.size();
}

// The rim's plane: its Newell normal (unit; the rim runs counterclockwise about it) and
// its centroid.
struct Plane {
  Vec3 normal, center;
};
Plane rim_plane(const std::vector<Vec3>& p, const std::vector<std::uint32_t>& rim) {
  Vec3 n{0, 0, 0}, c{0, 0, 0};
  for (std::size_t i = 0; i < rim.size(); ++i) {
    n = n + cross(p[rim[i]], p[rim[(i + 1) % rim.size()]]);
    c = c + p[rim[i]];
  }
  const double len = norm(n);
  return {len > 0 ? n * (1 / len) : n, c * (1.0 / static_cast<double>(rim.size()))};
}

// How far the fan stands out of its rim's plane, for the rim's size.
double height_ratio(const std::vector<Vec3>& p, std::uint32_t v, const Fan& fan) {
  const Plane plane = rim_plane(p, fan.rim);
  double spread = 0;
  for (const std::uint32_t r : fan.rim) spread += norm(p[r] - plane.center);
  spread /= static_cast<double>(fan.rim.size());
  return spread > 0 ? std::abs(dot(p[v] - plane.center, plane.normal)) / spread : 0;
}

// Ear clipping of the rim in its plane, keeping its orientation: triangles (a, b, c)
// with a, b, c in rim order. Empty if no ear is found (a rim that folds over itself).
std::vector<Tri> clip_ears(const std::vector<Vec3>& p, std::vector<std::uint32_t> rim, Vec3 normal) {
  const auto turn = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    return dot(cross(p[b] - p[a], p[c] - p[b]), normal);
  };
  const auto inside = [&](std::uint32_t q, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    return turn(a, b, q) >= 0 && turn(b, c, q) >= 0 && turn(c, a, q) >= 0;
  };
  std::vector<Tri> out;
  while (rim.size() > 3) {
    bool clipped = false;
    for (std::size_t i = 0; i < rim.size() && !clipped; ++i) {
      const std::uint32_t a = rim[(i + rim.size() - 1) % rim.size()], b = rim[i], c = rim[(i + 1) % rim.size()];
      if (!(turn(a, b, c) > 0)) continue;
      bool empty = true;
      for (const std::uint32_t q : rim)
        if (q != a && q != b && q != c && inside(q, a, b, c)) empty = false;
      if (!empty) continue;
      out.push_back({a, b, c});
      rim.erase(rim.begin() + static_cast<std::ptrdiff_t>(i));
      clipped = true;
    }
    if (!clipped) return {};
  }
  out.push_back({rim[0], rim[1], rim[2]});
  return out;
}

}  // namespace

void replace_fan(SurfaceMesh& mesh, const std::vector<std::size_t>& fan, const std::vector<Tri>& cap) {
  std::vector<bool> gone(mesh.triangles.size(), false);
  for (const std::size_t t : fan) gone[t] = true;
  std::size_t kept = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    if (!gone[t]) mesh.triangles[kept++] = mesh.triangles[t];
  mesh.triangles.resize(kept);
  for (Tri t : cap) {
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    mesh.triangles.push_back(t);
  }
}

std::size_t cap_bow_ties(SurfaceMesh& mesh) {
  std::size_t caps = 0;
  for (bool changed = true; changed;) {
    changed = false;
    const detail::VertexTriangles of_vertex =
        detail::triangles_by_vertex(mesh.triangles, mesh.vertices.size());
    const std::vector<std::size_t>&start = of_vertex.start, &by_vertex = of_vertex.by_vertex;
    // Whether the mesh has the edge ab, or the triangle with the corners of t, read
    // from the triangles of a: no index of the whole mesh is needed.
    const auto has_edge = [&](std::uint32_t a, std::uint32_t b) {
      for (std::size_t k = start[a]; k < start[a + 1]; ++k) {
        const Tri& tri = mesh.triangles[by_vertex[k]];
        if (tri[0] == b || tri[1] == b || tri[2] == b) return true;
      }
      return false;
    };
    const auto has_triangle = [&](Tri t) {
      std::sort(t.begin(), t.end());
      for (std::size_t k = start[t[0]]; k < start[t[0] + 1]; ++k) {
        Tri tri = mesh.triangles[by_vertex[k]];
        std::sort(tri.begin(), tri.end());
        if (tri == t) return true;
      }
      return false;
    };
    std::vector<std::size_t> around;  // v's triangles, in one buffer for every v
    for (std::uint32_t v = 0; v < mesh.vertices.size() && !changed; ++v) {
      // Two fans need at least three triangles each.
      if (start[v + 1] - start[v] < 6) continue;
      around.assign(by_vertex.begin() + static_cast<std::ptrdiff_t>(start[v]),
                    by_vertex.begin() + static_cast<std::ptrdiff_t>(start[v + 1]));
      if (one_closed_fan(mesh, v, around)) continue;
      const std::vector<Fan> fans = closed_fans(mesh, v, around);
      if (fans.size() < 2) continue;
      const Fan& cone = *std::max_element(fans.begin(), fans.end(), [&](const Fan& a, const Fan& b) {
        return height_ratio(mesh.vertices, v, a) < height_ratio(mesh.vertices, v, b);
      });
      const std::vector<Tri> cap = clip_ears(mesh.vertices, cone.rim, rim_plane(mesh.vertices, cone.rim).normal);
      bool fresh = !cap.empty();
      std::set<std::pair<std::uint32_t, std::uint32_t>> rim_edges;
      for (std::size_t i = 0; i < cone.rim.size(); ++i) rim_edges.insert(edge(cone.rim[i], cone.rim[(i + 1) % cone.rim.size()]));
      for (const Tri& t : cap) {
        fresh &= !has_triangle(t);
        for (int k = 0; k < 3; ++k) {
          const auto e = edge(t[k], t[(k + 1) % 3]);
          if (!rim_edges.count(e))
            fresh &= !has_edge(e.first, e.second);  // a diagonal must be a new edge
        }
      }
      if (!fresh) continue;
      replace_fan(mesh, cone.triangles, cap);
      ++caps;
      changed = true;
    }
  }
  return caps;
}

}  // namespace disktune::detail
