// SPDX-License-Identifier: GPL-3.0-or-later
// Sphere corners on a triangle, against an independent solution in space: the points of
// the plane on both spheres are where the plane meets the radical plane of the two
// spheres (a line), intersected with one sphere.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "disktune/errors.h"
#include "disktune/surface_geometry.h"

namespace disktune {
namespace {

// Independent: the points p with n.(p - a) = 0, |p - c1| = r1 and |p - c2| = r2.
std::vector<Vec3> corners_in_space(Vec3 a, Vec3 n, Vec3 c1, double r1, Vec3 c2, double r2) {
  // Radical plane: 2 (c2 - c1).p = r1^2 - r2^2 + |c2|^2 - |c1|^2.
  const Vec3 m = (c2 - c1) * 2;
  const double k = r1 * r1 - r2 * r2 + dot(c2, c2) - dot(c1, c1);
  const Vec3 dir = cross(n, m);
  const double dd = dot(dir, dir);
  if (dd < 1e-24) return {};
  // A point on both planes: p0 = (k1 (m x dir) + k2 (dir x n)) / |dir|^2 with k1 = n.a, k2 = k.
  const Vec3 p0 = (cross(m, dir) * dot(n, a) + cross(dir, n) * k) * (1 / dd);
  const Vec3 u = dir * (1 / std::sqrt(dd));
  const Vec3 w = p0 - c1;
  const double b = dot(u, w), c = dot(w, w) - r1 * r1, disc = b * b - c;
  if (disc < 0) return {};
  return {p0 + u * (-b - std::sqrt(disc)), p0 + u * (-b + std::sqrt(disc))};
}

// Independent inside test by barycentric coordinates (all three >= -eps).
bool in_triangle(Vec3 p, Vec3 a, Vec3 b, Vec3 c, double eps) {
  const Vec3 n = cross(b - a, c - a);
  const double area = dot(n, n);
  const double u = dot(cross(c - b, p - b), n) / area, v = dot(cross(a - c, p - c), n) / area,
               w = dot(cross(b - a, p - a), n) / area;
  return u >= -eps && v >= -eps && w >= -eps;
}

TEST(SurfaceGeometry, SectionOfASphereByAFlatTriangle) {
  const TrianglePlane t({0, 0, 0}, {2, 0, 0}, {0, 2, 0});
  const auto s = t.section({0.5, 0.5, 0.3}, 0.5);
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->radius, 0.4, 1e-15);
  EXPECT_NEAR(s->center.x, 0.5, 1e-15);
  EXPECT_NEAR(s->center.y, 0.5, 1e-15);
  EXPECT_FALSE(t.section({0.5, 0.5, 0.6}, 0.5));  // misses the plane
  const auto touch = t.section({0.5, 0.5, 0.5}, 0.5);
  ASSERT_TRUE(touch);
  EXPECT_EQ(touch->radius, 0);
  EXPECT_NEAR(t.normal().z, 1, 1e-15);
}

TEST(SurfaceGeometry, CornersMatchTheSolutionInSpaceOnRandomTriangles) {
  std::mt19937_64 gen(7);
  std::uniform_real_distribution<double> u(-1, 1);
  int compared = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec3 a{u(gen), u(gen), u(gen)}, b{u(gen), u(gen), u(gen)}, c{u(gen), u(gen), u(gen)};
    const Vec3 n0 = cross(b - a, c - a);
    if (norm(n0) < 0.1) continue;  // skip slivers: the test is about corners, not planes
    const TrianglePlane t(a, b, c);
    // Centers near the triangle (on it, as on a surface, or a little off it).
    auto near = [&] {
      const double s = std::abs(u(gen)), q = std::abs(u(gen)) * (1 - s);
      return a + (b - a) * s + (c - a) * q + t.normal() * (0.1 * u(gen));
    };
    const Vec3 c1 = near(), c2 = near();
    const double r1 = 0.2 + 0.5 * std::abs(u(gen)), r2 = 0.2 + 0.5 * std::abs(u(gen));
    std::vector<Vec3> got;
    sphere_corners_in_triangle(t, c1, r1, c2, r2, 0, got);
    std::vector<Vec3> want;
    for (const Vec3 p : corners_in_space(a, t.normal(), c1, r1, c2, r2)) {
      if (in_triangle(p, a, b, c, 1e-12)) want.push_back(p);
    }
    // Points within rounding of an edge may fall either way: compare the clear cases.
    bool borderline = false;
    for (const Vec3 p : corners_in_space(a, t.normal(), c1, r1, c2, r2)) {
      borderline |= in_triangle(p, a, b, c, 1e-9) != in_triangle(p, a, b, c, -1e-9);
    }
    if (borderline) continue;
    ASSERT_EQ(got.size(), want.size()) << "trial " << trial;
    for (const Vec3 p : got) {
      EXPECT_NEAR(norm(p - c1), r1, 1e-12);
      EXPECT_NEAR(norm(p - c2), r2, 1e-12);
      EXPECT_NEAR(dot(p - a, t.normal()), 0, 1e-12);
      double nearest = 1e300;
      for (const Vec3 q : want) nearest = std::min(nearest, norm(p - q));
      EXPECT_LT(nearest, 1e-9);
    }
    compared += !want.empty();
  }
  EXPECT_GT(compared, 300);  // the test saw enough corners to mean something
}

TEST(SurfaceGeometry, FrameKeepsCornersCounterclockwise) {
  const TrianglePlane t({1, 0, 0}, {0, 1, 0}, {0, 0, 1});
  EXPECT_GT(cross(t.corner(1) - t.corner(0), t.corner(2) - t.corner(0)), 0);
  EXPECT_TRUE(t.contains((t.corner(0) + t.corner(1) + t.corner(2)) * (1.0 / 3), 0));
  EXPECT_FALSE(t.contains(t.corner(0) - (t.corner(1) - t.corner(0)) * 0.01, 0));
  const Vec3 p{0.2, 0.3, 0.5};
  const Vec3 back = t.to_space(t.to_plane(p));
  EXPECT_NEAR(norm(back - p), 0, 1e-15);  // p lies in the plane x + y + z = 1
}

TEST(SurfaceGeometry, DegenerateTriangleHasNoPlane) {
  EXPECT_THROW(TrianglePlane({0, 0, 0}, {1, 1, 1}, {2, 2, 2}), InvalidInput);
}

}  // namespace
}  // namespace disktune
