// SPDX-License-Identifier: GPL-3.0-or-later
// The restricted Delaunay triangulation of samples on a surface, and the Hausdorff
// distance between a mesh and the surface: the only CGAL unit of surface resampling.
//
// A Delaunay triangle belongs to the restricted triangulation when its dual Voronoi edge
// (a segment between two circumcenters, or a ray for a hull facet) meets the surface; an
// AABB tree over the input triangles answers that, in exact arithmetic (see below). The
// surface triangle it meets also tells which way the mesh triangle should face.
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <numeric>
#include <set>
#include <utility>

#include "bow_tie_caps.h"
#include "disktune/errors.h"
#include "disktune/random.h"
#include "disktune/restricted_delaunay.h"
#include "feature_chain.h"

namespace disktune {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Triangle3 = Kernel::Triangle_3;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, Kernel>;
using Tds = CGAL::Triangulation_data_structure_3<VertexBase>;
using Delaunay = CGAL::Delaunay_triangulation_3<Kernel, Tds>;
using TriangleList = std::vector<Triangle3>;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, TriangleList::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
using Exact = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactTriangles = std::vector<Exact::Triangle_3>;
using ExactPrimitive = CGAL::AABB_triangle_primitive<Exact, ExactTriangles::const_iterator>;
using ExactTree = CGAL::AABB_tree<CGAL::AABB_traits<Exact, ExactPrimitive>>;

Point point(Vec3 p) { return {p.x, p.y, p.z}; }
Exact::Point_3 exact(Vec3 p) { return {p.x, p.y, p.z}; }

template <class Tri>
Vec3 normal(const std::vector<Vec3>& v, const Tri& t) {
  return cross(v[t[1]] - v[t[0]], v[t[2]] - v[t[0]]);
}

void check_samples(const std::vector<Vec3>& samples) {
  if (samples.size() < 4) {
    throw InvalidInput("restricted_delaunay needs at least 4 samples, got " +
                       std::to_string(samples.size()) + "; sample more densely (a smaller radius)");
  }
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const Vec3 p = samples[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      throw InvalidInput("restricted_delaunay: sample " + std::to_string(i) +
                         " has a non-finite coordinate");
    }
  }
}

/// The samples with info = their index, a repeated position only once (its first index):
/// the triangulation would merge repeats and keep an arbitrary one's info.
std::vector<std::pair<Point, std::uint32_t>> distinct_samples(const std::vector<Vec3>& samples) {
  std::vector<std::uint32_t> order(samples.size());
  std::iota(order.begin(), order.end(), 0);
  const auto key = [&](std::uint32_t i) {
    return std::array<double, 3>{samples[i].x, samples[i].y, samples[i].z};
  };
  std::stable_sort(order.begin(), order.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
  std::vector<std::pair<Point, std::uint32_t>> out;
  for (std::size_t k = 0; k < order.size(); ++k) {
    if (k == 0 || samples[order[k]] != samples[order[k - 1]]) {
      out.emplace_back(point(samples[order[k]]), order[k]);
    }
  }
  return out;
}

/// The triangles of a surface as CGAL triangles, for an AABB tree.
template <class Tris>
TriangleList cgal_triangles(const std::vector<Vec3>& v, const Tris& tris) {
  TriangleList out;
  out.reserve(tris.size());
  for (const auto& t : tris) {
    // Zero-area triangles add nothing to a distance and have no normal: left out.
    if (squared_norm(normal(v, t)) > 0) out.emplace_back(point(v[t[0]]), point(v[t[1]]), point(v[t[2]]));
  }
  return out;
}

/// Area-weighted random points on the triangles (u, v drawn uniformly: the square-root
/// map makes the point uniform in the triangle).
template <class Tris>
void random_points(const std::vector<Vec3>& v, const Tris& tris, std::size_t n, Rng& rng,
                   std::vector<Point>& out) {
  std::vector<double> cumulative;
  double total = 0;
  for (const auto& t : tris) cumulative.push_back(total += norm(normal(v, t)));
  if (total <= 0) return;
  for (std::size_t k = 0; k < n; ++k) {
    const double pick = uniform01(rng) * total;
    const std::size_t t = std::min<std::size_t>(
        std::upper_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin(),
        tris.size() - 1);
    const double s = std::sqrt(uniform01(rng)), w = uniform01(rng);
    const auto& tri = tris[t];
    out.push_back(point(v[tri[0]] * (1 - s) + v[tri[1]] * (s * (1 - w)) + v[tri[2]] * (s * w)));
  }
}

/// The largest distance from `points` to the triangles of `tree`.
double farthest(const std::vector<Point>& points, const Tree& tree) {
  double d2 = 0;
  for (const Point& p : points) d2 = std::max(d2, CGAL::to_double(tree.squared_distance(p)));
  return std::sqrt(d2);
}

/// An undirected edge as a map key.
std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  return a < b ? std::uint64_t{a} << 32 | b : std::uint64_t{b} << 32 | a;
}

