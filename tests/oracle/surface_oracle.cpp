// SPDX-License-Identifier: GPL-3.0-or-later
//
// Why the maximality check is exact (up to tol).
//
// The surface is the union of the closed triangles, so it is covered if and only if
// every closed triangle T is. The ball of disk i meets the plane of T in a closed
// planar disk (center: c_i projected, radius rho_i = sqrt(r_i^2 - h_i^2), h_i the
// height of c_i over the plane), so per triangle this is a planar question: is the
// closed triangle T inside the union U of finitely many closed planar disks? The
// candidates are (1) the points where two circles cross (or touch) strictly inside T,
// (2) the points where a circle crosses an edge of T (computed in space: the sphere
// met with the segment, by a quadratic), strictly between the edge's ends, (3) the
// corners of T. A candidate is a witness when no disk other than the ones it was built
// from covers it (within r*(1+tol)); a corner is a witness when no disk covers it.
//
// (a) Suppose p in T is uncovered. Let V be its component of T \ U (open in T,
//     bounded) and W its closure; W lies in no open disk. Look at the OUTER boundary
//     of V (the boundary of the unbounded component of the plane minus W): a closed
//     curve made of arcs of circles and pieces of the edges of T, with V on its inner
//     side. If it contains a corner of T: candidate (3). If it passes from an edge to
//     a circle: that point is on both, candidate (2). If it consists of edge pieces
//     only, it is the whole boundary of T, which has corners. If it consists of arcs
//     only, it passes from one circle to another at a crossing or touching point,
//     candidate (1), unless it is one whole circle: but then V would lie inside that
//     circle, i.e. in a disk, and V is uncovered. So some candidate lies in W, in no
//     open disk, and a disk other than its own covers it only if that disk's circle
//     passes through it (within tol): the degenerate case.
//     In particular a circle that meets no other circle and no edge (an "isolated"
//     circle inside T) needs no candidate of its own, unlike in the planar oracle
//     where a void can be a ring around a hole: the void around an isolated circle has
//     an outer boundary too, and the argument above finds a candidate there (in the
//     simplest case the corners of T). A planar domain with holes needs candidate (4)
//     of planar_oracle.cpp because the outer boundary of a void can be a hole's loop;
//     a triangle has no holes.
// (b) If T is covered, each non-degenerate candidate is covered by another disk: next
//     to a crossing strictly inside T there are points of T outside both circles; next
//     to an edge crossing strictly inside the edge there are points of the edge
//     outside the circle's disk (on the far side of the crossing); these points are
//     covered by finitely many other closed disks, and one of them contains the
//     candidate. So no false witnesses. That is why crossings ON an edge of T (or
//     within a relative 1e-9 of it) and edge crossings at an edge's end are not
//     candidates: their uncovered side may lie outside T, in a neighbouring triangle of
//     another plane (at a crease), where it may well be covered. They are redundant:
//     such a point is also an edge crossing (of both circles) or a corner, and those
//     are candidates (or, at an end of an edge, the corner is).
//
// Degenerate cases (a void whose corners all lie exactly on third circles, e.g. the
// cusp between two tangent circles, or a circle through a corner of T) are caught by
// step probes, as in the planar oracles: beside every candidate that is covered but
// with a margin smaller than the largest step (1e-2 of the local radius), points at
// 1e-2 and 1e-4 of that radius are tested, into the region outside the defining disks
// (crossings: along the sum of the outward normals and just inside both edges of that
// wedge; edge crossings: along the edge, away from the disk; corners: along both edges
// and the bisector), as long as they lie in T. A probe is a point of the surface, so an
// uncovered probe is a genuine witness; the crossings just outside T also get them. The
// random probes are an independent backstop for the degenerate cases and for bugs
// here. As in oracle.cpp, disks whose centers and radii agree within r*tol count as
// one disk.
//
// A degenerate (zero-area) triangle is a segment: its corners and edge crossings are
// the candidates, which is the 1D version of the argument above.
//
// Speed: one uniform grid of the centers (cells at least r_max*(1+tol), at most about
// 8N cells); a triangle's disks are those of the grid cells its bounding box, grown by
// r_max*(1+tol), touches, kept when their ball reaches the triangle. Conflicts use a
// sweep over the centers sorted by x, independent of the grid.

#include "oracle/surface_oracle.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <sstream>
#include <stdexcept>
#include <tuple>

