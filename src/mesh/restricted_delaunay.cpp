// SPDX-License-Identifier: GPL-3.0-or-later
// The restricted Delaunay triangulation of samples on a surface, and the Hausdorff
// distance between a mesh and the surface: the only CGAL unit of surface resampling.
//
// A Delaunay triangle belongs to the restricted triangulation when its dual Voronoi edge
// (a segment between two circumcenters, or a ray for a hull facet) meets the surface; an
// AABB tree over the input triangles answers that, exactly but mostly in interval
// arithmetic (DualEdges below). The surface triangle it meets also tells which way the
// mesh triangle should face.
#include "disktune/restricted_delaunay.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Mpzf.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <memory>
#include <numeric>
#include <type_traits>
#include <unordered_map>
#include <utility>

#include "../domain/half_edges.h"
#include "../geometry/threads.h"
#include "bow_tie_caps.h"
#include "disktune/errors.h"
#include "disktune/random.h"
#include "dual_edge.h"
#include "feature_chain.h"

namespace disktune {
namespace detail {
template <>
int strict_sign(const CGAL::Interval_nt_advanced& x) {
  return x.inf() > 0 ? 1 : x.sup() < 0 ? -1 : 0;
}
template <>
int strict_sign(const CGAL::Mpzf& x) {
  return static_cast<int>(x.sign());
}
}  // namespace detail

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Triangle3 = Kernel::Triangle_3;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, Kernel>;
// What a cell carries: its index among the cells DualEdges tests (into its arrays), and for
// meshing again after a few samples moved (RestrictedDelaunayReuse), a stamp naming it
// (0: made or changed since the last mesh) and per facet the verdict found for it with
// the cell across of that stamp (0 none, 1 no mesh triangle, 2 the triangle of its
// sorted corners a < b < c, 3 that of a, c, b).
struct CellInfo {
  std::uint32_t index = 0, stamp = 0;
  std::array<std::uint8_t, 4> verdict{};
  std::array<std::uint32_t, 4> across{};
};
using CellBase =
    CGAL::Triangulation_cell_base_with_info_3<CellInfo, Kernel,
                                              CGAL::Delaunay_triangulation_cell_base_3<Kernel>>;
using Tds = CGAL::Triangulation_data_structure_3<VertexBase, CellBase>;
using Delaunay = CGAL::Delaunay_triangulation_3<Kernel, Tds>;
using TriangleList = std::vector<Triangle3>;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, TriangleList::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
using Exact = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactTriangles = std::vector<Exact::Triangle_3>;
using ExactPrimitive = CGAL::AABB_triangle_primitive<Exact, ExactTriangles::const_iterator>;
using ExactTree = CGAL::AABB_tree<CGAL::AABB_traits<Exact, ExactPrimitive>>;
using Interval = CGAL::Interval_nt_advanced;  // only under CGAL::Protect_FPU_rounding
using Ring = CGAL::Mpzf;                      // exact +, -, * of doubles

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

/// The largest distance from `points` to the triangles of `tree`, on `threads` threads
/// (the tree's distance queries only read it once its search tree is built).
double farthest(const std::vector<Point>& points, const Tree& tree, unsigned threads) {
  constexpr std::size_t kChunk = 1024;
  std::vector<double> d2((points.size() + kChunk - 1) / kChunk, 0.0);
  detail::parallel_for(d2.size(), threads, [&](std::size_t chunk, unsigned) {
    for (std::size_t i = chunk * kChunk; i < std::min(points.size(), (chunk + 1) * kChunk); ++i)
      d2[chunk] = std::max(d2[chunk], CGAL::to_double(tree.squared_distance(points[i])));
  });
  return std::sqrt(d2.empty() ? 0.0 : *std::max_element(d2.begin(), d2.end()));
}

/// An undirected edge as a map key.
std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  return a < b ? std::uint64_t{a} << 32 | b : std::uint64_t{b} << 32 | a;
}

/// The triangles of a mesh that hold an edge, read from the triangles of one end (every
/// edge has few): the mending passes below ask about a few edges each, where a hash
/// table of every edge cost more than the rest of them. Dropped triangles leave the
/// counts.
class EdgeTriangles {
 public:
  explicit EdgeTriangles(const SurfaceMesh& mesh)
      : mesh_(mesh),
        around_(detail::triangles_by_vertex(mesh.triangles, mesh.vertices.size())),
        dropped_(mesh.triangles.size(), 0) {}
  /// The triangles not dropped that hold edge ab, in increasing order.
  std::vector<std::size_t> on(std::uint32_t a, std::uint32_t b) const {
    std::vector<std::size_t> out;
    for_each_on(a, b, [&](std::size_t t) { out.push_back(t); });
    return out;
  }
  std::size_t uses(std::uint32_t a, std::uint32_t b) const {
    std::size_t n = 0;
    for_each_on(a, b, [&](std::size_t) { ++n; });
    return n;
  }
  void drop(std::size_t t) { dropped_[t] = 1; }
  /// Removes the dropped triangles from the mesh (which this then no longer describes).
  void erase_dropped(SurfaceMesh& mesh) const {
    std::size_t kept = 0;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      if (!dropped_[t]) mesh.triangles[kept++] = mesh.triangles[t];
    mesh.triangles.resize(kept);
  }

 private:
  template <class F>
  void for_each_on(std::uint32_t a, std::uint32_t b, F&& f) const {
    for (std::size_t k = around_.start[a]; k < around_.start[a + 1]; ++k) {
      const std::size_t t = around_.by_vertex[k];
      const auto& tri = mesh_.triangles[t];
      if (!dropped_[t] && (tri[0] == b || tri[1] == b || tri[2] == b)) f(t);
    }
  }
  const SurfaceMesh& mesh_;
  detail::VertexTriangles around_;
  std::vector<char> dropped_;
};

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
  if (std::none_of(mesh.triangles.begin(), mesh.triangles.end(), crosses)) return;
  EdgeTriangles edges(mesh);
  std::vector<std::size_t> extra;  // all judged on the counts before any goes
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const auto& t = mesh.triangles[i];
    if (!crosses(t)) continue;
    for (int k = 0; k < 3; ++k)
      if (edges.uses(t[k], t[(k + 1) % 3]) > 2) {
        extra.push_back(i);
        break;
      }
  }
  for (const std::size_t i : extra) edges.drop(i);
  edges.erase_dropped(mesh);
}

