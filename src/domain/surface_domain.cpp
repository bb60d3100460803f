// SPDX-License-Identifier: GPL-3.0-or-later
// Validation and derived data of a triangulated surface, and its CGAL-based reader.
#include "disktune/surface_domain.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "../io/file_extension.h"
#include "../io/polygon_soup.h"
#include "disktune/errors.h"
#include "half_edges.h"
#include "point_text.h"
#include "precision.h"

namespace disktune {
namespace {

using Triangle = SurfaceDomain::Triangle;

std::string vertex_text(const std::vector<Vec3>& points, std::size_t v) {
  return "vertex " + std::to_string(v) + " " + detail::point_text(points[v]);
}

std::string triangle_text(const std::vector<Vec3>& points, const Triangle& tri, std::size_t t) {
  return "triangle " + std::to_string(t) + " (" + vertex_text(points, tri[0]) + ", " +
         vertex_text(points, tri[1]) + ", " + vertex_text(points, tri[2]) + ")";
}

using detail::for_each_edge;
using detail::HalfEdge;
using detail::sorted_half_edges;
using detail::UnionFind;

void check_triangles(const std::vector<Vec3>& points, const std::vector<Triangle>& tris) {
  if (tris.empty()) throw InvalidInput("the surface has no triangles; give at least one");
  for (std::size_t t = 0; t < tris.size(); ++t) {
    const Triangle& tri = tris[t];
    for (const std::size_t v : tri) {
      if (v >= points.size()) {
        throw InvalidInput("triangle " + std::to_string(t) + " names vertex " + std::to_string(v) +
                           ", but there are only " + std::to_string(points.size()) +
                           " vertices; fix the face's indices");
      }
    }
    const Vec3 a = points[tri[0]], b = points[tri[1]], c = points[tri[2]];
    // Relative to the longest edge, so the test does not depend on the model's units.
    const double longest =
        std::max({squared_norm(b - a), squared_norm(c - b), squared_norm(a - c)});
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0] ||
        norm(cross(b - a, c - a)) <= 1e-12 * longest) {
      throw InvalidInput(triangle_text(points, tri, t) +
                         " has zero area; remove degenerate triangles from the surface");
    }
  }
}

// Throws for an edge in more than two triangles or run the same way by both.
void check_edges(const std::vector<Vec3>& points, const std::vector<HalfEdge>& half) {
  for_each_edge(half, [&](std::size_t i, std::size_t j) {
    const HalfEdge& e = half[i];
    // Written only for a message: for every edge it took most of reading a surface
    // (fandisk 27 ms, 7.8 ms without).
    const auto edge = [&] {
      return "the edge between " + vertex_text(points, e.lo) + " and " + vertex_text(points, e.hi);
    };
    if (j - i > 2) {
      std::string list;
      for (std::size_t k = i; k < j; ++k) list += (k > i ? ", " : "") + std::to_string(half[k].tri);
      throw InvalidInput(edge() + " lies in " + std::to_string(j - i) + " triangles (" + list +
                         "), a non-manifold edge; a surface edge may border at most two "
                         "triangles");
    }
    if (j - i == 2 && half[i].forward == half[i + 1].forward) {
      throw InvalidInput("triangles " + std::to_string(half[i].tri) + " and " +
                         std::to_string(half[i + 1].tri) + " both run " + edge() +
                         " the same way: the surface is not consistently oriented; flip one "
                         "of them (or the surface is not orientable)");
    }
  });
}

// Throws for a vertex in no triangle or whose triangles form more than one fan.
void check_vertices(const std::vector<Vec3>& points, const std::vector<Triangle>& tris) {
  std::vector<std::vector<std::size_t>> around(points.size());
  for (std::size_t t = 0; t < tris.size(); ++t) {
    for (const std::size_t v : tris[t]) around[v].push_back(t);
  }
  for (std::size_t v = 0; v < points.size(); ++v) {
    if (around[v].empty()) {
      throw InvalidInput(vertex_text(points, v) +
                         " lies in no triangle; remove unused vertices from the surface");
    }
    const std::size_t pieces = detail::fan_count(v, around[v], tris);
    if (pieces > 1) {
      throw InvalidInput(vertex_text(points, v) + " joins " + std::to_string(pieces) +
                         " separate fans of triangles (a non-manifold, bow-tie vertex); give "
                         "each fan its own copy of the vertex");
    }
  }
}

