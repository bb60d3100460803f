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
//   mobile_neighbors(P, c, r, self, rng)  movable disks overlapping a disk (c, r)
//   repair_void(log, P, c, R, rng, max)   fill the voids within R of c
//   void_free_near(P, c, r)    no void within D(c, r): the exact check after a change
//   covering_point(P, voids, near, R, rng, z)  a random place within R of `near` where
//                    one disk covers every void point and meets no disk
// The primitives themselves are in void_repair.h / surface_repair.h.
#pragma once

#include <cstddef>
#include <vector>

#include "disktune/packing.h"
#include "disktune/surface_packing.h"
#include "disktune/surface_voids.h"
#include "disktune/voids.h"
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
};

/// A neighbour on a surface, named as the planar Neighbor is (no periodic images here).
struct SurfaceNeighbor {
  DiskId id;
  Vec3 image;
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
    return voids_near(packing, c, R, ignore);
  }
  static Point void_choice(const SurfacePacking& packing, const std::vector<VoidPoint>& voids, Rng& rng) {
    return void_point_choice(packing, voids, rng);
  }
  static bool covers_all(const SurfacePacking& packing, const Point& x, const std::vector<VoidPoint>& voids) {
    return detail::covers_all(packing, x, voids);
  }
  static std::vector<Near> mobile_neighbors(const SurfacePacking& packing, Location c, double r, DiskId self,
                                            Rng& rng) {
    std::vector<Near> out;
    for (const DiskId id : detail::mobile_neighbors(packing, c, r, self, rng))
      out.push_back({id, packing.center(id), packing.radius(id)});
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
};

}  // namespace disktune::detail