/// Removes flaps: a triangle with one edge in no other triangle and its other two edges
/// in three or more. Three faces of a tetrahedron kept around a vertex (their dual edges
/// all meet the surface near a crease) make one, and without it each of its edges is in
/// two triangles or none (the elephant at r = 0.01, seed 587: edges in three triangles and
/// a hole). The lone edge must not be one of an open boundary: on an open surface it needs
/// an end that is no fixed disk (`sample_patch` not kAnyPatch).
void drop_flaps(SurfaceMesh& mesh, const std::vector<std::uint32_t>& sample_patch, bool closed) {
  EdgeTriangles edges(mesh);
  // One at a time, the counts without those dropped: two flaps on one edge must not both go.
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const auto& t = mesh.triangles[i];
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = t[k], b = t[(k + 1) % 3], c = t[(k + 2) % 3];
      if (edges.uses(a, b) == 1 && edges.uses(b, c) >= 3 && edges.uses(c, a) >= 3 &&
          (closed || sample_patch[a] != kAnyPatch || sample_patch[b] != kAnyPatch)) {
        edges.drop(i);
        break;
      }
    }
  }
  edges.erase_dropped(mesh);
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
/// edges. One fan at a time, the edges read anew after each (they are rare).
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
  for (bool changed = !feature_edges.empty(); changed;) {
    changed = false;
    const EdgeTriangles edges(mesh);
    const auto on = [&](std::uint32_t p, std::uint32_t q) { return edges.on(p, q); };
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

/// The rounding mode interval arithmetic needs, set while an object lives; nothing for an
/// exact type.
template <class NT>
struct RoundingFor {};
template <>
struct RoundingFor<Interval> : CGAL::Protect_FPU_rounding<true> {};

Interval as_interval(const Interval& x) { return x; }
Interval as_interval(const Ring& x) { return Interval(x.to_interval()); }

/// An axis-aligned box known to hold a point.
struct PointBox {
  std::array<double, 3> lo, hi;
  bool finite() const {
    for (int k = 0; k < 3; ++k)
      if (!std::isfinite(lo[k]) || !std::isfinite(hi[k])) return false;
    return true;
  }
  Point middle() const { return {0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2])}; }
  double width() const { return std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}); }
};

template <class NT>
PointBox box_of(const detail::HomogeneousPoint<NT>& p) {
  [[maybe_unused]] const RoundingFor<Interval> rounding;
  PointBox b;
  const Interval d = as_interval(p.d);
  for (int k = 0; k < 3; ++k) {
    const Interval x = as_interval(p.n[k]) / d;  // all reals when d may be zero
    b.lo[k] = x.inf(), b.hi[k] = x.sup();
  }
  return b;
}

/// AABB traversal that lists the triangles whose box, grown by `pad`, meets the segment
/// from `from` to `from + step` (the middles of two point boxes): every triangle that the
/// segment between the boxed points can meet. pad also covers the rounding of the slab
/// test below, in doubles.
struct NearSegment {
  std::array<double, 3> from, step;
  double pad;
  TriangleList::const_iterator first;
  std::vector<std::size_t>* out;

  bool go_further() const { return true; }
  template <class Node>
  bool do_intersect(const Point&, const Node& node) const {
    return near(node.bbox());
  }
  void intersection(const Point&, const Primitive& primitive) {
    if (near(primitive.datum().bbox())) out->push_back(static_cast<std::size_t>(primitive.id() - first));
  }
  bool near(const CGAL::Bbox_3& b) const {
    double t0 = 0, t1 = 1;
    for (int k = 0; k < 3; ++k) {
      const double lo = b.min(k) - pad, hi = b.max(k) + pad;
      if (std::abs(step[k]) < 1e-300) {  // (nearly) parallel to this slab
        if (from[k] < lo || from[k] > hi) return false;
        continue;
      }
      double ta = (lo - from[k]) / step[k], tb = (hi - from[k]) / step[k];
      if (ta > tb) std::swap(ta, tb);
      t0 = std::max(t0, ta), t1 = std::min(t1, tb);
      if (t0 > t1) return false;
    }
    return true;
  }
};

/// Which surface triangles the dual of a Delaunay facet meets: the segment between the
/// circumcenters of its two cells, or for a hull facet the ray from the finite cell's
/// circumcenter away from it. Samples on a flat piece of surface are coplanar up to
/// rounding, so the triangulation holds flat slivers whose circumcenters, rounded, land
/// anywhere along the normal. Three tries, each exact where it answers: intervals on the
/// circumcenters kept homogeneous (dual_edge.h), which settle almost every facet; the
/// same polynomials in an exact ring where an interval holds zero (the slivers); and
/// rational constructions where even that meets a zero (a circumcenter on a triangle's
/// plane or edge, four cospherical samples).
// The surface's triangles as CGAL's, their boxes, their AABB tree and a ball around
// them: made once per surface (a kept triangulation keeps them too: remesh's later meshes
// of the elephant at 10^4 samples spent a fifth of their time making them again).
struct SurfaceSearch {
  explicit SurfaceSearch(const SurfaceDomain& surface)
      : vertices(surface.vertices()), corners(surface.triangles()) {
    for (const auto& t : corners)
      triangles.emplace_back(point(vertices[t[0]]), point(vertices[t[1]]), point(vertices[t[2]]));
    for (const auto& t : triangles) boxes.push_back(t.bbox());
    tree.insert(triangles.begin(), triangles.end());
    tree.build();
    const CGAL::Bbox_3 box = tree.bbox();
    ball_center = {(box.xmin() + box.xmax()) / 2, (box.ymin() + box.ymax()) / 2,
                   (box.zmin() + box.zmax()) / 2};
    ball_radius =
        1.001 *
        norm(Vec3{box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()}) / 2;
    scale = 1 + std::hypot(ball_center[0], ball_center[1], ball_center[2]) + ball_radius;
  }
  SurfaceSearch(const SurfaceSearch&) = delete;  // the tree points into `triangles`
  SurfaceSearch& operator=(const SurfaceSearch&) = delete;
  /// Made from this surface's vertices and triangles.
  bool of(const SurfaceDomain& surface) const {
    return surface.vertices() == vertices && surface.triangles() == corners;
  }

