// SPDX-License-Identifier: GPL-3.0-or-later
// Thickness sizing on a surface (issue #15, item 3, the surface side of `auto:`): the
// radius shrinks where another part of the surface faces a vertex closer than r_max /
// kFeatureShare, as a thin wall's two sides or a ledge over a face do. A ball that
// reaches the facing part covers it in space, no disk is put there, and the restricted
// Delaunay mesh then joins the two parts (bow ties, edges in three triangles).
//
// The thickness at vertex v: the distance to the nearest triangle, not one of v's own,
// whose normal points against v's (cosine below -1/2) and whose closest point lies
// within 60 degrees of v's normal line (above or below). A crease turns the normal by
// less and lies beside v, not above it, so it does not count; a blade's two sides do.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "disktune/errors.h"
#include "disktune/sizing.h"
#include "disktune/surface_geometry.h"
#include "disktune/surface_sizing.h"
#include "surface_sizing_util.h"

namespace disktune {
namespace {

// Unit triangle normals (zero for a degenerate triangle).
std::vector<Vec3> triangle_normals(const SurfaceDomain& d) {
  std::vector<Vec3> out;
  for (const auto& tri : d.triangles()) {
    const Vec3 a = d.vertices()[tri[0]], n = cross(d.vertices()[tri[1]] - a, d.vertices()[tri[2]] - a);
    const double len = norm(n);
    out.push_back(len > 0 ? n * (1 / len) : n);
  }
  return out;
}

// Area-weighted vertex normals (unit; zero at a vertex of degenerate triangles only).
std::vector<Vec3> vertex_normals(const SurfaceDomain& d) {
  std::vector<Vec3> n(d.vertices().size(), Vec3{0, 0, 0});
  for (const auto& tri : d.triangles()) {
    const Vec3 a = d.vertices()[tri[0]], twice_area_normal = cross(d.vertices()[tri[1]] - a, d.vertices()[tri[2]] - a);
    for (const auto v : tri) n[v] = n[v] + twice_area_normal;
  }
  for (Vec3& v : n) {
    const double len = norm(v);
    if (len > 0) v = v * (1 / len);
  }
  return n;
}

// The triangles in cells at least `reach` wide, each in every cell its bounding box
// meets: every triangle within reach of p is in the 27 cells around p's.
class TriangleCells {
 public:
  TriangleCells(const SurfaceDomain& d, double reach) : cell_(reach) {
    double longest = 0;  // cells no smaller than an eighth of the longest edge bound the cells a triangle meets
    for (const auto& tri : d.triangles())
      for (int k = 0; k < 3; ++k) longest = std::max(longest, norm(d.vertices()[tri[k]] - d.vertices()[tri[(k + 1) % 3]]));
    cell_ = std::max(reach, longest / 8);
    for (std::uint32_t t = 0; t < d.triangles().size(); ++t) {
      const auto& tri = d.triangles()[t];
      std::array<std::int64_t, 3> lo{}, hi{};
      for (int axis = 0; axis < 3; ++axis) {
        double a = coordinate(d.vertices()[tri[0]], axis), b = a;
        for (const auto v : tri) a = std::min(a, coordinate(d.vertices()[v], axis)), b = std::max(b, coordinate(d.vertices()[v], axis));
        lo[axis] = index(a), hi[axis] = index(b);
      }
      for (std::int64_t i = lo[0]; i <= hi[0]; ++i)
        for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
          for (std::int64_t k = lo[2]; k <= hi[2]; ++k) cells_[{i, j, k}].push_back(t);
    }
  }
  /// f(t) for each triangle in the cells around p (a triangle in several cells: several times).
  template <class F>
  void around(Vec3 p, F&& f) const {
    const std::int64_t ci = index(p.x), cj = index(p.y), ck = index(p.z);
    for (std::int64_t i = ci - 1; i <= ci + 1; ++i)
      for (std::int64_t j = cj - 1; j <= cj + 1; ++j)
        for (std::int64_t k = ck - 1; k <= ck + 1; ++k) {
          const auto it = cells_.find({i, j, k});
          if (it != cells_.end())
            for (const std::uint32_t t : it->second) f(t);
        }
  }

 private:
  static double coordinate(Vec3 p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }
  std::int64_t index(double v) const { return static_cast<std::int64_t>(std::floor(v / cell_)); }
  double cell_;
  std::map<std::array<std::int64_t, 3>, std::vector<std::uint32_t>> cells_;
};

}  // namespace

SurfaceSizing thickness_sizing(const SurfaceDomain& domain, double r_max, double gradation) {
  using detail::number_text;
  using detail::short_text;
  if (!std::isfinite(r_max) || !(r_max > 0) || !std::isfinite(gradation) || !(gradation > 0) || !(gradation < 0.5)) {
    throw InvalidInput("thickness sizing with r_max = " + number_text(r_max) + ", gradation " + number_text(gradation) +
                       " is not valid: it needs r_max > 0 and 0 < gradation < 0.5 (e.g. auto:0.02 or auto:0.02,0.3)");
  }
  const double reach = r_max / kFeatureShare;  // no part farther than this lowers r
  const TriangleCells cells(domain, reach);
  const std::vector<Vec3> normal = vertex_normals(domain), facing = triangle_normals(domain);
  const auto& triangles = domain.triangles();
  const auto& points = domain.vertices();
  std::vector<double> radii(points.size(), r_max);
  std::size_t thinnest = 0;
  for (std::size_t v = 0; v < radii.size(); ++v) {
    const Vec3 p = points[v];
    double thickness = reach;
    cells.around(p, [&](std::uint32_t t) {
      const auto& tri = triangles[t];
      if (tri[0] == v || tri[1] == v || tri[2] == v || !(dot(facing[t], normal[v]) < -0.5)) return;
      const Vec3 q = closest_point_on_triangle(p, points[tri[0]], points[tri[1]], points[tri[2]]);
      const double d = norm(q - p);
      if (d < thickness && std::abs(dot(q - p, normal[v])) >= 0.5 * d) thickness = d;
    });
    radii[v] = std::min(r_max, kFeatureShare * thickness);
    if (radii[v] < radii[thinnest]) thinnest = v;
  }
  const double smallest = radii[thinnest];
  if (!(smallest > 0)) {
    throw InvalidInput("thickness sizing: at " + detail::vertex_text(domain, thinnest) +
                       " another part of the surface touches it (thickness 0); the surface intersects itself there");
  }
  limit_gradation(domain, radii, gradation);
  std::string description = "thickness sizing min(" + number_text(r_max) + ", " + number_text(kFeatureShare) +
                            " thickness graded at " + number_text(gradation) + "), smallest " + short_text(smallest);
  if (smallest < r_max) {
    const Vec3 at = domain.vertices()[thinnest];
    description += " near (" + short_text(at.x) + ", " + short_text(at.y) + ", " + short_text(at.z) + ")";
  }
  return SurfaceSizing::per_vertex(domain, std::move(radii), std::move(description));
}

}  // namespace disktune
