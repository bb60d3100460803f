// SPDX-License-Identifier: GPL-3.0-or-later
// The geometry of disks on a triangulated surface (paper, section 7.2): a disk is the
// sphere of radius r around a center on the surface, and where two sphere boundaries
// meet on the surface is a void corner. Per triangle, a sphere cuts the triangle's plane
// in a circle; two such circles meet in at most two points, and those inside the
// triangle are the corners. Each triangle gets a 2D frame so the planar circle code
// (geometry.h) does the intersecting.
#pragma once

#include <optional>
#include <vector>

#include "disktune/geometry.h"
#include "disktune/vec3.h"

namespace disktune {

/// A triangle's plane with a 2D frame: origin at corner a, x along a->b, y completing a
/// right-handed frame with the triangle's unit normal (counterclockwise corners stay
/// counterclockwise in the frame).
class TrianglePlane {
 public:
  /// Throws InvalidInput for a degenerate triangle (no plane).
  TrianglePlane(Vec3 a, Vec3 b, Vec3 c);

  Vec3 normal() const { return normal_; }
  /// The corners in the frame: a is (0, 0), b on the x axis.
  Vec2 corner(int k) const { return corner_[k]; }
  /// The length of the edge from corner k to corner k + 1 (mod 3).
  double edge_length(int k) const { return edge_length_[k]; }
  /// Coordinates in the frame of the orthogonal projection of p.
  Vec2 to_plane(Vec3 p) const { return {dot(p - origin_, ex_), dot(p - origin_, ey_)}; }
  /// The point of the plane with these frame coordinates.
  Vec3 to_space(Vec2 q) const { return origin_ + ex_ * q.x + ey_ * q.y; }
  /// Signed distance of p from the plane (positive on the normal's side).
  double height(Vec3 p) const { return dot(p - origin_, normal_); }
  /// True when q lies in the closed triangle, up to `tol` (a length) outside its edges.
  bool contains(Vec2 q, double tol) const {
    // Inside the three edge lines (counterclockwise), each pushed out by tol.
    for (int k = 0; k < 3; ++k) {
      const Vec2 p = corner_[k], e = corner_[(k + 1) % 3] - p;
      if (cross(e, q - p) < -tol * edge_length_[k]) return false;
    }
    return true;
  }
  /// The circle in which the sphere S(center, r) cuts the plane (in the frame), or none
  /// when the sphere misses it. A sphere just touching the plane gives radius 0.
  std::optional<Circle> section(Vec3 center, double r) const;

 private:
  Vec3 origin_, ex_, ey_, normal_;
  Vec2 corner_[3];
  double edge_length_[3];  // of the edge from corner k to the next (contains, often asked)
};

/// The points of the triangle where the boundaries of spheres S(c1, r1) and S(c2, r2)
/// meet (0, 1 or 2): they lie in the triangle's plane, so on the surface, within
/// `tol` (a length) of the closed triangle. Appended to `out` in space.
void sphere_corners_in_triangle(const TrianglePlane& t, Vec3 c1, double r1, Vec3 c2, double r2,
                                double tol, std::vector<Vec3>& out);

/// The point of triangle abc closest to p.
Vec3 closest_point_on_triangle(Vec3 p, Vec3 a, Vec3 b, Vec3 c);

}  // namespace disktune