  std::vector<Vec3> vertices;
  std::vector<std::array<std::size_t, 3>> corners;
  TriangleList triangles;           // every surface triangle, in order (zero-area ones too)
  std::vector<CGAL::Bbox_3> boxes;  // their bounding boxes
  Tree tree;
  std::array<double, 3> ball_center{};
  double ball_radius = 0, scale = 1;
};

/// The cells' circumcenters in intervals and their boxes, by DualEdges' cell index: kept
/// with the triangulation, so meshing again writes memory already in use (fresh pages
/// cost more than the centers: the elephant at 10^4 samples, a fifth of a mesh's time).
struct CellCenters {
  std::vector<detail::HomogeneousPoint<Interval>> center;
  std::vector<PointBox> box;
};

class DualEdges {
 public:
  /// `reach` > 0: every point of the surface lies within it of a sample, so a point of
  /// the surface on a facet's dual edge (equally near its three corners, and no sample
  /// nearer) lies within it of the facet's corners; only that part of the edge is searched.
  /// The searches that follow may run on several threads, each with its own Scratch;
  /// `threads` find the triangles near each sample here.
  /// `tested`: the facets whose duals will be asked about (hits), where not all: only
  /// their cells get an index (CellInfo::index, into `centers`) and a circumcenter, and
  /// only their corners' triangles are found.
  DualEdges(const Delaunay& dt, const std::vector<Vec3>& samples, const SurfaceDomain& surface,
            const SurfaceSearch& search, detail::DualArithmetic arithmetic, double reach,
            unsigned threads, CellCenters& centers,
            const std::vector<Delaunay::Facet>* tested = nullptr)
      : dt_(dt),
        samples_(samples),
        surface_(surface),
        arithmetic_(arithmetic),
        reach_(reach),
        triangles_(search.triangles),
        boxes_(search.boxes),
        tree_(search.tree),
        ball_center_(search.ball_center),
        ball_radius_(search.ball_radius),
        scale_(search.scale),
        interval_centers_(centers.center),
        interval_boxes_(centers.box) {
    for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c)
      c->info().index = kNoIndex;
    std::vector<Delaunay::Cell_handle> cells;
    std::vector<char> sample_needed(samples.size(), 0);
    const auto need = [&](Delaunay::Cell_handle c) {
      if (dt.is_infinite(c) || c->info().index != kNoIndex) return;
      c->info().index = static_cast<std::uint32_t>(cells.size());
      cells.push_back(c);
    };
    if (!tested) {
      for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) need(c);
      sample_needed.assign(samples.size(), 1);
    } else {
      for (const Delaunay::Facet& f : *tested) {
        const Ends e = ends(f);
        need(e.cell);
        need(e.other);
        sample_needed[e.cell->vertex((e.facet + 1) & 3)->info()] = 1;
      }
    }
    if (arithmetic == detail::DualArithmetic::filtered) {
      interval_centers_.resize(cells.size());
      interval_boxes_.resize(cells.size());
      detail::parallel_for(
          (cells.size() + kChunk - 1) / kChunk, threads, [&](std::size_t chunk, unsigned) {
            [[maybe_unused]] const RoundingFor<Interval> rounding;
            for (std::size_t i = chunk * kChunk; i < std::min(cells.size(), (chunk + 1) * kChunk);
                 ++i) {
              const Delaunay::Cell_handle c = cells[i];
              interval_centers_[i] =
                  detail::circumcenter<Interval>(at(c, 0), at(c, 1), at(c, 2), at(c, 3));
              interval_boxes_[i] = box_of(interval_centers_[i]);
            }
          });
    }
    if (reach_ > 0) find_triangles_near_samples(threads, sample_needed);
  }

  /// What one thread's searches need of their own: caches of exact centers, the exact
  /// tree (built on first use), lists, and the count of each arithmetic's answers.
  struct Scratch {
    std::unordered_map<std::uint32_t, detail::HomogeneousPoint<Ring>> ring_centers;
    std::unordered_map<std::uint32_t, Exact::Point_3> exact_centers;
    ExactTriangles exact_input;
    std::unique_ptr<ExactTree> exact_tree;
    std::vector<std::size_t> candidates;
    std::vector<ExactTriangles::const_iterator> exact_hits;
    detail::DualEdgeCounts counts;
  };

  /// The indices of the surface triangles that the dual of f meets.
  void hits(const Delaunay::Facet& f, std::vector<std::size_t>& out, Scratch& s) const {
    if (arithmetic_ == detail::DualArithmetic::filtered) {
      if (try_in<Interval>(f, out, s) != detail::Crossing::unsure) return void(++s.counts.interval);
      if (try_in<Ring>(f, out, s) != detail::Crossing::unsure) return void(++s.counts.ring);
    }
    rational(f, out, s);
    ++s.counts.rational;
  }

  /// The surface triangle nearest to f's centroid among `hits` (ties: the lower index).
  std::size_t nearest(const std::array<std::uint32_t, 3>& f, const std::vector<std::size_t>& hits) const {
    const Point centroid = point((samples_[f[0]] + samples_[f[1]] + samples_[f[2]]) * (1.0 / 3));
    std::size_t best = hits[0];
    double best_d2 = CGAL::squared_distance(centroid, triangles_[best]);
    for (const std::size_t h : hits) {
      const double d2 = CGAL::squared_distance(centroid, triangles_[h]);
      if (d2 < best_d2 || (d2 == best_d2 && h < best)) best = h, best_d2 = d2;
    }
    return best;
  }

 private:
  Vec3 at(Delaunay::Cell_handle c, int k) const { return samples_[c->vertex(k)->info()]; }

  /// f as its finite cell, the facet's index in it and the other cell (infinite for a
  /// hull facet).
  struct Ends {
    Delaunay::Cell_handle cell, other;
    int facet;
  };
  Ends ends(const Delaunay::Facet& f) const {
    Ends e{f.first, f.first->neighbor(f.second), f.second};
    if (dt_.is_infinite(e.cell)) e.facet = e.other->index(e.cell), std::swap(e.cell, e.other);
    return e;
  }

  /// A box around a cell's circumcenter in NT.
  template <class NT>
  PointBox box(Delaunay::Cell_handle c, Scratch& s) const {
    if constexpr (std::is_same_v<NT, Interval>) {
      return interval_boxes_[c->info().index];
    } else {
      return box_of(center<NT>(c, s));
    }
  }

  template <class NT>
  const detail::HomogeneousPoint<NT>& center(Delaunay::Cell_handle c, Scratch& s) const {
    if constexpr (std::is_same_v<NT, Interval>) {
      return interval_centers_[c->info().index];
    } else {
      auto it = s.ring_centers.find(c->info().index);
      if (it == s.ring_centers.end())
        it = s.ring_centers
                 .emplace(c->info().index,
                          detail::circumcenter<Ring>(at(c, 0), at(c, 1), at(c, 2), at(c, 3)))
                 .first;
      return it->second;
    }
  }

  /// The dual of f tested in NT; `out` holds the hit triangles unless the answer is unsure.
  template <class NT>
  detail::Crossing try_in(const Delaunay::Facet& f, std::vector<std::size_t>& out,
                          Scratch& s) const {
    const Ends e = ends(f);
    const detail::HomogeneousPoint<NT>& p = center<NT>(e.cell, s);
    if (!dt_.is_infinite(e.other)) {
      const detail::HomogeneousPoint<NT>& q = center<NT>(e.other, s);
      if constexpr (std::is_same_v<NT, Ring>) {
        // Four cospherical samples: the dual edge is a point, which meets the surface
        // with probability zero (the rational path skips it too).
        if (p.n[0] * q.d == q.n[0] * p.d && p.n[1] * q.d == q.n[1] * p.d && p.n[2] * q.d == q.n[2] * p.d) {
          out.clear();
          return detail::Crossing::miss;
        }
      }
      return along<NT>(p, box<NT>(e.cell, s), q, box<NT>(e.other, s),
                       e.cell->vertex((e.facet + 1) & 3)->info(), out, s);
    }
    // The ray, cut where it leaves the ball around the surface.
    const Vec3 a = at(e.cell, (e.facet + 1) & 3), b = at(e.cell, (e.facet + 2) & 3), c = at(e.cell, (e.facet + 3) & 3);
    const bool flip = CGAL::orientation(point(a), point(b), point(c), point(at(e.cell, e.facet))) == CGAL::POSITIVE;
    detail::Vector3<NT> out_dir;
    {
      [[maybe_unused]] const RoundingFor<NT> rounding;
      const detail::Vector3<NT> va = detail::vector_of<NT>(a);
      out_dir = detail::cross(detail::minus(detail::vector_of<NT>(b), va), detail::minus(detail::vector_of<NT>(c), va));
      if (flip) out_dir = detail::scaled(out_dir, NT(-1));
    }
    const PointBox from = box<NT>(e.cell, s);
    double shortest = 0;  // a lower bound on |out_dir|
    {
      [[maybe_unused]] const RoundingFor<Interval> rounding;
      Interval length2(0);
      for (int k = 0; k < 3; ++k) length2 += CGAL::square(as_interval(out_dir[k]));
      shortest = std::sqrt(length2.inf()) * (1 - 1e-9);
    }
    if (!from.finite() || !(shortest > 0)) return detail::Crossing::unsure;
    const Point m = from.middle();
    const double farthest =
        std::hypot(m.x() - ball_center_[0], m.y() - ball_center_[1], m.z() - ball_center_[2]) + 2 * from.width();
    const double t = 2 * (farthest + ball_radius_) / shortest;
    if (!std::isfinite(t)) return detail::Crossing::unsure;
    detail::HomogeneousPoint<NT> q;
    {
      [[maybe_unused]] const RoundingFor<NT> rounding;
      q = detail::moved(p, out_dir, t);
    }
    return along<NT>(p, from, q, box_of(q), e.cell->vertex((e.facet + 1) & 3)->info(), out, s);
  }

  /// The triangles the segment pq meets, or unsure; bp and bq hold p and q, `corner`
  /// is the sample at a corner of the facet whose dual it is.
  template <class NT>
  detail::Crossing along(const detail::HomogeneousPoint<NT>& p, const PointBox& bp,
                         const detail::HomogeneousPoint<NT>& q, const PointBox& bq,
                         std::uint32_t corner, std::vector<std::size_t>& out, Scratch& s) const {
    out.clear();
    if (!bp.finite() || !bq.finite()) return detail::Crossing::unsure;
    if (reach_ > 0) {
      // Only the part within reach of the corner can meet the surface: most duals of
      // Delaunay facets that are no mesh triangles have none, and long ones get short;
      // what is left can meet only the triangles near the corner (in intervals).
      const Vec3 c = samples_[corner];
      const auto [u0, u1] = chord(bp, bq, {c.x, c.y, c.z}, reach_ * (1 + 1e-6));
      if (u0 > u1) return detail::Crossing::miss;
      const std::vector<std::uint32_t>* local =
          std::is_same_v<NT, Interval> ? &near_sample_[corner] : nullptr;
      if (u0 > 0 || u1 < 1) {
        detail::HomogeneousPoint<NT> from, to;
        {
          [[maybe_unused]] const RoundingFor<NT> rounding;
          from = detail::between(p, q, u0), to = detail::between(p, q, u1);
        }
        return along_inside(from, box_of(from), to, box_of(to), out, s, local);
      }
      return along_inside(p, bp, q, bq, out, s, local);
    }
    if (!in_ball(bp) || !in_ball(bq)) {
      // A flat sliver's circumcenter can lie 10^16 away, where doubles say nothing about
      // the surface: the segment is cut, exactly, to the part that can meet the ball.
      const auto [u0, u1] = chord(bp, bq, ball_center_, 1.01 * ball_radius_);
      if (u0 > u1) return detail::Crossing::miss;
      if (u0 > 0 || u1 < 1) {
        detail::HomogeneousPoint<NT> from, to;
        {
          [[maybe_unused]] const RoundingFor<NT> rounding;
          from = detail::between(p, q, u0), to = detail::between(p, q, u1);
        }
        return along_inside(from, box_of(from), to, box_of(to), out, s);
      }
    }
    return along_inside(p, bp, q, bq, out, s);
  }

  bool in_ball(const PointBox& b) const {
    double d2 = 0;
    for (int k = 0; k < 3; ++k) {
      const double far = std::max(std::abs(b.lo[k] - ball_center_[k]), std::abs(b.hi[k] - ball_center_[k]));
      d2 += far * far;
    }
    return d2 < ball_radius_ * ball_radius_;
  }

  /// Parameters u0, u1 such that the points p + u (q - p) in the ball (center, radius)
  /// have u in [u0, u1] (u0 > u1 if none): the ball's chord lies within R / |q - p| of
  /// the parameter of the point nearest to its center. Bounds rounded outward by
  /// interval arithmetic.
  static std::pair<double, double> chord(const PointBox& bp, const PointBox& bq,
                                         const std::array<double, 3>& center, double radius) {
    [[maybe_unused]] const RoundingFor<Interval> rounding;
    Interval length2(0), toward(0);
    for (int k = 0; k < 3; ++k) {
      const Interval from(bp.lo[k], bp.hi[k]), step = Interval(bq.lo[k], bq.hi[k]) - from;
      length2 += CGAL::square(step);
      toward += (Interval(center[k]) - from) * step;
    }
    if (!(length2.inf() > 0)) return {0, 1};
    const Interval nearest = toward / length2;
    const Interval reach = Interval(radius) / CGAL::sqrt(Interval(length2.inf()));
    return {std::max(0.0, (nearest - reach).inf()), std::min(1.0, (nearest + reach).sup())};
  }

  /// For each sample, the surface triangles whose boxes come within 1.5 reach (plus the
  /// largest pad an interval search allows) of it: a crossing of a dual edge of a facet
  /// at the sample lies within reach of it, so these hold every triangle it can be on.
  void find_triangles_near_samples(unsigned threads, const std::vector<char>& needed) {
    near_sample_.resize(samples_.size());
    std::vector<std::vector<std::size_t>> found(threads);
    const double w = 1.5 * reach_ * (1 + 1e-6) + 2e-3 * ball_radius_ + 1e-14 * scale_;
    detail::parallel_for(samples_.size(), threads, [&](std::size_t i, unsigned thread) {
      if (!needed[i]) return;
      const Vec3 c = samples_[i];
      NearSegment box{{c.x, c.y, c.z}, {0, 0, 0}, w, triangles_.begin(), &found[thread]};
      found[thread].clear();
      tree_.traversal(point(c), box);
      near_sample_[i].assign(found[thread].begin(), found[thread].end());
    });
  }

  /// along() for a segment that the caller has cut to the ball where needed; with
  /// `local`, the only triangles it can meet.
  template <class NT>
  detail::Crossing along_inside(const detail::HomogeneousPoint<NT>& p, const PointBox& bp,
                                const detail::HomogeneousPoint<NT>& q, const PointBox& bq,
                                std::vector<std::size_t>& out, Scratch& s,
                                const std::vector<std::uint32_t>* local = nullptr) const {
    if (!bp.finite() || !bq.finite()) return detail::Crossing::unsure;
    const Point a = bp.middle(), b = bq.middle();
    NearSegment near{{a.x(), a.y(), a.z()},
                     {b.x() - a.x(), b.y() - a.y(), b.z() - a.z()},
                     0,
                     triangles_.begin(),
                     &s.candidates};
    double extent = scale_;
    for (int k = 0; k < 3; ++k) extent = std::max({extent, std::abs(a[k]), std::abs(b[k])});
    near.pad = 2 * std::max(bp.width(), bq.width()) + 1e-14 * extent;
    // Too vague to be worth a search: the next arithmetic will be sharper.
    if (std::is_same_v<NT, Interval> && near.pad > 1e-3 * ball_radius_) return detail::Crossing::unsure;
    s.candidates.clear();
    if (local) {
      for (const std::uint32_t k : *local)
        if (near.near(boxes_[k])) s.candidates.push_back(k);
    } else {
      tree_.traversal(a, near);
    }
    // Exact centers are tested in intervals first (their rounding is tight), exactly
    // only where that is unsure.
    [[maybe_unused]] const RoundingFor<Interval> rounding;
    detail::HomogeneousPoint<Interval> p_near, q_near;
    if constexpr (std::is_same_v<NT, Ring>) p_near = rounded(p), q_near = rounded(q);
    const std::vector<Vec3>& v = surface_.vertices();
    for (const std::size_t k : s.candidates) {
      const auto& t = surface_.triangles()[k];
      detail::Crossing c;
      if constexpr (std::is_same_v<NT, Ring>) {
        c = detail::segment_meets_triangle(p_near, q_near, v[t[0]], v[t[1]], v[t[2]]);
        if (c == detail::Crossing::unsure) {
          const CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
          c = detail::segment_meets_triangle(p, q, v[t[0]], v[t[1]], v[t[2]]);
        }
      } else {
        c = detail::segment_meets_triangle(p, q, v[t[0]], v[t[1]], v[t[2]]);
      }
      if (c == detail::Crossing::unsure) return c;
      if (c == detail::Crossing::hit) out.push_back(k);
    }
    return out.empty() ? detail::Crossing::miss : detail::Crossing::hit;
  }

  static detail::HomogeneousPoint<Interval> rounded(const detail::HomogeneousPoint<Ring>& p) {
    return {{as_interval(p.n[0]), as_interval(p.n[1]), as_interval(p.n[2])}, as_interval(p.d)};
  }

  /// The dual built and tested in rational arithmetic (Epeck), the tree built on first use.
  void rational(const Delaunay::Facet& f, std::vector<std::size_t>& out, Scratch& s) const {
    if (!s.exact_tree) {
      const std::vector<Vec3>& v = surface_.vertices();
      for (const auto& t : surface_.triangles())
        s.exact_input.emplace_back(exact(v[t[0]]), exact(v[t[1]]), exact(v[t[2]]));
      s.exact_tree = std::make_unique<ExactTree>(s.exact_input.begin(), s.exact_input.end());
    }
    const Ends e = ends(f);
    s.exact_hits.clear();
    if (!dt_.is_infinite(e.other)) {
      const Exact::Segment_3 dual(exact_center(e.cell, s), exact_center(e.other, s));
      // AABB segment queries need a proper segment (and a point is missed anyway).
      if (!dual.is_degenerate())
        s.exact_tree->all_intersected_primitives(dual, std::back_inserter(s.exact_hits));
    } else {
      const Exact::Point_3 p = exact(at(e.cell, (e.facet + 1) & 3)), q = exact(at(e.cell, (e.facet + 2) & 3)),
                           r = exact(at(e.cell, (e.facet + 3) & 3)), inside = exact(at(e.cell, e.facet));
      Exact::Vector_3 dir = CGAL::cross_product(q - p, r - p);
      if (CGAL::orientation(p, q, r, inside) == CGAL::POSITIVE) dir = -dir;
      s.exact_tree->all_intersected_primitives(Exact::Ray_3(exact_center(e.cell, s), dir),
                                               std::back_inserter(s.exact_hits));
    }
    out.clear();
    for (const auto h : s.exact_hits)
      out.push_back(static_cast<std::size_t>(h - s.exact_input.begin()));
  }

  const Exact::Point_3& exact_center(Delaunay::Cell_handle c, Scratch& s) const {
    auto it = s.exact_centers.find(c->info().index);
    if (it == s.exact_centers.end()) {
      it = s.exact_centers
               .emplace(c->info().index, CGAL::circumcenter(exact(at(c, 0)), exact(at(c, 1)),
                                                            exact(at(c, 2)), exact(at(c, 3))))
               .first;
    }
    return it->second;
  }

  static constexpr std::uint32_t kNoIndex = ~std::uint32_t{0};
  const Delaunay& dt_;
  const std::vector<Vec3>& samples_;
  const SurfaceDomain& surface_;
  detail::DualArithmetic arithmetic_;
  double reach_;            // 0: the samples' coverage is not known
  static constexpr std::size_t kChunk = 1024;
  const TriangleList& triangles_;  // SurfaceSearch's
  const std::vector<CGAL::Bbox_3>& boxes_;
  const Tree& tree_;
  std::array<double, 3> ball_center_;  // a ray's part beyond this ball meets nothing
  double ball_radius_, scale_;
  std::vector<std::vector<std::uint32_t>>
      near_sample_;  // with a reach: find_triangles_near_samples
  std::vector<detail::HomogeneousPoint<Interval>>& interval_centers_;  // CellCenters'
  std::vector<PointBox>& interval_boxes_;
};

