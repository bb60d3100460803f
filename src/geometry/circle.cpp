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
  if (d2 > rsum * rsum + slack || d2 < rdiff * rdiff - slack) return out;
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