/// Removes the triangles that join two sides of a feature (vertices in two different
/// patches) and share an edge with two or more other triangles. Near a sharp crease a
/// dual edge can cross it, so the triangles on either side close a tetrahedron over the
/// crease: its faces across it are the extra ones. Elsewhere such a triangle stays: where
/// feature disks are too far apart to have an edge between them, the mesh needs it.
void drop_crossings(SurfaceMesh& mesh, const std::vector<std::uint32_t>& sample_patch) {
  const auto crosses = [&](const std::array<std::uint32_t, 3>& t) {
    std::uint32_t side = kAnyPatch;
    for (const std::uint32_t v : t) {
      if (sample_patch[v] == kAnyPatch) continue;
      if (side != kAnyPatch && sample_patch[v] != side) return true;
      side = sample_patch[v];
    }
    return false;
  };
  std::map<std::uint64_t, int> uses;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++uses[edge_key(t[k], t[(k + 1) % 3])];
  const auto extra = [&](const std::array<std::uint32_t, 3>& t) {
    if (!crosses(t)) return false;
    for (int k = 0; k < 3; ++k)
      if (uses[edge_key(t[k], t[(k + 1) % 3])] > 2) return true;
    return false;
  };
  mesh.triangles.erase(std::remove_if(mesh.triangles.begin(), mesh.triangles.end(), extra), mesh.triangles.end());
}

/// The fan of triangles around x from a to b that starts with `first` (which holds a
/// and x): the triangles in order and the rim a, y1, .., yk, b. Empty if the walk meets
/// an edge xy not in exactly two triangles, or does not reach b within a few steps.
struct Fan {
  std::vector<std::size_t> triangles;
  std::vector<std::uint32_t> rim;
};