// A facet's corners, sorted.
std::array<std::uint32_t, 3> sorted_corners(const Delaunay::Facet& f) {
  std::array<std::uint32_t, 3> t;
  for (int k = 0; k < 3; ++k) t[k] = f.first->vertex((f.second + 1 + k) & 3)->info();
  std::sort(t.begin(), t.end());
  return t;
}

// f's corners.
std::array<Vec3, 3> corners(const Delaunay::Facet& f, const std::vector<Vec3>& samples) {
  std::array<Vec3, 3> t;
  for (int k = 0; k < 3; ++k) t[k] = samples[f.first->vertex((f.second + 1 + k) & 3)->info()];
  return t;
}

// True where no point within `reach` of the corners of t is equally near to all three:
// an edge longer than twice the reach, or a circumcircle wider than it (its center is
// the nearest such point). Where every point of the surface lies within `reach` of a
// sample, the dual of such a facet meets no surface, and DualEdges, which searches only
// within reach * (1 + 1e-6) of a corner, would find nothing on it. The margins (that
// factor, 1e-9 more, and the cross product's norm taken 1e-12 of its bound larger) lie
// far above the rounding of doubles, so a facet is dropped only where that holds exactly.
bool out_of_reach(const std::array<Vec3, 3>& t, double reach) {
  const double far = reach * (1 + 1e-6) * (1 + 1e-9);
  const Vec3 ab = t[1] - t[0], ac = t[2] - t[0], bc = t[2] - t[1];
  const double ab2 = squared_norm(ab), ac2 = squared_norm(ac), bc2 = squared_norm(bc);
  const double edge2 = 4 * far * far;
  if (ab2 > edge2 || ac2 > edge2 || bc2 > edge2) return true;
  // The circumradius is |ab| |ac| |bc| / (2 |ab x ac|).
  const double twice_area = norm(cross(ab, ac)) + 1e-12 * std::sqrt(ab2 * ac2);
  return std::sqrt(ab2 * ac2 * bc2) > 2 * far * twice_area;
}