// The boundary edges (one triangle only) chained into loops, surface on their left.
std::vector<std::vector<std::size_t>> chain_boundary(std::size_t vertex_count,
                                                     const std::vector<HalfEdge>& half) {
  constexpr std::size_t none = static_cast<std::size_t>(-1);
  std::vector<std::size_t> next(vertex_count, none);
  for_each_edge(half, [&](std::size_t i, std::size_t j) {
    if (j - i != 1) return;
    const HalfEdge& e = half[i];
    // In triangle (a, b, c) the edge a->b has the triangle on its left.
    if (e.forward) next[e.lo] = e.hi; else next[e.hi] = e.lo;
  });
  std::vector<std::vector<std::size_t>> loops;
  for (std::size_t start = 0; start < vertex_count; ++start) {
    if (next[start] == none) continue;
    std::vector<std::size_t> loop;
    for (std::size_t v = start; next[v] != none;) {
      loop.push_back(v);
      const std::size_t w = next[v];
      next[v] = none;  // each vertex has one outgoing boundary edge (one fan), used once
      v = w;
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

}  // namespace

SurfaceDomain::SurfaceDomain(std::vector<Vec3> vertices, std::vector<Triangle> triangles)
    : vertices_(std::move(vertices)), triangles_(std::move(triangles)) {
  check_triangles(vertices_, triangles_);
  const std::vector<HalfEdge> half = sorted_half_edges(triangles_);
  check_edges(vertices_, half);
  check_vertices(vertices_, triangles_);
  for_each_edge(half, [&](std::size_t, std::size_t) { ++edge_count_; });
  loops_ = chain_boundary(vertices_.size(), half);

  // Components through shared vertices (edges, after the fan check), numbered in
  // triangle order; then Euler's formula per component.
  UnionFind uf(vertices_.size());
  for (const Triangle& t : triangles_) uf.unite(t[0], t[1]), uf.unite(t[1], t[2]);
  std::vector<std::size_t> of_root(vertices_.size(), static_cast<std::size_t>(-1));
  component_.resize(triangles_.size());
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    std::size_t& c = of_root[uf.find(triangles_[t][0])];
    if (c == static_cast<std::size_t>(-1)) c = genus_.size(), genus_.push_back(0);
    component_[t] = c;
  }
  const auto comp_of = [&](std::size_t v) { return of_root[uf.find(v)]; };
  std::vector<long long> euler(genus_.size(), 0), borders(genus_.size(), 0);
  for (std::size_t v = 0; v < vertices_.size(); ++v) ++euler[comp_of(v)];
  for_each_edge(half, [&](std::size_t i, std::size_t) { --euler[comp_of(half[i].lo)]; });
  for (std::size_t t = 0; t < triangles_.size(); ++t) ++euler[component_[t]];
  for (const auto& loop : loops_) ++borders[comp_of(loop.front())];
  for (std::size_t c = 0; c < genus_.size(); ++c) {
    genus_[c] = static_cast<int>((2 - borders[c] - euler[c]) / 2);
  }

  lo_ = hi_ = vertices_.front();
  for (const Vec3& p : vertices_) {
    lo_ = {std::min(lo_.x, p.x), std::min(lo_.y, p.y), std::min(lo_.z, p.z)};
    hi_ = {std::max(hi_.x, p.x), std::max(hi_.y, p.y), std::max(hi_.z, p.z)};
  }
  const double size = std::max({hi_.x - lo_.x, hi_.y - lo_.y, hi_.z - lo_.z});
  if (size > 0) {
    detail::check_coordinates_for_scale(
        std::max({std::abs(lo_.x), std::abs(lo_.y), std::abs(lo_.z), std::abs(hi_.x), std::abs(hi_.y), std::abs(hi_.z)}),
        size, "its size " + detail::number_text(size));
  }
  for (const Triangle& t : triangles_) {
    const Vec3 a = vertices_[t[0]];
    area_ += 0.5 * norm(cross(vertices_[t[1]] - a, vertices_[t[2]] - a));
  }
  set_features({});
}

int SurfaceDomain::genus() const { return std::accumulate(genus_.begin(), genus_.end(), 0); }

void SurfaceDomain::set_features(SurfaceFeatures features) {
  const std::size_t n = vertices_.size();
  std::vector<char> corner(n, 0);
  for (const std::size_t v : features.corners) {
    if (v >= n) throw InvalidInput("feature corner " + std::to_string(v) + " names a missing vertex");
    corner[v] = 1;
  }
  // Where an open boundary turns sharply, as at a planar domain's polygon vertices: a corner.
  const double straight = std::cos(kBoundaryCornerAngle * 3.14159265358979323846 / 180);
  for (const auto& loop : loops_) {
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const Vec3 in = vertices_[loop[k]] - vertices_[loop[(k + loop.size() - 1) % loop.size()]],
                 out = vertices_[loop[(k + 1) % loop.size()]] - vertices_[loop[k]];
      if (dot(in, out) < straight * norm(in) * norm(out)) corner[loop[k]] = 1;
    }
  }
  corners_.clear();
  for (std::size_t v = 0; v < n; ++v)
    if (corner[v]) corners_.push_back(v);
  for (std::size_t c = 0; c < features.curves.size(); ++c) {
    const SurfaceCurve& curve = features.curves[c];
    const auto bad = [&](const std::string& why) {
      throw InvalidInput("feature curve " + std::to_string(c) + " " + why + "; chain the feature edges again");
    };
    const std::vector<std::size_t>& v = curve.vertices;
    if (v.size() < 2) bad("has fewer than two vertices");
    for (std::size_t k = 0; k < v.size(); ++k) {
      if (v[k] >= n) bad("names a missing vertex " + std::to_string(v[k]));
      if (k + 1 == v.size() && !curve.closed) break;
      const std::size_t w = v[(k + 1) % v.size()];
      if (!std::binary_search(features.edges.begin(), features.edges.end(), MeshEdge{std::min(v[k], w), std::max(v[k], w)}))
        bad("steps from vertex " + std::to_string(v[k]) + " to " + std::to_string(w) + " along no feature edge");
    }
    if (!curve.closed && !(corner[v.front()] && corner[v.back()])) bad("is open but does not end at corners");
  }
  // The boundary loops, cut at the corners on them.
  curves_.clear();
  for (const auto& loop : loops_) {
    const auto first = std::find_if(loop.begin(), loop.end(), [&](std::size_t v) { return corner[v] != 0; });
    if (first == loop.end()) {
      curves_.push_back({loop, true});
      continue;
    }
    std::vector<std::size_t> turned(first, loop.end());
    turned.insert(turned.end(), loop.begin(), first);
    turned.push_back(turned.front());
    SurfaceCurve piece;
    for (const std::size_t v : turned) {
      piece.vertices.push_back(v);
      if (corner[v] && piece.vertices.size() > 1) {
        curves_.push_back(piece);
        piece.vertices = {v};
      }
    }
  }
  curves_.insert(curves_.end(), features.curves.begin(), features.curves.end());
  // Patches: triangles joined across the edges that are no feature edge; without
  // features, the components.
  features_ = std::move(features);
  if (features_.edges.empty()) {
    patch_.assign(component_.begin(), component_.end());
    patch_count_ = genus_.size();
    return;
  }
  UnionFind uf(triangles_.size());
  const std::vector<HalfEdge> half = sorted_half_edges(triangles_);
  for_each_edge(half, [&](std::size_t first, std::size_t last) {
    if (last - first == 2 &&
        !std::binary_search(features_.edges.begin(), features_.edges.end(), MeshEdge{half[first].lo, half[first].hi}))
      uf.unite(half[first].tri, half[first + 1].tri);
  });
  std::vector<std::uint32_t> of_root(triangles_.size(), ~0u);
  patch_.resize(triangles_.size());
  patch_count_ = 0;
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    std::uint32_t& p = of_root[uf.find(t)];
    if (p == ~0u) p = static_cast<std::uint32_t>(patch_count_++);
    patch_[t] = p;
  }
}

