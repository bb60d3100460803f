// SPDX-License-Identifier: GPL-3.0-or-later
// The space a packing lives in, as the tuning operations see it (internal). An
// operation is written once, as a template over the packing kind P, and asks
// Space<P> for the few things that differ between the plane (the periodic box or a
// planar domain, Packing) and a triangulated surface (SurfacePacking):
//   Point            where a disk can be put (Vec2; on a surface a SurfacePoint, which
//                    carries its triangle, so every point made lies on the surface)
//   Location         a position in space (Vec2, Vec3): distances are measured there
//   VoidPoint        a point bounding a void (a planar Corner, a SurfaceVoidPoint)
//   Near             a neighbour: id, `image` (its center as seen from the query point:
//                    on the torus the periodic image in range) and radius
//   location(x), point_of(v)   a Point's location, a VoidPoint's Point
//   void_reach(r)    the region a lifted disk of radius r leaves uncovered
//   voids_in(P, c, R, ignore)  the void points within R of c, `ignore` lifted
//   void_choice(P, voids, rng) where a new disk goes: largest weighted diameter
//   covers_all(P, x, voids)    a disk at x holds every void point
//   covers_lifted_voids(P, c, R, p, x[, near_p[, lifted]])  covers_all(P, x, voids_in(P, c, R,
//                    {p})): disk p moved from c to x still holds its own void (on a
//                    surface without listing the void points, much faster; near_p: the
//                    triangles near p, where known)
//   mobile_neighbors(P, c, r, self, rng)  movable disks overlapping a disk (c, r)
//   repair_void(log, P, c, R, rng, max)   fill the voids within R of c
//   void_free_near(P, c, r)    no void within D(c, r): the exact check after a change
//   covering_point(P, voids, near, R, rng, z)  a random place within R of `near` where
//                    one disk covers every void point and meets no disk
//   pair_too_wide(P, own_p, q)  no one disk can cover what lifting p (its void points
//                    own_p) and neighbour q leaves, or false where that is not known
//   sole_cover_point(P, voids, p, c, r, z)  where disk p alone covers the voids around
//                    it (p's own disk ignored), or false
//   pull_toward(log, P, q, to, passable)  moves neighbour q as close to `to` as it can
//                    while it covers its own void and meets no disk but `passable`'s
//   for_each_near(P, c, R, f), any_near(P, c, R, pred)  neighbours (Near, with d2)
//   inside(P, x)     x lies in the domain (a surface's points always do)
//   near_of(P, p)    disk p as a Near (its own center as the image)
//   along_surface(P, p, v)  v without its part along the surface normal at disk p
//   one_radius(P)    every disk has the same radius (no sizing)
//   project(P, p, y, x)  the point x of the domain nearest y, a step from disk p, or false
//   stable_order(ids)  sorts ids where the grid's visiting order is not reproducible
// and, for crystal growth (lattice spacing s):
//   for_each_site(P, a, ia, b, ib, s, f)  the points at distance s from centers a and b
//   point_at(P, c, s, rng, x)  a random point at distance s from center c, or false
//   point_at_turn(P, c, s, turn, x)  the point at that turn (in [0, 1)) around c
//   Sites            the lattice sites waiting to be settled, each place once at a time
// The primitives themselves are in void_repair.h / surface_repair.h.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "../geometry/triangle_arrangement.h"
#include "disktune/packing.h"
#include "disktune/surface_packing.h"
#include "disktune/surface_voids.h"
#include "disktune/voids.h"
#include "own_voids.h"
#include "surface_repair.h"
#include "undo_log.h"
#include "void_repair.h"

namespace disktune::detail {

template <class P>
struct Space;

template <>
struct Space<Packing> {
  using Point = Vec2;
  using Location = Vec2;
  using VoidPoint = Corner;
  using Near = Neighbor;

