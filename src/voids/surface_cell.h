// SPDX-License-Identifier: GPL-3.0-or-later
// A disk's restricted Voronoi cell on the surface (internal): the part of the surface
// nearer to its center than to any other disk that counts there.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
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

/// cell_inside asked again and again of one disk p at one place while nothing moves (a
/// move's halvings): the cell's parts are clipped only as far as the questions so far
/// needed and kept, and each question goes on from there. A part shrinks as it is
/// clipped, and one inside a ball stays inside it, so each answer is the one a fresh
/// cell_inside gives (but where rounding puts a corner of a part on the ball's rim).
class DiskCell {
 public:
  /// The cell of disk p where it is now (`near` as for cell_inside, kept by reference).
  void of(const SurfacePacking& packing, DiskId p,
          const std::vector<std::uint32_t>* near = nullptr);
  /// cell_inside(packing, p, x, radius, near) for the packing, p and near of `of`.
  bool inside(Vec3 x, double radius);
  /// Whether this is the cell of disk p at c (as `of` left it, and not forgotten since).
  bool is_of(DiskId p, Vec3 c) const { return packing_ && p_ == p && c_ == c; }
  /// The cell of no disk (the lists kept for the next).
  void forget() { packing_ = nullptr; }

  /// A part's most corners: clipping a triangle by k planes makes at most 3 + k, and a
  /// part needing more is left larger than the cell (the answer is then false).
  static constexpr std::size_t kCorners = 32;

 private:
  // A triangle within p's ball, clipped by the bisectors of near_[0, next), its corners
  // at corners_[kCorners * (its index), + size).
  struct Part {
    std::size_t size = 0, next = 0;
    double far2 = 0;  // its farthest corner's squared distance from p's center
    PatchSet patch = 0;
    bool final = false;  // no bisector left cuts it (or it would need too many corners)
  };
  const SurfacePacking* packing_ = nullptr;
  DiskId p_ = 0;
  Vec3 c_{};
  double R_ = 0;  // p's radius with the coverage tolerance: where it can be the only cover
  const std::vector<std::uint32_t>* listed_ = nullptr;
  std::vector<std::uint32_t> found_;             // the triangles near p, where not given
  std::size_t scanned_ = 0;                      // listed triangles looked at so far
  std::vector<std::pair<double, DiskId>> near_;  // squared distance, disk; nearest first
  std::vector<Part> parts_;                      // the listed triangles within the ball
  std::vector<Vec3> corners_;                    // never shrunk: reused from disk to disk
  std::array<Vec3, kCorners> scratch_;           // a part being clipped
};

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