// The verdict f got with the same two cells around it, from either side, or 0.
std::uint8_t known_verdict(const Delaunay::Facet& f) {
  const Delaunay::Cell_handle c = f.first, d = c->neighbor(f.second);
  const CellInfo &ci = c->info(), &di = d->info();
  if (ci.verdict[f.second] != 0 && ci.across[f.second] == di.stamp) return ci.verdict[f.second];
  const int j = d->index(c);
  if (di.verdict[j] != 0 && di.across[j] == ci.stamp) return di.verdict[j];
  return 0;
}

}  // namespace

// The triangulation of the last mesh, kept for the next (RestrictedDelaunayReuse).
struct detail::RestrictedDelaunayState {
  Delaunay dt;
  std::vector<Delaunay::Vertex_handle> vertex;  // of each sample
  std::vector<Vec3> samples;                    // where they were
  const SurfaceDomain* surface = nullptr;
  std::shared_ptr<const SurfaceSearch> search;  // of the last surface (kept though not valid)
  double reach = 0;
  std::uint32_t next_stamp = 1;
  bool valid = false;  // all the above describe the last mesh
  CellCenters centers;  // DualEdges' memory, whatever `valid` says
};

RestrictedDelaunayReuse::RestrictedDelaunayReuse()
    : state_(std::make_unique<detail::RestrictedDelaunayState>()) {}
