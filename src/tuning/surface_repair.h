// SPDX-License-Identifier: GPL-3.0-or-later
// The surface's primitives for the tuning operations (internal; space.h gathers them
// with the planar ones of void_repair.h): void points in place of planar corners.
#pragma once

#include <optional>
#include <vector>

#include "../voids/surface_cell.h"
#include "disktune/random.h"
#include "disktune/surface_voids.h"
#include "undo_log.h"

namespace disktune::detail {

/// The region a lifted disk's void lies in: its ball, with a hair of slack.
inline double void_reach(double r) { return r * (1 + 1e-6); }

/// The void points within R of q, with the disks in `ignore` lifted.
std::vector<SurfaceVoidPoint> voids_near(const SurfacePacking& packing, Vec3 q, double R,
                                         const std::vector<DiskId>& ignore = {});

/// True when no void point lies within the ball of radius r around c (with void_reach's
/// slack): the exact check of a region after the disks covering it changed.
bool void_free_near(const SurfacePacking& packing, Vec3 c, double r);

/// The void point a new disk goes to: largest weighted diameter (void_repair.h).
SurfacePoint void_point_choice(const SurfacePacking& packing, const std::vector<SurfaceVoidPoint>& voids, Rng& rng);

/// True when a disk at c (radius radius_at(c)) contains every void point, so it covers
/// the void they bound (per triangle a void lies in the convex hull of its points).
/// With a sizing each must lie inside by 1e-7 r (see void_repair.h's covers_all).
bool covers_all(const SurfacePacking& packing, const SurfacePoint& c, const std::vector<SurfaceVoidPoint>& voids);

/// What a disk at c holds in covers_all's sense: its radius (less 1e-7 r with a
/// sizing) on its patches.
HoldingBall holding_ball(const SurfacePacking& packing, const SurfacePoint& c);

/// What one check of a disk's move learns that the next check of the same move can use
/// (its halvings: the same disk, place and reach, nothing moved in between); forget()
/// before each new move.
struct LiftedDisk {
  DiskCell cell;                            // its cell, clipped as far as asked so far
  std::optional<SurfaceVoidPoint> outside;  // a void point a scan found outside a ball
  void forget() {
    cell.forget();
    outside.reset();
  }
};

/// Whether disk p (centered at c), moved to x, still holds its own void: first whether
/// its cell lies in its ball at x (cell_inside, surface_cell.h), else covers_all(packing,
/// x, voids_near(packing, c, R, {p})) at a fraction of its cost (void_points_near_within).
/// The first can say yes where the second, which asks x to cover every void near c, would
/// not: where the packing already had a void there that p did not cover.
/// `near_p`, where given, holds every triangle within p's ball (TrianglesNearDisks).
/// `lifted`, where given, carries from one call to the next of one move p's cell as far
/// as it was clipped (DiskCell), and a void point a scan found outside an earlier x's
/// ball, which answers no at once where x's ball does not hold it either (the scan would
/// find it again: it is a void point of lifting p wherever p goes), and which a scan that
/// answers no sets.
bool covers_lifted_voids(const SurfacePacking& packing, Vec3 c, double R, DiskId p,
                         const SurfacePoint& x, const std::vector<std::uint32_t>* near_p = nullptr,
                         LiftedDisk* lifted = nullptr);

/// The widest two points one disk can hold (covers_all's balls are at most max_radius,
/// with is_covered's tolerance): its diameter, and a hair.
double hold_span(const SurfacePacking& packing);

/// Whether a point of `a` and one of `b` lie farther apart than hold_span: then no one
/// disk covers both sets (covering_positions finds none for their union).
bool wider_than_one_disk(const SurfacePacking& packing, const std::vector<SurfaceVoidPoint>& a,
                         const std::vector<SurfaceVoidPoint>& b);

/// Positions within R of `near` where a disk covers every void point (covers_all) and
/// conflicts with no disk but `self` and `passable`: the vertices of the arrangement of
/// the balls around the void points and the other disks' spheres, cut with the triangles
/// there, so each is exactly on the surface. With `toward`, also the points of those
/// circles nearest it (where the nearest feasible position may lie).
std::vector<SurfacePoint> covering_positions(const SurfacePacking& packing, const std::vector<SurfaceVoidPoint>& voids,
                                             Vec3 near, double R, DiskId self, DiskId passable = kNoDisk,
                                             const Vec3* toward = nullptr);

/// One of the covering_positions within R of `near` that no disk holds, chosen at
/// random, into `z`; false when there is none.
bool covering_point(const SurfacePacking& packing, const std::vector<SurfaceVoidPoint>& voids, Vec3 near, double R,
                    Rng& rng, SurfacePoint& z);

/// The disks that can move (not fixed, not frozen) whose disk overlaps one of radius r at `point`,
/// except `self` (and, given a `self`, those on no patch of its), in random order.
std::vector<DiskId> mobile_neighbors(const SurfacePacking& packing, Vec3 point, double r, DiskId self, Rng& rng);

/// Fills the voids within R of q by injecting at void_point_choice until none is left.
/// Returns the number injected, or max_added + 1 as soon as more would be needed.
std::size_t repair_void(SurfaceUndoLog& log, const SurfacePacking& packing, Vec3 q, double R, Rng& rng,
                        std::size_t max_added);

/// Where disk p alone covers the void points within r of c (p's own disk ignored), into
/// `z`: the covering position nearest to the farthest void point; false when there is none.
bool sole_cover_point(const SurfacePacking& packing, const std::vector<SurfaceVoidPoint>& voids, DiskId p, Vec3 c,
                      double r, SurfacePoint& z);

/// Moves q as close to `to` as it can while it still covers its own void and conflicts
/// with no disk but `passable`'s; nothing when no covering position is closer.
void pull_toward(SurfaceUndoLog& log, SurfacePacking& packing, DiskId q, Vec3 to, DiskId passable);

}  // namespace disktune::detail