namespace oracle {
namespace {

constexpr std::size_t kKeep = 100;  // entries kept in each report list
constexpr std::size_t kNone = static_cast<std::size_t>(-1);
constexpr double kInf = std::numeric_limits<double>::infinity();
// Step probes: at these fractions of the local radius; needed only beside candidates
// covered with a margin below the larger one.
constexpr double kSteps[2] = {1e-2, 1e-4};
// Relative distance from an edge (or an edge's end) below which a crossing is no
// candidate (see (b) above).
constexpr double kEdgeMargin = 1e-9;

Point3 sub(const Point3& a, const Point3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Point3 add(const Point3& a, const Point3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Point3 mul(const Point3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
double dot(const Point3& a, const Point3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Point3 cross(const Point3& a, const Point3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double norm(const Point3& a) { return std::sqrt(dot(a, a)); }
double dist(const Point3& a, const Point3& b) { return norm(sub(a, b)); }

double segment_distance(const Point3& a, const Point3& b, const Point3& p) {
  const Point3 d = sub(b, a);
  const double len2 = dot(d, d);
  const double t = len2 > 0 ? std::clamp(dot(sub(p, a), d) / len2, 0.0, 1.0) : 0.0;
  return dist(add(a, mul(d, t)), p);
}

// A triangle with an orthonormal frame: a at (0, 0), b at (bx, 0), c at (cx, cy) with
// cy > 0 in the plane coordinates (x, y) = ((p-a).u, (p-a).v); n = u x v.
struct Frame {
  Point3 p[3];
  Point3 u{}, v{}, n{};
  double bx = 0, cx = 0, cy = 0;
  double len[3] = {0, 0, 0};  // |p1-p0|, |p2-p1|, |p0-p2|
  bool degenerate = true;
};

Frame make_frame(const Point3& a, const Point3& b, const Point3& c) {
  Frame f;
  f.p[0] = a;
  f.p[1] = b;
  f.p[2] = c;
  for (int k = 0; k < 3; ++k) f.len[k] = dist(f.p[(k + 1) % 3], f.p[k]);
  const Point3 ab = sub(b, a), ac = sub(c, a);
  const Point3 cr = cross(ab, ac);
  const double twice_area = norm(cr);
  const double longest = std::max({f.len[0], f.len[1], f.len[2]});
  f.degenerate = !(twice_area > 1e-12 * longest * longest) || !(f.len[0] > 0);
  if (f.degenerate) return f;
  f.u = mul(ab, 1 / f.len[0]);
  f.n = mul(cr, 1 / twice_area);
  f.v = cross(f.n, f.u);
  f.bx = f.len[0];
  f.cx = dot(ac, f.u);
  f.cy = dot(ac, f.v);
  return f;
}

// Smallest signed distance from plane point (x, y) to the three edge lines, positive
// inside (non-degenerate frames only).
double inside_margin(const Frame& f, double x, double y) {
  const double s0 = y;
  const double s1 = ((f.cx - f.bx) * y - f.cy * (x - f.bx)) / f.len[1];
  const double s2 = (-f.cx * (y - f.cy) + f.cy * (x - f.cx)) / f.len[2];
  return std::min({s0, s1, s2});
}

Point3 lift(const Frame& f, double x, double y) {
  return add(f.p[0], add(mul(f.u, x), mul(f.v, y)));
}

double triangle_distance(const Frame& f, const Point3& q) {
  if (!f.degenerate) {
    const Point3 w = sub(q, f.p[0]);
    const double x = dot(w, f.u), y = dot(w, f.v), h = dot(w, f.n);
    if (inside_margin(f, x, y) >= 0) return std::fabs(h);
  }
  double best = kInf;
  for (int k = 0; k < 3; ++k) best = std::min(best, segment_distance(f.p[k], f.p[(k + 1) % 3], q));
  return best;
}

// Centers in cubic cells of side >= the requested side (counting-sorted arrays).
// visit() looks at every cell that the query's bounding box touches, so it sees every
// center within R.
class Grid3 {
 public:
  Grid3(const std::vector<Point3>& pts, double side) : p_(pts) {
    if (pts.empty()) return;
    Point3 hi = pts[0];
    lo_ = pts[0];
    for (const auto& q : pts)
      for (int k = 0; k < 3; ++k) {
        lo_[k] = std::min(lo_[k], q[k]);
        hi[k] = std::max(hi[k], q[k]);
      }
    const double cap = 8.0 * static_cast<double>(pts.size()) + 64;
    side_ = side > 0 ? side : 1;
    for (;;) {
      double cells = 1;
      for (int k = 0; k < 3; ++k) cells *= std::floor((hi[k] - lo_[k]) / side_) + 1;
      if (cells <= cap) break;
      side_ *= 1.5;
    }
    for (int k = 0; k < 3; ++k)
      dim_[k] = static_cast<long long>(std::floor((hi[k] - lo_[k]) / side_)) + 1;
    start_.assign(static_cast<std::size_t>(dim_[0] * dim_[1] * dim_[2]) + 1, 0);
    std::vector<std::size_t> cell_of(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) {
      cell_of[i] = index(cell(0, pts[i][0]), cell(1, pts[i][1]), cell(2, pts[i][2]));
      ++start_[cell_of[i] + 1];
    }
    for (std::size_t k = 1; k < start_.size(); ++k) start_[k] += start_[k - 1];
    items_.resize(pts.size());
    std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < pts.size(); ++i) items_[fill[cell_of[i]]++] = i;
  }

  // Calls f(k) for every center k in the cells the box [lo, hi] touches (a superset of
  // the centers in the box); stops and returns true as soon as f returns true.
  template <class F>
  bool visit_box(const Point3& lo, const Point3& hi, F&& f) const {
    if (p_.empty()) return false;
    const long long i0 = cell(0, lo[0]), i1 = cell(0, hi[0]);
    const long long j0 = cell(1, lo[1]), j1 = cell(1, hi[1]);
    const long long k0 = cell(2, lo[2]), k1 = cell(2, hi[2]);
    for (long long k = k0; k <= k1; ++k)
      for (long long j = j0; j <= j1; ++j)
        for (long long i = i0; i <= i1; ++i) {
          const std::size_t c = index(i, j, k);
          for (std::size_t m = start_[c]; m < start_[c + 1]; ++m)
            if (f(items_[m])) return true;
        }
    return false;
  }

  // Calls f(k, distance) for each center k within R of q; stops and returns true as
  // soon as f returns true.
  template <class F>
  bool visit(const Point3& q, double R, F&& f) const {
    return visit_box({q[0] - R, q[1] - R, q[2] - R}, {q[0] + R, q[1] + R, q[2] + R},
                     [&](std::size_t k) {
                       const double d = dist(p_[k], q);
                       return d <= R && f(k, d);
                     });
  }

 private:
  // Cell of coordinate x along axis a, clamped to the grid (floor is monotone).
  long long cell(int a, double x) const {
    const double u = std::floor((x - lo_[a]) / side_);
    return static_cast<long long>(std::clamp(u, 0.0, static_cast<double>(dim_[a] - 1)));
  }
  std::size_t index(long long i, long long j, long long k) const {
    return static_cast<std::size_t>((k * dim_[1] + j) * dim_[0] + i);
  }

  const std::vector<Point3>& p_;
  Point3 lo_{};
  double side_ = 1;
  long long dim_[3] = {1, 1, 1};
  std::vector<std::size_t> start_, items_;
};

template <class T>
void keep(std::vector<T>& list, std::size_t& count, const T& entry) {
  if (list.size() < kKeep) list.push_back(entry);
  ++count;
}

// why() builds the message; it is only called for kept entries.
template <class Why>
void add_uncovered(SurfaceReport& rep, const Point3& p, std::size_t triangle, Why why) {
  if (rep.uncovered.size() < kKeep) rep.uncovered.push_back({p[0], p[1], p[2], triangle, why()});
  ++rep.uncovered_count;
}

bool finite3(const Point3& p) {
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

void validate(const SurfaceMeshInput& mesh, const std::vector<Point3>& centers,
              const std::vector<double>& radii, const SurfaceOptions& opt) {
  if (radii.size() != centers.size())
    throw std::invalid_argument("surface oracle: radii must have one radius per center");
  for (double r : radii)
    if (!(std::isfinite(r) && r > 0))
      throw std::invalid_argument("surface oracle: radii must be finite and > 0");
  if (!(opt.tol >= 0 && opt.tol < 1))
    throw std::invalid_argument("surface oracle: tol must be in [0, 1)");
  if (mesh.triangles.empty()) throw std::invalid_argument("surface oracle: the mesh has no triangle");
  for (const auto& v : mesh.vertices)
    if (!finite3(v)) throw std::invalid_argument("surface oracle: vertices must be finite");
  for (const auto& t : mesh.triangles)
    for (std::size_t v : t)
      if (v >= mesh.vertices.size())
        throw std::invalid_argument("surface oracle: triangle index out of range");
  for (const auto& p : centers)
    if (!finite3(p)) throw std::invalid_argument("surface oracle: centers must be finite");
  if (!opt.boundary_flags.empty() && opt.boundary_flags.size() != centers.size())
    throw std::invalid_argument("surface oracle: boundary_flags must have one flag per center");
}

// The parameter interval [t0, t1] of segment a + t(b - a) within distance R of q; false
// if none (or the segment has no length). From the foot of the perpendicular, so it is
// accurate when the sphere only grazes the line.
bool segment_interval(const Point3& a, const Point3& b, const Point3& q, double R, double& t0,
                      double& t1) {
  const Point3 d = sub(b, a);
  const double len2 = dot(d, d);
  if (!(len2 > 0)) return false;
  const double tf = dot(sub(q, a), d) / len2;
  const double h = dist(add(a, mul(d, tf)), q);
  if (h > R) return false;
  const double half = std::sqrt(std::max(0.0, (R - h) * (R + h))) / std::sqrt(len2);
  t0 = tf - half;
  t1 = tf + half;
  return true;
}

struct EdgeInfo {
  std::size_t v0, v1;  // in the owner's order
  std::size_t owner;   // the first triangle that uses it
  std::size_t uses;
};

std::string edge_name(const EdgeInfo& e) {
  return "edge (" + std::to_string(e.v0) + ", " + std::to_string(e.v1) + ")";
}

}  // namespace

double distance_to_surface(const SurfaceMeshInput& mesh, const Point3& p) {
  double best = kInf;
  for (const auto& t : mesh.triangles)
    best = std::min(best, triangle_distance(make_frame(mesh.vertices.at(t[0]), mesh.vertices.at(t[1]),
                                                       mesh.vertices.at(t[2])),
                                            p));
  return best;
}

SurfaceReport check_surface(const SurfaceMeshInput& mesh, const std::vector<Point3>& c,
                            const std::vector<double>& radii, const SurfaceOptions& opt) {
  validate(mesh, c, radii, opt);
  const double tol = opt.tol;
  const std::size_t n = c.size(), T = mesh.triangles.size();
  const auto& V = mesh.vertices;
  double r_max = 0, r_min = kInf;
  std::vector<double> reach(n);  // a point is covered if center k is within reach[k]
  for (std::size_t k = 0; k < n; ++k) {
    r_max = std::max(r_max, radii[k]);
    r_min = std::min(r_min, radii[k]);
    reach[k] = radii[k] * (1 + tol);
  }
  const double reach_max = r_max * (1 + tol);
  const auto& flags = opt.boundary_flags;

  SurfaceReport rep;
  rep.on_surface_checked = opt.on_surface;
  rep.conflicts_checked = opt.conflicts;
  rep.maximality_checked = opt.maximality;
  rep.boundary_checked = opt.boundary && !flags.empty();
  rep.n = n;
  rep.triangles = T;
  rep.r = r_max;
  rep.r_min = n ? r_min : 0;
  rep.tol = tol;
  for (char f : flags) rep.boundary_count += f != 0;

  // Edges by vertex index pairs; the owner (first triangle) handles each edge once,
  // and the first triangle using a vertex handles that corner once.
  std::vector<EdgeInfo> edges;
  std::vector<std::array<std::size_t, 3>> tri_edges(T);
  {
    std::vector<std::tuple<std::size_t, std::size_t, std::size_t, int>> all;
    all.reserve(3 * T);
    for (std::size_t t = 0; t < T; ++t)
      for (int k = 0; k < 3; ++k) {
        const std::size_t a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
        all.emplace_back(std::min(a, b), std::max(a, b), t, k);
      }
    std::sort(all.begin(), all.end());
    for (std::size_t m = 0; m < all.size(); ++m) {
      const auto& [a, b, t, k] = all[m];
      if (m == 0 || std::get<0>(all[m - 1]) != a || std::get<1>(all[m - 1]) != b)
        edges.push_back({mesh.triangles[t][k], mesh.triangles[t][(k + 1) % 3], t, 0});
      ++edges.back().uses;
      tri_edges[t][k] = edges.size() - 1;
    }
  }
  std::vector<std::size_t> vertex_owner(V.size(), kNone);
  for (std::size_t t = 0; t < T; ++t)
    for (std::size_t v : mesh.triangles[t])
      if (vertex_owner[v] == kNone) vertex_owner[v] = t;
  for (const auto& e : edges) rep.boundary_edges += e.uses == 1;

  const Grid3 grid(c, reach_max);
  auto covered = [&](const Point3& p) {
    return grid.visit(p, reach_max, [&](std::size_t k, double d) { return d <= reach[k]; });
  };
  // Is disk k (a copy of) disk g: center and radius within r_g*tol? (kNone: no disk.)
  auto same = [&](std::size_t k, std::size_t g) {
    if (g == kNone) return false;
    const double s = radii[g] * tol;
    return dist(c[k], c[g]) <= s && std::fabs(radii[k] - radii[g]) <= s;
  };
  // The largest margin reach_k - |p - c_k| over the disks k covering p, other than (the
  // copies of) g0 and g1; -infinity if there is none. Stops once it reaches `enough`.
  auto other_cover = [&](const Point3& p, std::size_t g0, std::size_t g1, double enough) {
    double best = -kInf;
    grid.visit(p, reach_max, [&](std::size_t k, double d) {
      if (d > reach[k] || same(k, g0) || same(k, g1)) return false;
      best = std::max(best, reach[k] - d);
      return best >= enough;
    });
    return best;
  };

  // (b) Conflicts: a sweep over the centers sorted by x.
  if (opt.conflicts) {
    std::vector<std::size_t> order(n);
    for (std::size_t k = 0; k < n; ++k) order[k] = k;
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return c[a][0] < c[b][0]; });
    for (std::size_t a = 0; a < n; ++a) {
      const std::size_t i = order[a];
      for (std::size_t b = a + 1; b < n; ++b) {
        const std::size_t j = order[b];
        if (c[j][0] - c[i][0] > radii[i] + r_max) break;
        const double d = dist(c[i], c[j]);
        if (d > radii[i] + radii[j]) continue;
        rep.min_distance = std::min(rep.min_distance, d);
        const double lo = std::min(radii[i], radii[j]), hi = std::max(radii[i], radii[j]);
        const Conflict k{std::min(i, j), std::max(i, j), d};
        if (d < lo * (1 - tol))
          keep(rep.conflicts, rep.conflict_count, k);
        else if (d < hi * (1 - tol))  // allowed: only the larger covers
          keep(rep.covered_centers, rep.covered_center_count, k);
      }
    }
  }

  // Per triangle: (a) distances of the nearby centers, (c) candidates, (d) probes.
  std::vector<double> dmin(n, kInf);  // distance to the surface, where computed
  std::vector<std::size_t> stamp(n, kNone), pos(n, 0);
  std::vector<std::size_t> L;  // the disks whose reach meets the triangle
  struct Planar {
    double x, y, rho;  // projected center, circle radius (0: no circle)
  };
  std::vector<Planar> planar;
  std::mt19937_64 rng(opt.seed);
  auto unit = [&rng] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };  // [0,1)

  if (opt.on_surface || opt.maximality)
    for (std::size_t t = 0; t < T; ++t) {
      const auto& tri = mesh.triangles[t];
      const Frame f = make_frame(V[tri[0]], V[tri[1]], V[tri[2]]);
      Point3 lo = f.p[0], hi = f.p[0];
      for (const auto& q : f.p)
        for (int k = 0; k < 3; ++k) {
          lo[k] = std::min(lo[k], q[k] - reach_max);
          hi[k] = std::max(hi[k], q[k] + reach_max);
        }
      L.clear();
      grid.visit_box(lo, hi, [&](std::size_t k) {
        const double d = triangle_distance(f, c[k]);
        dmin[k] = std::min(dmin[k], d);
        if (d <= reach[k]) L.push_back(k);
        return false;
      });
      if (!opt.maximality) continue;
      double r_local = kInf;  // smallest radius of the triangle's disks
      for (std::size_t m = 0; m < L.size(); ++m) {
        stamp[L[m]] = t;
        pos[L[m]] = m;
        r_local = std::min(r_local, radii[L[m]]);
      }
      auto step_probe = [&](const Point3& q, const std::function<std::string()>& why) {
        if (!covered(q)) add_uncovered(rep, q, t, why);
      };

      // (3) Corners (each vertex once), with step probes along the edges and the bisector.
      for (int k = 0; k < 3; ++k) {
        const Point3& P = f.p[k];
        const std::size_t vid = tri[k];
        const bool owner = vertex_owner[vid] == t;
        const Point3 e1 = sub(f.p[(k + 1) % 3], P), e2 = sub(f.p[(k + 2) % 3], P);
        const double l1 = norm(e1), l2 = norm(e2);
        const double base = std::min({r_local, l1 > 0 ? l1 : kInf, l2 > 0 ? l2 : kInf});
        rep.candidates += owner;
        const double margin = other_cover(P, kNone, kNone, kSteps[0] * base);
        if (margin == -kInf) {
          if (owner)
            add_uncovered(rep, P, t, [&] {
              return "triangle " + std::to_string(t) + ": corner " + std::to_string(k) +
                     " (vertex " + std::to_string(vid) + ") is covered by no disk";
            });
          continue;
        }
        if (margin >= kSteps[0] * base) continue;
        std::vector<Point3> dirs;
        if (l1 > 0) dirs.push_back(mul(e1, 1 / l1));
        if (l2 > 0) dirs.push_back(mul(e2, 1 / l2));
        if (!f.degenerate) {
          const Point3 w = add(mul(e1, 1 / l1), mul(e2, 1 / l2));
          if (norm(w) > 1e-9) dirs.push_back(mul(w, 1 / norm(w)));
        }
        for (const auto& d : dirs)
          for (double s : kSteps)
            step_probe(add(P, mul(d, s * base)), [&] {
              return "triangle " + std::to_string(t) + ": probe beside corner " +
                     std::to_string(k) + " (vertex " + std::to_string(vid) +
                     ") is covered by no disk";
            });
      }

      // (2) Circles with edges (each edge once, by its owner): in space, the sphere of
      // each disk met with the segment.
      for (int k = 0; k < 3; ++k) {
        const EdgeInfo& e = edges[tri_edges[t][k]];
        if (e.owner != t) continue;
        const Point3 &A = f.p[k], &B = f.p[(k + 1) % 3];
        const Point3 d = sub(B, A);
        const double len = norm(d);
        for (std::size_t a : L) {
          double t0, t1;
          if (!segment_interval(A, B, c[a], radii[a], t0, t1)) continue;
          for (const double s : {t0, t1}) {
            if (!(s > kEdgeMargin && s < 1 - kEdgeMargin)) continue;
            const Point3 P = add(A, mul(d, s));
            ++rep.candidates;
            const double step = kSteps[0] * radii[a];
            const double margin = other_cover(P, a, a, step);
            if (margin == -kInf) {
              add_uncovered(rep, P, t, [&] {
                return "triangle " + std::to_string(t) + ": circle of disk " + std::to_string(a) +
                       " crosses " + edge_name(e) + " at a point no other disk covers";
              });
            } else if (margin < step) {
              // Along the edge, away from disk a (both ways where the sphere is tangent).
              const double out = dot(sub(P, c[a]), d);
              for (const double sign : {1.0, -1.0}) {
                if (out * sign < 0) continue;
                for (double st : kSteps) {
                  const double q = s + sign * st * radii[a] / len;
                  if (q < 0 || q > 1) continue;
                  step_probe(add(A, mul(d, q)), [&] {
                    return "triangle " + std::to_string(t) + ": probe beside where circle of disk " +
                           std::to_string(a) + " crosses " + edge_name(e) + " is covered by no disk";
                  });
                }
              }
            }
            if (t1 == t0) break;
          }
        }
      }

      // (1) Circles with circles, in the triangle's plane.
      if (!f.degenerate) {
        planar.resize(L.size());
        for (std::size_t m = 0; m < L.size(); ++m) {
          const Point3 w = sub(c[L[m]], f.p[0]);
          const double h = std::fabs(dot(w, f.n)), r = radii[L[m]];
          planar[m] = {dot(w, f.u), dot(w, f.v), h < r ? std::sqrt((r - h) * (r + h)) : 0.0};
        }
        for (std::size_t ma = 0; ma < L.size(); ++ma) {
          const std::size_t a = L[ma];
          const Planar pa = planar[ma];
          if (!(pa.rho > 0)) continue;
          // Two circles meet only if the balls do: the grid finds the partners.
          grid.visit(c[a], radii[a] + r_max, [&](std::size_t b, double) {
            if (b <= a || stamp[b] != t) return false;
            const Planar pb = planar[pos[b]];
            if (!(pb.rho > 0)) return false;
            const double d = std::hypot(pb.x - pa.x, pb.y - pa.y);
            const double lo = std::min(pa.rho, pb.rho), hi = std::max(pa.rho, pb.rho);
            // Coincident circles have no corners; others meet unless one is inside the
            // other or they are apart.
            if ((d <= lo * tol && hi - lo <= lo * tol) || d < hi - lo || d > pa.rho + pb.rho)
              return false;
            const double ux = (pb.x - pa.x) / d, uy = (pb.y - pa.y) / d;
            const double along = (pa.rho * pa.rho - pb.rho * pb.rho + d * d) / (2 * d);
            const double h2 = (pa.rho + pb.rho - d) * (d + pa.rho - pb.rho) *
                              (d - pa.rho + pb.rho) * (d + pa.rho + pb.rho);
            const double h = std::sqrt(std::max(0.0, h2)) / (2 * d);
            const double step = kSteps[0] * lo;
            for (const double side : {-1.0, 1.0}) {
              const double px = pa.x + along * ux - side * h * uy;
              const double py = pa.y + along * uy + side * h * ux;
              const double in = inside_margin(f, px, py);
              if (in >= -step) {
                const bool candidate = in > kEdgeMargin * hi;
                rep.candidates += candidate;
                const Point3 P = lift(f, px, py);
                const double margin = other_cover(P, a, b, step);
                if (candidate && margin == -kInf) {
                  add_uncovered(rep, P, t, [&] {
                    return "triangle " + std::to_string(t) + ": circles of disks " +
                           std::to_string(a) + " and " + std::to_string(b) +
                           " cross at a point no third disk covers";
                  });
                } else if (margin < step) {
                  // Into the wedge outside both disks: along the sum of the outward
                  // normals, and just inside the wedge's two edges (the tangents).
                  const double nax = (px - pa.x) / pa.rho, nay = (py - pa.y) / pa.rho;
                  const double nbx = (px - pb.x) / pb.rho, nby = (py - pb.y) / pb.rho;
                  double wx = nax + nbx, wy = nay + nby;
                  const double wl = std::hypot(wx, wy);
                  std::vector<std::array<double, 2>> dirs;
                  if (wl > 1e-9) {
                    wx /= wl;
                    wy /= wl;
                    dirs.push_back({wx, wy});
                  } else {
                    wx = wy = 0;
                  }
                  auto tangent = [&](double nx, double ny, double ox, double oy) {
                    for (const double sg : {1.0, -1.0}) {
                      const double tx = -sg * ny, ty = sg * nx;  // perpendicular to n
                      if (tx * ox + ty * oy < 0) continue;     // not on the other's outside
                      const double dx = tx + 0.05 * wx, dy = ty + 0.05 * wy;
                      const double dl = std::hypot(dx, dy);
                      dirs.push_back({dx / dl, dy / dl});
                    }
                  };
                  tangent(nax, nay, nbx, nby);
                  tangent(nbx, nby, nax, nay);
                  for (const auto& dir : dirs)
                    for (double st : kSteps) {
                      const double qx = px + st * lo * dir[0], qy = py + st * lo * dir[1];
                      if (inside_margin(f, qx, qy) < 0) continue;
                      step_probe(lift(f, qx, qy), [&] {
                        return "triangle " + std::to_string(t) +
                               ": probe beside the crossing of the circles of disks " +
                               std::to_string(a) + " and " + std::to_string(b) +
                               " is covered by no disk";
                      });
                    }
                }
              }
              if (h == 0) break;
            }
            return false;
          });
        }
      }

      // (d) Probes: the centroid, the midpoints of the edges (once each) and random
      // points, uniform over the triangle.
      auto probe = [&](const Point3& q, const char* kind) {
        ++rep.probes;
        double nearest = kInf;
        bool hit = false;
        grid.visit(q, reach_max, [&](std::size_t k, double d) {
          nearest = std::min(nearest, d);
          hit = hit || d <= reach[k];
          return false;
        });
        if (nearest == kInf)  // nothing within reach: the nearest center the slow way
          for (const auto& p : c) nearest = std::min(nearest, dist(p, q));
        rep.max_probe_gap = std::max(rep.max_probe_gap, nearest);
        if (!hit)
          add_uncovered(rep, q, t, [&] {
            std::ostringstream why;
            why << "triangle " << t << ": " << kind << " probe, nearest center at distance "
                << nearest;
            return why.str();
          });
      };
      probe(mul(add(f.p[0], add(f.p[1], f.p[2])), 1.0 / 3), "centroid");
      for (int k = 0; k < 3; ++k)
        if (edges[tri_edges[t][k]].owner == t)
          probe(mul(add(f.p[k], f.p[(k + 1) % 3]), 0.5), "edge midpoint");
      const Point3 ab = sub(f.p[1], f.p[0]), ac = sub(f.p[2], f.p[0]);
      for (std::size_t m = 0; m < opt.probes_per_triangle; ++m) {
        double s = unit(), q = unit();
        if (s + q > 1) {
          s = 1 - s;
          q = 1 - q;
        }
        probe(add(f.p[0], add(mul(ab, s), mul(ac, q))), "random");
      }
    }

  // (a) On the surface. Every triangle within reach of c_i computed its distance, so
  // dmin[i] <= r_i*tol is exact; the distance reported is recomputed for kept entries.
  if (opt.on_surface)
    for (std::size_t i = 0; i < n; ++i)
      if (!(dmin[i] <= radii[i] * tol)) {
        const double d = rep.off_surface.size() < kKeep ? distance_to_surface(mesh, c[i]) : dmin[i];
        keep(rep.off_surface, rep.off_surface_count, {i, c[i][0], c[i][1], c[i][2], d});
      }

  // (e) Boundary: each boundary edge covered by the flagged disks alone (intervals of
  // each edge's parameter), and each flagged center on a boundary edge.
  if (rep.boundary_checked) {
    for (const EdgeInfo& e : edges) {
      if (e.uses != 1) continue;
      const Point3 &A = V[e.v0], &B = V[e.v1];
      Point3 lo, hi;
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(A[k], B[k]) - reach_max;
        hi[k] = std::max(A[k], B[k]) + reach_max;
      }
      std::vector<std::array<double, 2>> cover;
      grid.visit_box(lo, hi, [&](std::size_t i) {
        double t0, t1;
        if (flags[i] && segment_interval(A, B, c[i], reach[i], t0, t1) && t1 >= 0 && t0 <= 1)
          cover.push_back({t0, t1});
        return false;
      });
      std::sort(cover.begin(), cover.end());
      double done = 0;  // [0, done] is covered (t = 0 alone counts: a gap has length)
      auto gap = [&](double t0, double t1) {
        const Point3 m = add(A, mul(sub(B, A), (t0 + t1) / 2));
        keep(rep.boundary_gaps, rep.boundary_gap_count,
             {e.owner, e.v0, e.v1, t0, t1, m[0], m[1], m[2]});
      };
      if (!(dot(sub(B, A), sub(B, A)) > 0)) {  // a point: covered or not
        if (!grid.visit(A, reach_max, [&](std::size_t i, double d) { return flags[i] && d <= reach[i]; }))
          gap(0, 1);
        continue;
      }
      for (const auto& iv : cover) {
        if (iv[0] > done) gap(done, iv[0]);
        done = std::max(done, iv[1]);
        if (done >= 1) break;
      }
      if (done < 1) gap(done, 1);
    }
    for (std::size_t i = 0; i < n; ++i) {
      if (!flags[i]) continue;
      double d = kInf;
      for (const EdgeInfo& e : edges)
        if (e.uses == 1) d = std::min(d, segment_distance(V[e.v0], V[e.v1], c[i]));
      if (!(d <= radii[i] * tol))
        keep(rep.off_boundary, rep.off_boundary_count, {i, c[i][0], c[i][1], c[i][2], d});
    }
  }
  return rep;
}

SurfaceReport check_surface(const SurfaceMeshInput& mesh, const std::vector<Point3>& c, double r,
                            const SurfaceOptions& opt) {
  // One radius: validated here (also when there are no centers), echoed as given.
  if (!(std::isfinite(r) && r > 0)) throw std::invalid_argument("surface oracle: r must be > 0");
  SurfaceReport rep = check_surface(mesh, c, std::vector<double>(c.size(), r), opt);
  rep.r = rep.r_min = r;
  return rep;
}

bool SurfaceReport::ok() const {
  const bool any = on_surface_checked || conflicts_checked || maximality_checked || boundary_checked;
  return any && (!on_surface_checked || on_surface()) && (!conflicts_checked || conflict_free()) &&
         (!maximality_checked || maximal()) && (!boundary_checked || boundary_ok());
}

std::string SurfaceReport::summary() const {
  std::ostringstream s;
  s.precision(10);
  s << "surface oracle: N=" << n << " (" << boundary_count << " flagged), " << triangles
    << " triangles (" << boundary_edges << " boundary edges), ";
  if (r_min == r)
    s << "r=" << r;
  else
    s << "radii in [" << r_min << ", " << r << "]";
  s << ", tol=" << tol << ". ";
  auto list = [&](const char* title, bool checked, std::size_t count, std::size_t kept,
                  const std::function<void(std::size_t)>& item) {
    summary_list(s, title, checked, count, kept, item);
  };
  list("Centers off the surface", on_surface_checked, off_surface_count, off_surface.size(),
       [&](std::size_t k) {
         const auto& o = off_surface[k];
         s << "disk " << o.i << " at (" << o.x << ", " << o.y << ", " << o.z << "), " << o.distance
           << " from the surface";
       });
  list("Conflicts", conflicts_checked, conflict_count, conflicts.size(), [&](std::size_t k) {
    s << "disks " << conflicts[k].i << " and " << conflicts[k].j << " at distance "
      << conflicts[k].distance;
  });
  if (conflicts_checked && covered_center_count > 0)
    s << "Centers covered by a larger disk (allowed): " << covered_center_count << ". ";
  if (conflicts_checked) s << "Min center distance: " << min_distance << ". ";
  list("Uncovered", maximality_checked, uncovered_count, uncovered.size(), [&](std::size_t k) {
    const auto& u = uncovered[k];
    s << "(" << u.x << ", " << u.y << ", " << u.z << "): " << u.why;
  });
  if (maximality_checked)
    s << "Candidates: " << candidates << ", probes: " << probes
      << ", max probe gap: " << max_probe_gap << ". ";
  list("Flagged disks off the boundary", boundary_checked, off_boundary_count, off_boundary.size(),
       [&](std::size_t k) {
         const auto& o = off_boundary[k];
         s << "disk " << o.i << " at (" << o.x << ", " << o.y << ", " << o.z << "), " << o.distance
           << " away";
       });
  list("Boundary gaps", boundary_checked, boundary_gap_count, boundary_gaps.size(),
       [&](std::size_t k) {
         const auto& g = boundary_gaps[k];
         s << "edge (" << g.v0 << ", " << g.v1 << ") of triangle " << g.triangle << ", t in ["
           << g.t0 << ", " << g.t1 << "], around (" << g.x << ", " << g.y << ", " << g.z << ")";
       });
  return s.str();
}

}  // namespace oracle