RestrictedDelaunayReuse::~RestrictedDelaunayReuse() = default;
RestrictedDelaunayReuse::RestrictedDelaunayReuse(RestrictedDelaunayReuse&&) noexcept = default;
RestrictedDelaunayReuse& RestrictedDelaunayReuse::operator=(RestrictedDelaunayReuse&&) noexcept =
    default;

SurfaceMesh restricted_delaunay(const std::vector<Vec3>& samples, const SurfaceDomain& surface) {
  return restricted_delaunay(samples, surface, std::vector<std::uint32_t>(samples.size(), kAnyPatch), {});
}

SurfaceMesh restricted_delaunay(const SurfacePacking& packing, Coverage coverage,
                                unsigned threads) {
  return restricted_delaunay(packing, coverage, threads, nullptr);
}

SurfaceMesh restricted_delaunay(const SurfacePacking& packing, Coverage coverage, unsigned threads,
                                RestrictedDelaunayReuse* reuse) {
  std::vector<Vec3> samples;
  std::vector<std::uint32_t> patch;
  for (const DiskId id : packing.ids()) {
    samples.push_back(packing.center(id));
    patch.push_back((packing.flags(id) & kFixed) ? kAnyPatch
                                                 : packing.domain().triangle_patch()[packing.point(id).triangle]);
  }
  const auto along_features = detail::feature_neighbours(packing);
  SurfaceMesh mesh = detail::restricted_delaunay(
      samples, packing.domain(), patch, along_features, detail::DualArithmetic::filtered, nullptr,
      coverage == Coverage::maximal ? packing.max_radius() : 0, threads,
      reuse ? reuse->state_.get() : nullptr);
  // The feature curves' consecutive disks that the mesh joins (none without curves: a
  // set of the mesh's edges was 4 % of the elephant's mesh at 10^4 vertices).
  if (along_features.empty()) return mesh;
  std::vector<std::uint64_t> edges;
  edges.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) edges.push_back(edge_key(t[k], t[(k + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  for (const auto& e : along_features)
    if (std::binary_search(edges.begin(), edges.end(), edge_key(e[0], e[1])))
      mesh.feature_edges.push_back(e);
  return mesh;
}

SurfaceMesh restricted_delaunay(const std::vector<Vec3>& samples, const SurfaceDomain& surface,
                                const std::vector<std::uint32_t>& sample_patch,
                                const std::vector<std::array<std::uint32_t, 2>>& feature_edges) {
  return detail::restricted_delaunay(samples, surface, sample_patch, feature_edges, detail::DualArithmetic::filtered,
                                     nullptr);
}

SurfaceMesh detail::restricted_delaunay(
    const std::vector<Vec3>& samples, const SurfaceDomain& surface,
    const std::vector<std::uint32_t>& sample_patch,
    const std::vector<std::array<std::uint32_t, 2>>& feature_edges, DualArithmetic arithmetic,
    DualEdgeCounts* counts, double covered_within, unsigned threads,
    RestrictedDelaunayState* state) {
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
  // The triangulation: the last call's with the moved samples moved, where this one
  // meshes the same surface with the same reach and few samples moved; else built anew.
  RestrictedDelaunayState local;
  RestrictedDelaunayState& st = state ? *state : local;
  const bool same_surface = st.search && st.search->of(surface);
  if (!same_surface) st.search = std::make_shared<const SurfaceSearch>(surface);
  std::vector<std::uint32_t> moved;
  bool reuse = st.valid && same_surface && st.surface == &surface && st.reach == covered_within &&
               st.samples.size() == samples.size() && arithmetic == DualArithmetic::filtered;
  for (std::size_t i = 0; reuse && i < samples.size(); ++i) {
    if (!(samples[i] == st.samples[i])) moved.push_back(static_cast<std::uint32_t>(i));
    reuse = moved.size() <= samples.size() / 8;  // beyond that a new one is cheaper
  }
  st.valid = false;  // until this call has finished
  for (const std::uint32_t i : moved) {
    const Delaunay::Vertex_handle v = st.dt.move(st.vertex[i], point(samples[i]));
    if (v != st.vertex[i]) {  // it landed on another sample: start afresh
      reuse = false;
      break;
    }
    // Its cells are new, or moved with it where CGAL could move it in place: their
    // verdicts, and (by their stamps) those of the facets facing them, lapse.
    std::vector<Delaunay::Cell_handle> around;
    st.dt.incident_cells(v, std::back_inserter(around));
    for (const Delaunay::Cell_handle c : around) c->info() = CellInfo{};
  }
  if (!reuse) {
    const auto distinct = distinct_samples(samples);
    st.dt = Delaunay(distinct.begin(), distinct.end());
    st.vertex.assign(samples.size(), Delaunay::Vertex_handle());
    for (auto v = st.dt.finite_vertices_begin(); v != st.dt.finite_vertices_end(); ++v)
      st.vertex[v->info()] = v;
  }
  Delaunay& dt = st.dt;
  if (dt.dimension() < 2) {
    throw InvalidInput("restricted_delaunay: the " + std::to_string(samples.size()) +
                       " samples lie on one line; sample the whole surface");
  }
  threads = thread_count(threads);
  // Stamps for the cells made since the last call; a facet whose two cells kept theirs
  // keeps its verdict (its dual edge, and the samples near its corners, are the same):
  // those facets are settled here (their triangles in `settled`), and with a reach,
  // those whose corners no point within it is equally near to (most facets of a
  // surface's Delaunay tetrahedra: those across its inside), before any dual is made.
  // The others are tested.
  std::vector<Delaunay::Facet> tested;
  std::vector<std::array<std::uint32_t, 3>> settled;
  if (dt.dimension() == 3) {
    for (auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c)
      if (c->info().stamp == 0) c->info().stamp = st.next_stamp++;
    for (auto f = dt.finite_facets_begin(); f != dt.finite_facets_end(); ++f) {
      if (const std::uint8_t verdict = reuse ? known_verdict(*f) : 0) {
        if (verdict == 1) continue;
        std::array<std::uint32_t, 3> t = sorted_corners(*f);
        if (verdict == 3) std::swap(t[1], t[2]);
        settled.push_back(t);
      } else if (covered_within > 0 && out_of_reach(corners(*f, samples), covered_within)) {
        f->first->info().verdict[f->second] = 1;
        f->first->info().across[f->second] = f->first->neighbor(f->second)->info().stamp;
      } else {
        tested.push_back(*f);
      }
    }
  }
  // Where every facet is tested, every cell's center is made, in the order they lie.
  const bool every_facet = !reuse && covered_within == 0;
  DualEdges duals(dt, samples, surface, *st.search, arithmetic, covered_within, threads, st.centers,
                  every_facet ? nullptr : &tested);
  const std::vector<Vec3>& sv = surface.vertices();
  SurfaceMesh mesh;
  mesh.vertices = samples;
  // Keeps facet f, given the surface triangles its dual meets, facing the way of the hit
  // surface triangle nearest to it (a long dual edge may cross the surface more than once).
  const auto keep = [&](const Delaunay::Facet& f, const std::vector<std::size_t>& hits,
                        std::vector<std::array<std::uint32_t, 3>>& kept) {
    if (hits.empty()) return;
    std::array<std::uint32_t, 3> t;
    for (int k = 0; k < 3; ++k) t[k] = f.first->vertex((f.second + 1 + k) & 3)->info();
    const auto& hit = surface.triangles()[duals.nearest(t, hits)];
    if (dot(normal(samples, t), normal(sv, hit)) < 0) std::swap(t[1], t[2]);
    // The smallest index first (orientation kept), so the output does not depend on
    // how the triangulation happens to store its cells.
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    kept.push_back(t);
  };

  if (dt.dimension() == 2) {
    // Coplanar samples (rare: a flat surface): each triangle's dual is the line through
    // its circumcenter along the plane's normal, built and tested exactly.
    std::vector<Exact::Triangle_3> input;
    for (const auto& t : surface.triangles()) input.emplace_back(exact(sv[t[0]]), exact(sv[t[1]]), exact(sv[t[2]]));
    const ExactTree tree(input.begin(), input.end());
    std::vector<std::vector<Exact::Triangle_3>::const_iterator> found;
    std::vector<std::size_t> hits;
    const auto exact_point = [&](Delaunay::Vertex_handle v) { return exact(samples[v->info()]); };
    for (auto f = dt.finite_facets_begin(); f != dt.finite_facets_end(); ++f) {
      const Exact::Point_3 a = exact_point(f->first->vertex(0)), b = exact_point(f->first->vertex(1)),
                           c = exact_point(f->first->vertex(2));
      found.clear();
      tree.all_intersected_primitives(Exact::Line_3(CGAL::circumcenter(a, b, c), CGAL::normal(a, b, c)),
                                      std::back_inserter(found));
      hits.clear();
      for (const auto h : found) hits.push_back(static_cast<std::size_t>(h - input.cbegin()));
      keep(*f, hits, mesh.triangles);
    }
  } else {
    // The facets in chunks on the threads, each with its own scratch; the kept triangles
    // are sorted below, so the mesh is the same for any number of threads. A facet's
    // verdict is written into the cell it is seen from, by its thread alone.
    constexpr std::size_t kChunk = 1024;
    const std::size_t chunks = (tested.size() + kChunk - 1) / kChunk;
    std::vector<DualEdges::Scratch> scratch(threads);
    std::vector<std::vector<std::size_t>> hits(threads);
    std::vector<std::vector<std::array<std::uint32_t, 3>>> kept(chunks);
    mesh.triangles = std::move(settled);
    parallel_for(chunks, threads, [&](std::size_t chunk, unsigned thread) {
      for (std::size_t i = chunk * kChunk; i < std::min(tested.size(), (chunk + 1) * kChunk); ++i) {
        const Delaunay::Facet& f = tested[i];
        const std::array<std::uint32_t, 3> t = sorted_corners(f);
        duals.hits(f, hits[thread], scratch[thread]);
        const std::size_t before = kept[chunk].size();
        keep(f, hits[thread], kept[chunk]);
        CellInfo& info = f.first->info();
        info.verdict[f.second] = kept[chunk].size() == before    ? 1
                                 : kept[chunk].back()[1] == t[1] ? 2
                                                                 : 3;
        info.across[f.second] = f.first->neighbor(f.second)->info().stamp;
      }
    });
    for (const auto& part : kept)
      mesh.triangles.insert(mesh.triangles.end(), part.begin(), part.end());
    if (counts) {
      *counts = {};
      for (const DualEdges::Scratch& one : scratch) {
        counts->interval += one.counts.interval, counts->ring += one.counts.ring;
        counts->rational += one.counts.rational;
      }
    }
  }
  // Kept for the next call: a 3D triangulation holding every sample (no repeats).
  if (dt.dimension() == 3 && std::all_of(st.vertex.begin(), st.vertex.end(),
                                         [](Delaunay::Vertex_handle v) { return v != nullptr; })) {
    st.samples = samples;
    st.surface = &surface;
    st.reach = covered_within;
    st.valid = true;
  }
  // Each of these three mends edges in three or more triangles (rare: creases, thin
  // parts), and each rebuilt a hash table of every edge: a third of a later mesh's time.
  if (detail::some_edge_in_three(mesh.triangles, mesh.vertices.size())) {
    cap_fans_across_creases(mesh, feature_edges);
    drop_crossings(mesh, sample_patch);
    drop_flaps(mesh, sample_patch, surface.is_closed());
  }
  detail::cap_bow_ties(mesh);
  // Deterministic order whatever CGAL's internal one: by the triangles' vertex indices.
  std::sort(mesh.triangles.begin(), mesh.triangles.end());
  return mesh;
}

double hausdorff_distance(const SurfaceMesh& mesh, const SurfaceDomain& surface,
                          std::size_t samples_per_mesh, std::uint64_t seed, unsigned threads) {
  threads = detail::thread_count(threads);
  const TriangleList mesh_tris = cgal_triangles(mesh.vertices, mesh.triangles);
  if (mesh_tris.empty()) {
    throw InvalidInput("hausdorff_distance: the mesh has no triangles of non-zero area");
  }
  const TriangleList surface_tris = cgal_triangles(surface.vertices(), surface.triangles());
  Tree mesh_tree(mesh_tris.begin(), mesh_tris.end()), surface_tree(surface_tris.begin(), surface_tris.end());
  mesh_tree.build();  // now, not lazily inside the queries on several threads
  surface_tree.build();
  mesh_tree.accelerate_distance_queries();
  surface_tree.accelerate_distance_queries();

  Rng rng(seed);
  std::vector<Point> on_mesh, on_surface;
  for (const Vec3& v : mesh.vertices) on_mesh.push_back(point(v));
  random_points(mesh.vertices, mesh.triangles, samples_per_mesh, rng, on_mesh);
  for (const Vec3& v : surface.vertices()) on_surface.push_back(point(v));
  random_points(surface.vertices(), surface.triangles(), samples_per_mesh, rng, on_surface);
  return std::max(farthest(on_mesh, surface_tree, threads),
                  farthest(on_surface, mesh_tree, threads));
}

}  // namespace disktune
