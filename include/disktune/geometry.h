// SPDX-License-Identifier: GPL-3.0-or-later
// Small value types and robust circle primitives.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace disktune {

// Trivially constructible, so arrays of it cost nothing to declare in hot loops:
// `Vec2 v;` is uninitialised, `Vec2{}` is zero.
struct Vec2 {
  double x, y;
  Vec2() = default;
  constexpr Vec2(double x_, double y_) : x(x_), y(y_) {}
  Vec2 operator+(Vec2 o) const { return {x + o.x, y + o.y}; }
  Vec2 operator-(Vec2 o) const { return {x - o.x, y - o.y}; }
  Vec2 operator*(double s) const { return {x * s, y * s}; }
  Vec2& operator+=(Vec2 o) { x += o.x; y += o.y; return *this; }
  Vec2& operator-=(Vec2 o) { x -= o.x; y -= o.y; return *this; }
  bool operator==(Vec2 o) const { return x == o.x && y == o.y; }
};

inline double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
inline double squared_norm(Vec2 a) { return dot(a, a); }
inline double norm(Vec2 a) { return std::sqrt(dot(a, a)); }
inline double squared_distance(Vec2 a, Vec2 b) { return squared_norm(a - b); }
inline double distance(Vec2 a, Vec2 b) { return norm(a - b); }
inline Vec2 perp(Vec2 a) { return {-a.y, a.x}; }
/// z-component of the cross product: twice the signed area of the triangle (0, a, b).
inline double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }

/// The circumcenter of triangle abc (not degenerate), computed relative to a for
/// accuracy: a Voronoi vertex of the Delaunay triangulation.
inline Vec2 circumcenter(Vec2 a, Vec2 b, Vec2 c) {
  const Vec2 u = b - a, v = c - a;
  const double d = 2 * cross(u, v);
  const double u2 = squared_norm(u), v2 = squared_norm(v);
  return a + Vec2{(v.y * u2 - u.y * v2) / d, (u.x * v2 - v.x * u2) / d};
}

/// A circle, or a disk, by its center and radius.
struct Circle {
  Vec2 center;
  double radius;
};

/// The smallest circle enclosing the points (Welzl's algorithm, iterative form; the
/// points are taken in the given order, so shuffle them for the expected linear time).
/// Empty input gives radius -1.
Circle min_enclosing_circle(const std::vector<Vec2>& points);

/// Intersection points of two circles. `count` is 0 (disjoint, nested or concentric),
/// 1 (tangent, also when rounding makes near-tangent circles miss by a hair) or 2.
struct CircleIntersection {
  int count = 0;
  std::array<Vec2, 2> points;
};

/// True when circles whose centers are d2 apart (squared) and whose radii add up to
/// rsum are too far apart to meet, beyond the rounding slack intersect_circles allows
/// (it finds no point then): a cheap first test for searches over many pairs.
inline bool too_far_apart_to_meet(double d2, double rsum) {
  return d2 > rsum * rsum + 8.0 * 2.220446049250313e-16 * std::max(d2, rsum * rsum);  // a few ulps
}

/// Midpoint-plus-perpendicular form, valid for unequal radii. The squared half-chord is
/// clamped at zero when it is negative by no more than rounding, so near-tangent circles
/// give their touching point instead of nothing or NaN.
CircleIntersection intersect_circles(Vec2 c1, double r1, Vec2 c2, double r2);

/// False only when no intersection point of the two circles lies in the closed disk
/// D(center, R): a square-root-free test (the points are m +- h n, with m the chord's
/// midpoint, h its half-length and n its unit normal) that lets corner searches skip
/// most circle pairs before computing anything.
inline bool intersections_may_lie_in(Vec2 c1, double r1, Vec2 c2, double r2, Vec2 center, double R) {
  const Vec2 u = c2 - c1;
  const double d2 = squared_norm(u);
  if (d2 == 0.0) return false;
  const double a = 0.5 + (r1 * r1 - r2 * r2) / (2.0 * d2);
  const double h2 = r1 * r1 - a * a * d2;  // squared half-chord (negative: no points)
  const Vec2 mc = c1 + u * a - center;
  const double s = squared_norm(mc) + std::max(h2, 0.0) - R * R;
  if (s <= 0) return true;
  const double n_mc = dot(perp(u), mc);    // |u| (n . mc)
  return s * s * d2 <= 4 * std::max(h2, 0.0) * n_mc * n_mc * (1 + 1e-9);
}

}  // namespace disktune