  static Location location(Point x) { return x; }
  static Point point_of(const VoidPoint& v) { return v.point; }
  static double void_reach(double r) { return r; }
  static std::vector<VoidPoint> voids_in(const Packing& packing, Location c, double R,
                                         const std::vector<DiskId>& ignore) {
    std::vector<Corner> out;
    corners_in_region(packing, c, R, ignore, out);
    return out;
  }
  static Point void_choice(const Packing& packing, const std::vector<VoidPoint>& voids, Rng& rng) {
    return void_corner(packing, voids, rng);
  }
  static bool covers_all(const Packing& packing, Point x, const std::vector<VoidPoint>& voids) {
    return detail::covers_all(packing, x, voids);
  }
  static bool covers_lifted_voids(
      const Packing& packing, Location c, double R, DiskId p, Point x,
      const std::vector<std::uint32_t>* /*near_p: a surface's*/ = nullptr) {
    return detail::covers_all(packing, x, voids_in(packing, c, R, {p}));
  }
  // Planar radii follow the position (radius_at), so `r` is implied by c.
  static std::vector<Near> mobile_neighbors(const Packing& packing, Location c, double /*r*/, DiskId self,
                                            Rng& rng) {
    return detail::mobile_neighbors(packing, c, self, rng);
  }
  static std::size_t repair_void(UndoLog& log, const Packing& packing, Location c, double R, Rng& rng,
                                 std::size_t max_added) {
    return detail::repair_void(log, packing, c, R, rng, max_added);
  }
  static bool void_free_near(const Packing& packing, Location c, double r) {
    return detail::void_free_near(packing, c, r);
  }
  // The darts go where every corner is in reach, so `near` and R are not needed.
  static bool covering_point(const Packing& packing, const std::vector<VoidPoint>& voids, Location /*near*/,
                             double /*R*/, Rng& rng, Point& z) {
    return detail::covering_point(packing, voids, rng, z);
  }
  // The darts need no such shortcut (see the surface's).
  static bool pair_too_wide(const Packing& /*packing*/, const std::vector<VoidPoint>& /*own_p*/,
                            const Near& /*q*/) {
    return false;
  }
  static bool sole_cover_point(const Packing& packing, const std::vector<VoidPoint>& voids, DiskId p, Location /*c*/,
                               double /*r*/, Point& z) {
    return detail::sole_cover_point(packing, voids, p, z);
  }
  static void pull_toward(UndoLog& log, Packing& packing, const Near& q, Location to, DiskId passable) {
    detail::pull_toward(log, packing, q, to, passable);
  }
  template <class F>
  static void for_each_near(const Packing& packing, Location c, double R, F&& f) {
    packing.for_each_near(c, R, std::forward<F>(f));
  }
  template <class Pred>
  static bool any_near(const Packing& packing, Location c, double R, Pred&& pred) {
    return packing.any_near(c, R, std::forward<Pred>(pred));
  }
  static bool inside(const Packing& packing, Point x) { return packing.inside(x); }
  static Near near_of(const Packing& packing, DiskId p) { return {p, packing.center(p), 0.0, packing.radius(p)}; }
  static Location along_surface(const Packing& /*packing*/, DiskId /*p*/, Location v) { return v; }
  static bool one_radius(const Packing& packing) { return !packing.sizing(); }
  static bool project(const Packing& packing, DiskId /*p*/, Location y, Point& x) {
    x = y;
    return packing.inside(y);
  }
  static void stable_order(std::vector<DiskId>& /*ids*/) {}  // the flat grid's order is fixed

  template <class F>
  static void for_each_site(const Packing& /*packing*/, Location a, DiskId, Location b, DiskId, double s, F&& f) {
    const CircleIntersection x = intersect_circles(a, s, b, s);
    for (int k = 0; k < x.count; ++k) f(x.points[k]);
  }
  static bool point_at(const Packing& packing, DiskId c, double s, Rng& rng, Point& x) {
    return point_at_turn(packing, c, s, uniform01(rng), x);
  }
  static bool point_at_turn(const Packing& packing, DiskId c, double s, double turn, Point& x) {
    const double angle = 2 * 3.14159265358979323846 * turn;
    x = packing.center(c) + Vec2{std::cos(angle), std::sin(angle)} * s;
    return true;
  }
  /// Sites in a grid over the frame (wrapped on the torus), each place once at a time.
  class Sites {
   public:
    Sites(const Packing& packing, double r) : grid_(packing.frame(), r), r_(r) {}
    bool empty() const { return live_.empty(); }
    void add(Point a) {
      a = grid_.frame().wrap(a);
      if (grid_.any_near(a, 1e-7 * r_, [](const Neighbor&) { return true; })) return;
      const auto id = static_cast<DiskId>(points_.size());
      points_.push_back(a);
      grid_.insert(id, a, 0.0);
      live_.push_back(id);
    }
    Point take_random(Rng& rng) {
      const std::size_t i = uniform_index(rng, live_.size());
      const DiskId id = live_[i];
      live_[i] = live_.back();
      live_.pop_back();
      grid_.remove(id, points_[id]);
      return points_[id];
    }

