// SPDX-License-Identifier: GPL-3.0-or-later
// cell_inside: each triangle within the disk's ball is clipped by the bisector planes of
// the disks within twice that ball (no farther disk is nearer to a point of the ball),
// Sutherland-Hodgman style; a cell part is convex, so it lies in a ball when its
// corners do.
#include "surface_cell.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "disktune/tolerance.h"

namespace disktune::detail {
namespace {

// A convex polygon of at most 32 corners, on the stack: clipping a triangle by k planes
// makes at most 3 + k, and a cell needing more gives up (the answer is then false).
struct Polygon {
  std::array<Vec3, 32> corner;
  std::size_t size = 0;
};

// Keeps the part of `poly` where dot(y - c, u) <= k (the side of the bisector plane of
// c and c + u, with k = |u|^2 / 2, nearer to c); false when it would need too many corners.
bool clip(const Polygon& poly, Vec3 c, Vec3 u, double k, Polygon& out) {
  out.size = 0;
  const std::size_t n = poly.size;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 a = poly.corner[i], b = poly.corner[i + 1 == n ? 0 : i + 1];
    const double fa = dot(a - c, u) - k, fb = dot(b - c, u) - k;
    if (out.size + 2 > out.corner.size()) return false;
    if (fa <= 0) out.corner[out.size++] = a;
    if ((fa < 0 && fb > 0) || (fa > 0 && fb < 0))
      out.corner[out.size++] = a + (b - a) * (fa / (fa - fb));
  }
  return true;
}

double farthest2(const Polygon& poly, Vec3 from) {
  double far2 = 0;
  for (std::size_t i = 0; i < poly.size; ++i)
    far2 = std::max(far2, squared_norm(poly.corner[i] - from));
  return far2;
}

}  // namespace

bool cell_inside(const SurfacePacking& packing, DiskId p, Vec3 x, double radius,
                 const std::vector<std::uint32_t>* near_p) {
  const SurfaceIndex& index = packing.index();
  const Vec3 c = packing.center(p);
  // The ball where p can be the only cover (its radius with the coverage tolerance).
  const double R = packing.radius(p) * (1 + 1e-6);
  thread_local std::vector<std::uint32_t> tris;
  thread_local std::vector<std::pair<double, DiskId>> near;  // squared distance, disk
  Polygon buffers[2];
  if (!near_p) index.triangles_near(c, R, tris), near_p = &tris;
  near.clear();
  packing.for_each_near(c, 2 * R + packing.max_radius() * kRelTol, [&](DiskId q) {
    if (q != p) near.emplace_back(squared_norm(packing.center(q) - c), q);
  });
  // Nearest first: they cut the most, and once the cell lies within half a disk's
  // distance of c, neither that disk's bisector nor a farther one's reaches it.
  std::sort(near.begin(), near.end());
  const auto& corners = packing.domain().triangles();
  const auto& vertices = packing.domain().vertices();
  for (const std::uint32_t t : *near_p) {
    const PatchSet patch = index.patch_of_triangle(t);
    if (!packing.share_patch(packing.patches(p), patch)) continue;  // p covers nothing there
    const double h = index.plane(t).height(c);  // the plane's distance: a cheap first test
    if (h * h > R * R || squared_norm(index.closest_point(t, c) - c) > R * R) continue;
    Polygon *poly = &buffers[0], *clipped = &buffers[1];
    poly->size = 3;
    for (int k = 0; k < 3; ++k) poly->corner[k] = vertices[corners[t][k]];
    // Clipped by the nearest bisectors first, the part soon lies in the ball at x, and
    // further cuts only shrink it.
    const double inside2 = radius * radius;
    double far2 = farthest2(*poly, c), far_x2 = farthest2(*poly, x);
    for (const auto& [d2, q] : near) {
      if (far_x2 <= inside2 || far2 < 0.25 * d2 * (1 - 1e-9)) break;
      if (!packing.share_patch(packing.patches(q), patch)) continue;  // it covers nothing there
      if (!(d2 > 0)) continue;  // no bisector: the cell stays larger, never smaller
      if (!clip(*poly, c, packing.center(q) - c, 0.5 * d2, *clipped)) return false;
      std::swap(poly, clipped);
      far2 = farthest2(*poly, c);
      far_x2 = farthest2(*poly, x);
    }
    if (far_x2 > inside2) return false;
  }
  return true;
}

TrianglesNearDisks::TrianglesNearDisks(DiskId id_bound, double reach, double slack)
    : reach_(reach),
      slack_(slack),
      near_(id_bound),
      found_at_(id_bound, Vec3{std::numeric_limits<double>::infinity(), 0, 0}) {}

const std::vector<std::uint32_t>& TrianglesNearDisks::of(const SurfacePacking& packing, DiskId p) {
  const Vec3 c = packing.center(p);
  if (!(squared_norm(c - found_at_[p]) <= slack_ * slack_)) {
    packing.index().triangles_near(c, reach_ + slack_, near_[p]);
    found_at_[p] = c;
  }
  return near_[p];
}

}  // namespace disktune::detail
