// SPDX-License-Identifier: GPL-3.0-or-later
// Voids on a surface (paper, section 7.2): per triangle, each disk's ball cuts the
// triangle's plane in a circle, and the uncovered part of the triangle is bounded by
// those circles and the triangle's edges. Its vertices - two circles meeting, a circle
// crossing an edge, a triangle corner - are the void points: the triangle is covered
// exactly when none of them is uncovered, so they both find voids and certify
// maximality, and each is exactly on the surface.
#pragma once

#include <array>
#include <vector>

#include "disktune/surface_packing.h"

namespace disktune {

/// An uncovered vertex of a void: where the circles of disks a and b meet (a circle
/// meeting a triangle edge: b == kNoDisk; a triangle corner: a == b == kNoDisk).
struct SurfaceVoidPoint {
  SurfacePoint at;
  DiskId a = kNoDisk, b = kNoDisk;
};

/// Appends the void points of triangle t; the disks in `ignore` count as absent.
void void_points_in_triangle(const SurfacePacking& packing, std::size_t t,
                             const std::vector<DiskId>& ignore, std::vector<SurfaceVoidPoint>& out);

/// Appends the void points of `cell`, a triangle inside triangle t of the domain (in its
/// plane): the vertices of the cell's uncovered part, so none exactly when one disk or
/// several together cover the whole cell.
void void_points_in_cell(const SurfacePacking& packing, std::size_t t, const std::array<Vec3, 3>& cell,
                         std::vector<SurfaceVoidPoint>& out);

/// Appends the void points within distance R of q (on every triangle near q).
void void_points_near(const SurfacePacking& packing, Vec3 q, double R,
                      const std::vector<DiskId>& ignore, std::vector<SurfaceVoidPoint>& out);

/// A ball that holds the points within `radius` of `center` (is_covered) on the patches
/// `patches`: a disk's reach where it counts.
struct HoldingBall {
  Vec3 center;
  double radius;
  PatchSet patches;
};

/// True when `ball` holds every void point within R of q (the disks in `ignore` lifted):
/// void_points_near's answer checked point by point, without listing them. Triangles and
/// circles well inside the ball are passed over, and it stops at the first void point
/// outside it, so a disk's small move is checked at a fraction of the cost.
/// `outside`, where given, gets the void point found outside the ball when the answer is
/// false.
bool void_points_near_within(const SurfacePacking& packing, Vec3 q, double R,
                             const std::vector<DiskId>& ignore, const HoldingBall& ball,
                             SurfaceVoidPoint* outside = nullptr);

/// True when no triangle has a void point: the surface is covered (up to the tolerance).
bool is_maximal(const SurfacePacking& packing);

/// The uncovered pieces of the fixed curves (domain().fixed_curves(): open boundary and
/// features), counting only fixed disks when `fixed_only`: for each curve c and each of
/// its edges e (from vertex e to e + 1), intervals [t0, t1] of the edge's parameter.
struct CurveGap {
  std::size_t curve, edge;
  double t0, t1;
};
std::vector<CurveGap> uncovered_curves(const SurfacePacking& packing, bool fixed_only);
/// The same for edge e of curve c alone, appended to `out`.
void uncovered_on_curve_edge(const SurfacePacking& packing, std::size_t c, std::size_t e, bool fixed_only,
                             std::vector<CurveGap>& out);

/// True when no two disks cover each other's centers (the prior-disk rule, pairwise: a
/// center may lie in a larger disk, which came later).
bool is_conflict_free(const SurfacePacking& packing);

/// Throws InvalidInput unless the packing is non-empty, conflict-free and maximal,
/// naming a conflicting pair or an uncovered point; `what` names the input.
void validate_packing(const SurfacePacking& packing, const std::string& what);

/// What makes the packing invalid, as a phrase naming the place (voids.h's words; a hole
/// is "the point (x, y, z) of triangle t"); empty when it is conflict-free and maximal.
/// The exact checks of validate_packing.
std::string packing_defect(const SurfacePacking& packing);

}  // namespace disktune