   private:
    SpatialGrid grid_;
    double r_;
    std::vector<Vec2> points_;
    std::vector<DiskId> live_;
  };
};

/// A neighbour on a surface, named as the planar Neighbor is (no periodic images here).
struct SurfaceNeighbor {
  DiskId id;
  Vec3 image;
  double d2;  // squared distance to the query point
  double radius;
};

template <>
struct Space<SurfacePacking> {
  using Point = SurfacePoint;
  using Location = Vec3;
  using VoidPoint = SurfaceVoidPoint;
  using Near = SurfaceNeighbor;

  static Location location(const Point& x) { return x.p; }
  static Point point_of(const VoidPoint& v) { return v.at; }
  static double void_reach(double r) { return detail::void_reach(r); }
  static std::vector<VoidPoint> voids_in(const SurfacePacking& packing, Location c, double R,
                                         const std::vector<DiskId>& ignore) {
    // A disk's own void (own_voids.h: kept while nothing near it changes).
    if (ignore.size() == 1 && packing.alive(ignore[0]) && packing.center(ignore[0]) == c &&
        R == void_reach(packing.radius(ignore[0])))
      return own_voids(packing, ignore[0]);
    return voids_near(packing, c, R, ignore);
  }
  static Point void_choice(const SurfacePacking& packing, const std::vector<VoidPoint>& voids, Rng& rng) {
    return void_point_choice(packing, voids, rng);
  }
  static bool covers_all(const SurfacePacking& packing, const Point& x, const std::vector<VoidPoint>& voids) {
    return detail::covers_all(packing, x, voids);
  }
  static bool covers_lifted_voids(const SurfacePacking& packing, Location c, double R, DiskId p,
                                  const Point& x,
                                  const std::vector<std::uint32_t>* near_p = nullptr,
                                  detail::LiftedDisk* lifted = nullptr) {
    return detail::covers_lifted_voids(packing, c, R, p, x, near_p, lifted);
  }
  static std::vector<Near> mobile_neighbors(const SurfacePacking& packing, Location c, double r, DiskId self,
                                            Rng& rng) {
    std::vector<Near> out;
    for (const DiskId id : detail::mobile_neighbors(packing, c, r, self, rng))
      out.push_back({id, packing.center(id), squared_norm(packing.center(id) - c), packing.radius(id)});
    return out;
  }
  static std::size_t repair_void(SurfaceUndoLog& log, const SurfacePacking& packing, Location c, double R,
                                 Rng& rng, std::size_t max_added) {
    return detail::repair_void(log, packing, c, R, rng, max_added);
  }
  static bool void_free_near(const SurfacePacking& packing, Location c, double r) {
    return detail::void_free_near(packing, c, r);
  }
  static bool covering_point(const SurfacePacking& packing, const std::vector<VoidPoint>& voids, Location near,
                             double R, Rng& rng, Point& z) {
    return detail::covering_point(packing, voids, near, R, rng, z);
  }
  // Lifting p and q leaves at least what each leaves alone; one scan of q's own void
  // (against two of the pair's) tells most pairs apart (wider_than_one_disk). Before
  // it, q's center: where no other disk covers it, it lies in q's own void, so in the
  // hull of that void's points on its triangle, and a point of p's void farther from it
  // than one disk holds (by a margin for rounding) is farther from one of those points.
  static bool pair_too_wide(const SurfacePacking& packing, const std::vector<VoidPoint>& own_p,
                            const Near& q) {
    const double span2 = hold_span(packing) * hold_span(packing) * (1 + 1e-9);
    bool far = false;
    for (const VoidPoint& v : own_p) far = far || squared_norm(v.at.p - q.image) > span2;
    if (far && !packing.covered(packing.point(q.id), q.id)) return true;
    return detail::wider_than_one_disk(packing, own_p,
                                       voids_in(packing, q.image, void_reach(q.radius), {q.id}));
  }
  static bool sole_cover_point(const SurfacePacking& packing, const std::vector<VoidPoint>& voids, DiskId p,
                               Location c, double r, Point& z) {
    return detail::sole_cover_point(packing, voids, p, c, r, z);
  }
  static void pull_toward(SurfaceUndoLog& log, SurfacePacking& packing, const Near& q, Location to,
                          DiskId passable) {
    detail::pull_toward(log, packing, q.id, to, passable);
  }
  template <class F>
  static void for_each_near(const SurfacePacking& packing, Location c, double R, F&& f) {
    packing.for_each_near(c, R, [&](DiskId j) {
      f(Near{j, packing.center(j), squared_norm(packing.center(j) - c), packing.radius(j)});
    });
  }
  template <class Pred>
  static bool any_near(const SurfacePacking& packing, Location c, double R, Pred&& pred) {
    return packing.any_near(c, R, [&](DiskId j) {
      return pred(Near{j, packing.center(j), squared_norm(packing.center(j) - c), packing.radius(j)});
    });
  }
  static bool inside(const SurfacePacking& /*packing*/, const Point& /*x*/) { return true; }  // made on it
  static Near near_of(const SurfacePacking& packing, DiskId p) {
    return {p, packing.center(p), 0.0, packing.radius(p)};
  }
  static Location along_surface(const SurfacePacking& packing, DiskId p, Location v) {
    const Vec3 n = packing.index().plane(packing.point(p).triangle).normal();
    return v - n * dot(v, n);
  }
  static bool one_radius(const SurfacePacking& packing) { return packing.sizing().is_constant(); }
  // Nearest among the triangles facing the same way as p's (within 60 degrees), so that
  // a step never lands on a sheet across a thin part.
  static bool project(const SurfacePacking& packing, DiskId p, Location y, Point& x) {
    const SurfaceIndex& index = packing.index();
    const std::uint32_t own = packing.point(p).triangle;
    // A step along p's own triangle that stays on it (the common case) lands where it
    // points, up to rounding, and no other triangle is nearer.
    const Vec3 on_own = index.closest_point(own, y);
    const double hair = 1e-12 * packing.radius(p);
    if (squared_norm(on_own - y) <= hair * hair) {
      x = Point{on_own, own};
      return true;
    }
    const Vec3 n = index.plane(own).normal();
    thread_local std::vector<std::uint32_t> tris;
    index.triangles_near(y, norm(y - packing.center(p)) + 1e-9 * packing.radius(p), tris);
    double best = 1e300;
    for (const std::uint32_t t : tris) {
      if (dot(index.plane(t).normal(), n) < 0.5) continue;
      const Vec3 q = index.closest_point(t, y);
      const double d2 = squared_norm(q - y);
      if (d2 < best) best = d2, x = Point{q, t};
    }
    return best < 1e300;
  }
  // The hashed grid visits cells in an order a rehash changes.
  static void stable_order(std::vector<DiskId>& ids) { std::sort(ids.begin(), ids.end()); }

