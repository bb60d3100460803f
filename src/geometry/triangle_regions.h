// SPDX-License-Identifier: GPL-3.0-or-later
// Balls that together cover a triangle, for work done region by region (internal): the
// exact void search and the index that finds the triangles near a point.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "disktune/surface_geometry.h"

namespace disktune {

// Calls f(q, R) for balls of radius R, centred in the plane, that together cover the
// triangle: the circumscribed balls of squares of side `side` in the plane's frame, a
// band of rows at a time and only the squares meeting the triangle. Their number grows
// with the triangle's area over side^2 plus its perimeter over side, so a long needle
// costs its length, not its length squared.
template <class F>
void for_each_region(const TrianglePlane& plane, double side, F&& f) {
  const Vec2 v[3] = {plane.corner(0), plane.corner(1), plane.corner(2)};
  const double xmin = std::min({v[0].x, v[1].x, v[2].x});
  const double ymin = std::min({v[0].y, v[1].y, v[2].y}), ymax = std::max({v[0].y, v[1].y, v[2].y});
  const double R = side * std::sqrt(0.5) * (1 + 1e-9);
  const long rows = std::max(1L, static_cast<long>(std::ceil((ymax - ymin) / side)));
  for (long j = 0; j < rows; ++j) {
    const double y0 = ymin + j * side, y1 = y0 + side;
    // The triangle's x-extent within the band: its corners there and its edges' crossings.
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (int k = 0; k < 3; ++k) {
      const Vec2 p = v[k], q = v[(k + 1) % 3];
      if (p.y >= y0 && p.y <= y1) lo = std::min(lo, p.x), hi = std::max(hi, p.x);
      for (const double y : {y0, y1})
        if ((p.y - y) * (q.y - y) < 0) {
          const double x = p.x + (q.x - p.x) * (y - p.y) / (q.y - p.y);
          lo = std::min(lo, x), hi = std::max(hi, x);
        }
    }
    if (!(lo <= hi)) continue;
    const long first = static_cast<long>(std::floor((lo - xmin) / side));
    const long last = static_cast<long>(std::floor((hi - xmin) / side));
    for (long i = first; i <= last; ++i) f(plane.to_space({xmin + (i + 0.5) * side, y0 + 0.5 * side}), R);
  }
}

}  // namespace disktune
