// SPDX-License-Identifier: GPL-3.0-or-later
// The vertices of the arrangement that balls cut into one triangle: the triangle's
// corners, each ball's circle crossing an edge, and two circles meeting inside. Void
// points (uncovered vertices) and feasible positions for a moved disk (vertices inside
// every ball) are both filtered from this one list.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "disktune/surface_geometry.h"

namespace disktune {

/// A ball's tag is the id of the disk it stands for. The packing layer (spatial_grid.h)
/// declares the same alias; a second declaration must name the same type, so the two
/// cannot drift apart where both are seen.
using DiskId = std::uint32_t;
/// The tag of no ball (the value of kNoDisk, which lives a layer up).
inline constexpr DiskId kNoTag = static_cast<DiskId>(-1);

struct Ball {
  Vec3 center;
  double radius;
  DiskId tag;  // the disk it stands for (kNoTag: none)
};

/// emit(point in space, tag a, tag b) for each arrangement vertex in the closed
/// triangle (within `tol`): corners with (kNoTag, kNoTag), circle-edge crossings with
/// (a, kNoTag), circle-circle crossings with (a, b). Balls missing the plane are skipped.
/// With `toward`, also the points of the triangle, of each edge and of each circle
/// nearest to it (tags kNoTag): where a region's point nearest `toward` may lie
/// besides its vertices.
template <class Emit>
void for_each_arrangement_vertex(const TrianglePlane& t, const std::vector<Ball>& balls, double tol, Emit&& emit,
                                 const Vec3* toward = nullptr) {
  for (int k = 0; k < 3; ++k) emit(t.to_space(t.corner(k)), kNoTag, kNoTag);
  const Vec2 goal = toward ? t.to_plane(*toward) : Vec2{};
  if (toward) {
    if (t.contains(goal, tol)) emit(t.to_space(goal), kNoTag, kNoTag);
    for (int k = 0; k < 3; ++k) {
      const Vec2 p = t.corner(k), e = t.corner((k + 1) % 3) - p;
      const double s = std::clamp(dot(goal - p, e) / dot(e, e), 0.0, 1.0);
      emit(t.to_space(p + e * s), kNoTag, kNoTag);
    }
  }
  thread_local std::vector<Circle> circles;
  thread_local std::vector<std::size_t> owner;
  circles.clear();
  owner.clear();
  // Circles that miss the triangle's bounding box add no vertex.
  Vec2 lo = t.corner(0), hi = t.corner(0);
  for (int k = 1; k < 3; ++k) {
    lo = {std::min(lo.x, t.corner(k).x), std::min(lo.y, t.corner(k).y)};
    hi = {std::max(hi.x, t.corner(k).x), std::max(hi.y, t.corner(k).y)};
  }
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const auto c = t.section(balls[i].center, balls[i].radius);
    if (!c) continue;
    const double dx = std::max({lo.x - c->center.x, 0.0, c->center.x - hi.x});
    const double dy = std::max({lo.y - c->center.y, 0.0, c->center.y - hi.y});
    if (dx * dx + dy * dy > c->radius * c->radius * (1 + 1e-9) + tol * tol) continue;
    circles.push_back(*c);
    owner.push_back(i);
  }
  for (std::size_t i = 0; i < circles.size(); ++i) {
    const Circle& c = circles[i];
    if (toward) {
      const Vec2 d = goal - c.center;
      const double len = norm(d);
      if (len > 0) {
        const Vec2 q = c.center + d * (c.radius / len);
        if (t.contains(q, tol)) emit(t.to_space(q), kNoTag, kNoTag);
      }
    }
    // Edge crossings: |p + s e - center| = radius for s in [0, 1].
    for (int k = 0; k < 3; ++k) {
      const Vec2 p = t.corner(k), e = t.corner((k + 1) % 3) - p, f = p - c.center;
      const double a = dot(e, e), b = dot(f, e), cc = dot(f, f) - c.radius * c.radius;
      const double disc = b * b - a * cc;
      if (disc < 0) continue;
      const double root = std::sqrt(disc);
      for (const double s : {(-b - root) / a, (-b + root) / a}) {
        if (s >= 0 && s <= 1) emit(t.to_space(p + e * s), balls[owner[i]].tag, kNoTag);
        if (root == 0) break;
      }
    }
    for (std::size_t j = i + 1; j < circles.size(); ++j) {
      const Circle& d = circles[j];
      const double sum = c.radius + d.radius;
      if (squared_distance(c.center, d.center) > sum * sum) continue;
      const CircleIntersection x = intersect_circles(c.center, c.radius, d.center, d.radius);
      for (int m = 0; m < x.count; ++m) {
        if (t.contains(x.points[m], tol)) emit(t.to_space(x.points[m]), balls[owner[i]].tag, balls[owner[j]].tag);
      }
    }
  }
}

}  // namespace disktune