/// A sample x beside a feature edge ab can have a Voronoi cell reaching over a sharp
/// crease. The dual test then keeps abx and two fans of triangles around x from a to b:
/// one on x's side, one across the crease (x y1 .. yk, k >= 1; for k = 1 three faces of
/// the tetrahedron abxy). ax and bx lie in three triangles, ab in one. The fan across
/// the crease (the one bent further from abx) gives way to a cap over its rim a y1 .. yk
/// b, triangles from a, which holds ab: every edge is then in two triangles, x keeps one
/// fan, and the feature edge stays. Nothing changes unless the cap's diagonals are new
/// edges. One fan at a time, the edge map rebuilt after each (they are rare).
void cap_fans_across_creases(SurfaceMesh& mesh, const std::vector<std::array<std::uint32_t, 2>>& feature_edges) {
  using Tri = std::array<std::uint32_t, 3>;
  const auto third = [](const Tri& t, std::uint32_t p, std::uint32_t q) {
    for (const std::uint32_t v : t)
      if (v != p && v != q) return v;
    return p;
  };
  const auto unit_normal = [&](const Tri& t) {
    const Vec3 n = normal(mesh.vertices, t);
    const double len = norm(n);
    return len > 0 ? n * (1 / len) : n;
  };
  for (bool changed = true; changed;) {
    changed = false;
    std::map<std::uint64_t, std::vector<std::size_t>> with_edge;  // triangles by edge
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
      for (int k = 0; k < 3; ++k) with_edge[edge_key(mesh.triangles[i][k], mesh.triangles[i][(k + 1) % 3])].push_back(i);
    const auto on = [&](std::uint32_t p, std::uint32_t q) {
      const auto it = with_edge.find(edge_key(p, q));
      return it == with_edge.end() ? std::vector<std::size_t>{} : it->second;
    };
    for (const auto& feature : feature_edges) {
      const std::uint32_t a = feature[0], b = feature[1];  // plain names: lambdas below capture them
      const auto on_ab = on(a, b);
      if (on_ab.size() != 1) continue;
      const Tri abx = mesh.triangles[on_ab[0]];
      const std::uint32_t x = third(abx, a, b);
      if (on(a, x).size() != 3 || on(b, x).size() != 3) continue;
      const auto walk = [&](std::size_t first) {
        Fan fan{{}, {a}};
        for (std::size_t t = first; fan.triangles.size() < 16;) {
          const std::uint32_t y = third(mesh.triangles[t], x, fan.rim.back());
          fan.triangles.push_back(t);
          fan.rim.push_back(y);
          if (y == b) return fan;
          const auto on_xy = on(x, y);
          if (on_xy.size() != 2) break;
          t = on_xy[0] == t ? on_xy[1] : on_xy[0];
        }
        return Fan{};
      };
      std::vector<Fan> fans;
      for (const std::size_t t : on(a, x))
        if (t != on_ab[0]) fans.push_back(walk(t));
      if (fans[0].rim.empty() || fans[1].rim.empty()) continue;
      // How far a fan bends away from abx: the least cosine between their normals.
      const auto bend = [&](const Fan& f) {
        double least = 1;
        for (const std::size_t t : f.triangles) least = std::min(least, dot(unit_normal(mesh.triangles[t]), unit_normal(abx)));
        return least;
      };
      const Fan& across = bend(fans[0]) < bend(fans[1]) ? fans[0] : fans[1];
      const auto& rim = across.rim;
      bool fresh = true;  // the cap's diagonals a-yi (i >= 2) are no edges yet
      for (std::size_t i = 2; i + 1 < rim.size(); ++i) fresh &= on(a, rim[i]).empty();
      if (!fresh) continue;
      // Cap triangle i holds rim edge yi yi+1, run the way fan triangle i runs it.
      std::vector<Tri> cap;
      for (std::size_t i = 1; i + 1 < rim.size(); ++i) {
        const Tri& t = mesh.triangles[across.triangles[i]];
        const int at = static_cast<int>(std::find(t.begin(), t.end(), rim[i]) - t.begin());
        cap.push_back(t[(at + 1) % 3] == rim[i + 1] ? Tri{a, rim[i], rim[i + 1]} : Tri{a, rim[i + 1], rim[i]});
      }
      detail::replace_fan(mesh, across.triangles, cap);
      changed = true;
      break;
    }
  }
}

}  // namespace

SurfaceMesh restricted_delaunay(const std::vector<Vec3>& samples, const SurfaceDomain& surface) {
  return restricted_delaunay(samples, surface, std::vector<std::uint32_t>(samples.size(), kAnyPatch), {});
}

SurfaceMesh restricted_delaunay(const SurfacePacking& packing) {
  std::vector<Vec3> samples;
  std::vector<std::uint32_t> patch;
  for (const DiskId id : packing.ids()) {
    samples.push_back(packing.center(id));
    patch.push_back((packing.flags(id) & kFixed) ? kAnyPatch
                                                 : packing.domain().triangle_patch()[packing.point(id).triangle]);
  }
  const auto along_features = detail::feature_neighbours(packing);
  SurfaceMesh mesh = restricted_delaunay(samples, packing.domain(), patch, along_features);
  // The feature curves' consecutive disks that the mesh joins.
  std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) edges.insert(std::minmax(t[k], t[(k + 1) % 3]));
  for (const auto& e : along_features)
    if (edges.count(std::minmax(e[0], e[1]))) mesh.feature_edges.push_back(e);
  return mesh;
}

