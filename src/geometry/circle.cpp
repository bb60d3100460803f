// SPDX-License-Identifier: GPL-3.0-or-later
#include "disktune/geometry.h"

#include <algorithm>

namespace disktune {

CircleIntersection intersect_circles(Vec2 c1, double r1, Vec2 c2, double r2) {
  CircleIntersection out;
  const Vec2 u = c2 - c1;
  const double d2 = squared_norm(u);
  if (d2 == 0.0) return out;  // concentric: no isolated points
  const double rsum = r1 + r2;
  const double rdiff = r1 - r2;
  // Rounding slack on d^2 comparisons: a few ulps of the largest term.
  const double slack = 8.0 * 2.220446049250313e-16 * std::max(d2, rsum * rsum);
  if (too_far_apart_to_meet(d2, rsum) || d2 < rdiff * rdiff - slack) return out;
  // a = signed distance from c1 to the chord midpoint along u, as a fraction of |u|.
  const double a = 0.5 + (r1 * r1 - r2 * r2) / (2.0 * d2);
  const Vec2 m = c1 + u * a;
  const double h2 = r1 * r1 / d2 - a * a;  // (half-chord / |u|)^2
  if (h2 <= 0.0) {
    out.count = 1;
    out.points[0] = m;
    return out;
  }
  const Vec2 off = perp(u) * std::sqrt(h2);
  out.count = 2;
  out.points[0] = m + off;
  out.points[1] = m - off;
  return out;
}

}  // namespace disktune

namespace disktune {
namespace {

Circle circle_from(Vec2 a, Vec2 b) { return {(a + b) * 0.5, distance(a, b) * 0.5}; }

Circle circle_from(Vec2 a, Vec2 b, Vec2 c) {
  if (std::abs(cross(b - a, c - a)) < 1e-300) {  // collinear: the widest pair spans it
    Circle best = circle_from(a, b);
    for (const Circle& k : {circle_from(a, c), circle_from(b, c)}) {
      if (k.radius > best.radius) best = k;
    }
    return best;
  }
  const Vec2 o = circumcenter(a, b, c);
  return {o, distance(o, a)};
}

bool holds(const Circle& c, Vec2 p) { return distance(c.center, p) <= c.radius * (1 + 1e-12) + 1e-300; }

}  // namespace

Circle min_enclosing_circle(const std::vector<Vec2>& pts) {
  if (pts.empty()) return {{0, 0}, -1};
  Circle c{pts[0], 0};
  for (std::size_t i = 1; i < pts.size(); ++i) {
    if (holds(c, pts[i])) continue;
    c = {pts[i], 0};  // pts[i] is on the boundary of the circle of pts[0..i]
    for (std::size_t j = 0; j < i; ++j) {
      if (holds(c, pts[j])) continue;
      c = circle_from(pts[i], pts[j]);  // both on the boundary
      for (std::size_t k = 0; k < j; ++k) {
        if (!holds(c, pts[k])) c = circle_from(pts[i], pts[j], pts[k]);
      }
    }
  }
  return c;
}

}  // namespace disktune
