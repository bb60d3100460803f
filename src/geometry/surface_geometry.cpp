// SPDX-License-Identifier: GPL-3.0-or-later
#include "disktune/surface_geometry.h"

#include <cmath>
#include <sstream>

#include "disktune/errors.h"
#include "triangle_arrangement.h"

namespace disktune {

TrianglePlane::TrianglePlane(Vec3 a, Vec3 b, Vec3 c) : origin_(a) {
  const Vec3 ab = b - a, ac = c - a, n = cross(ab, ac);
  const double len = norm(ab), area2 = norm(n);
  if (!(len > 0 && area2 > 1e-14 * std::max(squared_norm(ab), squared_norm(ac)))) {
    std::ostringstream msg;
    msg << "degenerate triangle (" << a.x << ", " << a.y << ", " << a.z << "), (" << b.x << ", "
        << b.y << ", " << b.z << "), (" << c.x << ", " << c.y << ", " << c.z << "): it spans no plane";
    throw InvalidInput(msg.str());
  }
  ex_ = ab * (1 / len);
  normal_ = n * (1 / area2);
  ey_ = cross(normal_, ex_);
  corner_[0] = {0, 0};
  corner_[1] = {len, 0};
  corner_[2] = to_plane(c);
  for (int k = 0; k < 3; ++k) edge_length_[k] = norm(corner_[(k + 1) % 3] - corner_[k]);
}

std::optional<Circle> TrianglePlane::section(Vec3 center, double r) const {
  const double h = height(center);
  const double rho2 = r * r - h * h;
  // A sphere touching the plane within rounding gives its touching point.
  if (rho2 < -1e-12 * r * r) return std::nullopt;
  return Circle{to_plane(center), std::sqrt(std::max(rho2, 0.0))};
}

void sphere_corners_in_triangle(const TrianglePlane& t, Vec3 c1, double r1, Vec3 c2, double r2,
                                double tol, std::vector<Vec3>& out) {
  // The circle-circle vertices of the two balls' arrangement.
  const std::vector<Ball> balls{{c1, r1, 0}, {c2, r2, 1}};
  for_each_arrangement_vertex(t, balls, tol, [&](Vec3 p, DiskId a, DiskId b) {
    if (a != kNoTag && b != kNoTag) out.push_back(p);
  });
}

Vec3 closest_point_on_triangle(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
  // Region tests over the triangle's Voronoi regions (vertices, edges, face).
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const double denom = 1 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

}  // namespace disktune