SurfaceMesh restricted_delaunay(const std::vector<Vec3>& samples, const SurfaceDomain& surface,
                                const std::vector<std::uint32_t>& sample_patch,
                                const std::vector<std::array<std::uint32_t, 2>>& feature_edges) {
  check_samples(samples);
  if (sample_patch.size() != samples.size()) {
    throw InvalidInput("restricted_delaunay: " + std::to_string(sample_patch.size()) + " patches for " +
                       std::to_string(samples.size()) + " samples; give one per sample");
  }
  for (const std::uint32_t p : sample_patch) {
    if (p != kAnyPatch && p >= surface.patch_count()) {
      throw InvalidInput("restricted_delaunay: patch " + std::to_string(p) + " of a sample, but the surface has " +
                         std::to_string(surface.patch_count()) + "; give SurfaceDomain::triangle_patch values");
    }
  }
  for (const auto& [a, b] : feature_edges) {
    if (a >= samples.size() || b >= samples.size() || a == b) {
      throw InvalidInput("restricted_delaunay: feature edge " + std::to_string(a) + "-" + std::to_string(b) +
                         " is not a pair of two of the " + std::to_string(samples.size()) + " samples");
    }
  }
  const auto distinct = distinct_samples(samples);
  Delaunay dt(distinct.begin(), distinct.end());
  if (dt.dimension() < 2) {
    throw InvalidInput("restricted_delaunay: the " + std::to_string(samples.size()) +
                       " samples lie on one line; sample the whole surface");
  }
  // Samples on a flat piece of the surface are coplanar up to rounding, so the
  // triangulation holds flat slivers whose circumcenters, rounded, land anywhere: dual
  // edges are built and tested exactly (one kept facet per pair of sliver facets).
  const std::vector<Vec3>& sv = surface.vertices();
  ExactTriangles input;
  for (const auto& t : surface.triangles()) input.emplace_back(exact(sv[t[0]]), exact(sv[t[1]]), exact(sv[t[2]]));
  const ExactTree tree(input.begin(), input.end());

  SurfaceMesh mesh;
  mesh.vertices = samples;
  std::vector<ExactTriangles::const_iterator> hits;
  // Keeps the facet if `dual` meets the surface, facing the way of the hit surface
  // triangle nearest to it (a long dual edge may cross the surface more than once).
  const auto keep_if_hit = [&](const Delaunay::Facet& f, const auto& dual) {
    std::array<std::uint32_t, 3> t;
    for (int k = 0; k < 3; ++k) t[k] = f.first->vertex((f.second + 1 + k) & 3)->info();
    hits.clear();
    tree.all_intersected_primitives(dual, std::back_inserter(hits));
    if (hits.empty()) return;
    const Point centroid = point((samples[t[0]] + samples[t[1]] + samples[t[2]]) * (1.0 / 3));
    const auto distance2 = [&](ExactTriangles::const_iterator h) {
      const auto& tri = surface.triangles()[static_cast<std::size_t>(h - input.begin())];
      return CGAL::squared_distance(centroid, Triangle3(point(sv[tri[0]]), point(sv[tri[1]]), point(sv[tri[2]])));
    };
    std::size_t best = 0;
    for (std::size_t k = 1; k < hits.size(); ++k) {
      if (distance2(hits[k]) < distance2(hits[best])) best = k;
    }
    const auto& hit = surface.triangles()[static_cast<std::size_t>(hits[best] - input.begin())];
    if (dot(normal(samples, t), normal(sv, hit)) < 0) std::swap(t[1], t[2]);
    // The smallest index first (orientation kept), so the output does not depend on
    // how the triangulation happens to store its cells.
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    mesh.triangles.push_back(t);
  };
  const auto exact_point = [&](Delaunay::Vertex_handle v) { return exact(samples[v->info()]); };

  if (dt.dimension() == 2) {
    // Coplanar samples: each triangle's dual is the line through its circumcenter along
    // the plane's normal.
    for (auto f = dt.finite_facets_begin(); f != dt.finite_facets_end(); ++f) {
      const Exact::Point_3 a = exact_point(f->first->vertex(0)), b = exact_point(f->first->vertex(1)),
                           c = exact_point(f->first->vertex(2));
      keep_if_hit(*f, Exact::Line_3(CGAL::circumcenter(a, b, c), CGAL::normal(a, b, c)));
    }
  } else {
    // Each finite cell's circumcenter, once.
    std::map<Delaunay::Cell_handle, Exact::Point_3> center;
    for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) {
      center.emplace(c, CGAL::circumcenter(exact_point(c->vertex(0)), exact_point(c->vertex(1)),
                                           exact_point(c->vertex(2)), exact_point(c->vertex(3))));
    }
    for (auto f = dt.finite_facets_begin(); f != dt.finite_facets_end(); ++f) {
      Delaunay::Cell_handle c = f->first, n = c->neighbor(f->second);
      if (!dt.is_infinite(c) && !dt.is_infinite(n)) {
        const Exact::Segment_3 dual(center.at(c), center.at(n));
        // Four cospherical samples make the segment a point, which meets the surface with
        // probability zero (and AABB segment queries need a proper segment).
        if (!dual.is_degenerate()) keep_if_hit(*f, dual);
        continue;
      }
      // A hull facet: its dual is the ray from the finite cell's circumcenter outward.
      int i = f->second;
      if (dt.is_infinite(c)) i = n->index(c), std::swap(c, n);
      const Exact::Point_3 p = exact_point(c->vertex((i + 1) & 3)), q = exact_point(c->vertex((i + 2) & 3)),
                           r = exact_point(c->vertex((i + 3) & 3)), inside = exact_point(c->vertex(i));
      Exact::Vector_3 out = CGAL::cross_product(q - p, r - p);
      if (CGAL::orientation(p, q, r, inside) == CGAL::POSITIVE) out = -out;
      keep_if_hit(*f, Exact::Ray_3(center.at(c), out));
    }
  }
  cap_fans_across_creases(mesh, feature_edges);
  drop_crossings(mesh, sample_patch);
  detail::cap_bow_ties(mesh);
  // Deterministic order whatever CGAL's internal one: by the triangles' vertex indices.
  std::sort(mesh.triangles.begin(), mesh.triangles.end());
  return mesh;
}