  // Sites: where the two balls' circles meet a triangle near a.
  template <class F>
  static void for_each_site(const SurfacePacking& packing, Location a, DiskId ia, Location b, DiskId ib, double s,
                            F&& f) {
    const std::vector<Ball> pair{{a, s, ia}, {b, s, ib}};
    std::vector<std::uint32_t> tris;
    packing.index().triangles_near(a, s, tris);
    for (const std::uint32_t t : tris) {
      for_each_arrangement_vertex(packing.index().plane(t), pair, kRelTol * packing.max_radius(),
                                  [&](Vec3 x, DiskId u, DiskId v) {
                                    if (u != kNoDisk && v != kNoDisk) f(Point{x, t});
                                  });
    }
  }
  // A random one of the points where the sphere S(c, s) crosses a triangle edge.
  static bool point_at(const SurfacePacking& packing, DiskId c, double s, Rng& rng, Point& x) {
    const std::vector<Point> ring = edge_points_at(packing, c, s);
    if (ring.empty()) return false;
    x = ring[uniform_index(rng, ring.size())];
    return true;
  }
  // A surface has no common direction: the turn (in [0, 1)) picks one of those points.
  static bool point_at_turn(const SurfacePacking& packing, DiskId c, double s, double turn,
                            Point& x) {
    const std::vector<Point> ring = edge_points_at(packing, c, s);
    if (ring.empty()) return false;
    x = ring[std::min(ring.size() - 1,
                      static_cast<std::size_t>(turn * static_cast<double>(ring.size())))];
    return true;
  }
  static std::vector<Point> edge_points_at(const SurfacePacking& packing, DiskId c, double s) {
    std::vector<Point> ring;
    std::vector<std::uint32_t> tris;
    packing.index().triangles_near(packing.center(c), s, tris);
    const std::vector<Ball> ball{{packing.center(c), s, c}};
    for (const std::uint32_t t : tris) {
      for_each_arrangement_vertex(packing.index().plane(t), ball, kRelTol * packing.max_radius(),
                                  [&](Vec3 y, DiskId u, DiskId v) {
                                    if (u == c && v == kNoDisk) ring.push_back({y, t});
                                  });
    }
    return ring;
  }
  /// Sites in a hashed grid, each place once at a time.
  class Sites {
   public:
    Sites(const SurfacePacking& /*packing*/, double r) : grid_(r), r_(r) {}
    bool empty() const { return live_.empty(); }
    void add(const Point& a) {
      if (grid_.any_in_box(a.p, 1e-7 * r_, [&](std::uint32_t k) {
            return squared_norm(points_[k].p - a.p) <= 1e-14 * r_ * r_;
          }))
        return;
      const auto id = static_cast<std::uint32_t>(points_.size());
      points_.push_back(a);
      grid_.insert(id, a.p);
      live_.push_back(id);
    }
    Point take_random(Rng& rng) {
      const std::size_t i = uniform_index(rng, live_.size());
      const std::uint32_t id = live_[i];
      live_[i] = live_.back();
      live_.pop_back();
      grid_.remove(id, points_[id].p);
      return points_[id];
    }

