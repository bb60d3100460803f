// SPDX-License-Identifier: GPL-3.0-or-later
// A disk's restricted Voronoi cell on the surface (internal): the part of the surface
// nearer to its center than to any other disk that counts there.
#pragma once

#include <cstdint>
#include <vector>

#include "disktune/surface_packing.h"

namespace disktune::detail {

/// Whether the cell of disk p, on the triangles of p's patches that come within its
/// ball (radius r, with a hair of slack), lies inside the ball of `radius` around x.
/// Every point that only p covers lies in that cell, since a disk covering it would be
/// nearer to it than p's center; so where this holds with radius r, p moved to x still
/// covers all of them. Only the disks within twice p's ball clip the cell, which is
/// exact inside the ball and larger beyond it, so the answer errs only toward false
/// (as where a cell needs more than 32 corners); rounding moves the corners by a few
/// ulps of r, which the caller's radius must leave room for.
/// `near`, where given, holds every triangle within p's ball (more do no harm).
bool cell_inside(const SurfacePacking& packing, DiskId p, Vec3 x, double radius,
                 const std::vector<std::uint32_t>* near = nullptr);

/// The triangles near each disk's center, found again only after the disk moved more than
/// `slack` from where they were last found (a Verlet list: the surface stays put, and
/// relaxation moves each disk a little each sweep). One disk's list is read and renewed
/// only by whoever moves that disk.
class TrianglesNearDisks {
 public:
  /// Lists of the triangles within `reach` of each disk of ids below `id_bound`.
  TrianglesNearDisks(DiskId id_bound, double reach, double slack);
  /// Every triangle within `reach` of disk p's center (and some a little farther).
  const std::vector<std::uint32_t>& of(const SurfacePacking& packing, DiskId p);

 private:
  double reach_, slack_;
  std::vector<std::vector<std::uint32_t>> near_;
  std::vector<Vec3> found_at_;  // infinitely far: none found yet
};

}  // namespace disktune::detail