double hausdorff_distance(const SurfaceMesh& mesh, const SurfaceDomain& surface,
                          std::size_t samples_per_mesh, std::uint64_t seed) {
  const TriangleList mesh_tris = cgal_triangles(mesh.vertices, mesh.triangles);
  if (mesh_tris.empty()) {
    throw InvalidInput("hausdorff_distance: the mesh has no triangles of non-zero area");
  }
  const TriangleList surface_tris = cgal_triangles(surface.vertices(), surface.triangles());
  Tree mesh_tree(mesh_tris.begin(), mesh_tris.end()), surface_tree(surface_tris.begin(), surface_tris.end());
  mesh_tree.accelerate_distance_queries();
  surface_tree.accelerate_distance_queries();

  Rng rng(seed);
  std::vector<Point> on_mesh, on_surface;
  for (const Vec3& v : mesh.vertices) on_mesh.push_back(point(v));
  random_points(mesh.vertices, mesh.triangles, samples_per_mesh, rng, on_mesh);
  for (const Vec3& v : surface.vertices()) on_surface.push_back(point(v));
  random_points(surface.vertices(), surface.triangles(), samples_per_mesh, rng, on_surface);
  return std::max(farthest(on_mesh, surface_tree), farthest(on_surface, mesh_tree));
}

}  // namespace disktune