   private:
    SpaceGrid grid_;
    double r_;
    std::vector<Point> points_;
    std::vector<std::uint32_t> live_;
  };
};

/// True when no void lies within reach of a disk the log placed (inserted or moved)
/// since `mark`. Checking what disks left is not always enough: where several circles
/// nearly meet, a crossing a placed disk's circle makes can be judged open by the
/// corners' strict cover rule (a disk whose circle only passes through a point covers
/// just the side toward its center), far from what any disk left. Seen on the sphere
/// at 10^5 disks: an attractor's pull put a circle through a point where three others
/// met within 1e-9 r, and the final check failed.
template <class P>
bool placed_void_free(const BasicUndoLog<P>& log, const P& packing, std::size_t mark = 0) {
  bool free = true;
  log.for_each_placed(mark, [&](DiskId id) {
    free = free && Space<P>::void_free_near(packing, packing.center(id), packing.radius(id));
  });
  return free;
}

/// True when a void point lies on the rim of a disk of radius r at x (not inside by
/// 1e-6 r): only then can a disk moved to x to cover them make such a crossing.
template <class P, class VoidPoint>
bool voids_on_rim(const typename Space<P>::Point& x, double r,
                  const std::vector<VoidPoint>& voids) {
  using S = Space<P>;
  const double inside = r * (1 - 1e-6);
  for (const VoidPoint& v : voids)
    if (squared_norm(S::location(S::point_of(v)) - S::location(x)) > inside * inside) return true;
  return false;
}

}  // namespace disktune::detail