namespace {

// STL repeats each corner in every facet: one index per distinct position.
void merge_equal_points(std::vector<Vec3>& points, std::vector<Triangle>& tris) {
  std::map<std::array<double, 3>, std::size_t> index;
  std::vector<std::size_t> to(points.size());
  std::vector<Vec3> merged;
  for (std::size_t v = 0; v < points.size(); ++v) {
    const auto [it, added] = index.emplace(std::array<double, 3>{points[v].x, points[v].y,
                                                                 points[v].z},
                                           merged.size());
    if (added) merged.push_back(points[v]);
    to[v] = it->second;
  }
  for (Triangle& t : tris) {
    for (std::size_t& v : t) v = to[v];
  }
  points = std::move(merged);
}

// Files often mix orientations: flip triangles, spreading from the first of each
// component across edges of two triangles, to agree with their neighbours. A
// non-orientable surface keeps a conflict, which the constructor then reports.
void orient_consistently(std::vector<Triangle>& tris) {
  const std::vector<HalfEdge> half = sorted_half_edges(tris);
  struct Link {
    std::size_t to;
    bool same_way;  // both triangles run the shared edge the same way
  };
  std::vector<std::vector<Link>> links(tris.size());
  for_each_edge(half, [&](std::size_t i, std::size_t j) {
    if (j - i != 2) return;
    const bool same = half[i].forward == half[i + 1].forward;
    links[half[i].tri].push_back({half[i + 1].tri, same});
    links[half[i + 1].tri].push_back({half[i].tri, same});
  });
  std::vector<char> seen(tris.size(), 0), flip(tris.size(), 0);
  std::vector<std::size_t> stack;
  for (std::size_t s = 0; s < tris.size(); ++s) {
    if (seen[s]) continue;
    seen[s] = 1;
    stack.push_back(s);
    while (!stack.empty()) {
      const std::size_t t = stack.back();
      stack.pop_back();
      for (const Link& l : links[t]) {
        if (seen[l.to]) continue;
        seen[l.to] = 1;
        flip[l.to] = flip[t] ^ static_cast<char>(l.same_way);
        stack.push_back(l.to);
      }
    }
  }
  for (std::size_t t = 0; t < tris.size(); ++t) {
    if (flip[t]) std::swap(tris[t][1], tris[t][2]);
  }
}

}  // namespace

SurfaceDomain read_surface(const std::string& path) {
  const detail::PolygonSoup soup = detail::read_polygon_soup(path);
  std::vector<Vec3> points;
  points.reserve(soup.points.size());
  for (const auto& p : soup.points) points.push_back({p[0], p[1], p[2]});
  std::vector<Triangle> tris;
  tris.reserve(soup.polygons.size());
  for (std::size_t f = 0; f < soup.polygons.size(); ++f) {
    const auto& poly = soup.polygons[f];
    if (poly.size() != 3) {
      throw InvalidInput("face " + std::to_string(f) + " of " + path + " has " +
                         std::to_string(poly.size()) +
                         " corners; a surface domain needs triangles: triangulate the mesh first");
    }
    tris.push_back({poly[0], poly[1], poly[2]});
  }
  const std::string ext = detail::lower_extension(path);
  if (ext == ".stl") merge_equal_points(points, tris);
  orient_consistently(tris);
  try {
    return SurfaceDomain(std::move(points), std::move(tris));
  } catch (const InvalidInput& e) {
    throw InvalidInput(path + ": " + e.what());
  }
}

}  // namespace disktune
