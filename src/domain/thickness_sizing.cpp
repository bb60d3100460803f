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
// At a vertex of a fixed curve the radius also stays below the distance to another part
// of the curves (curve_clearance.cpp: two creases of a chamfer, close holes), so that
// both keep disks of their own.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "disktune/errors.h"
#include "disktune/sizing.h"
#include "disktune/surface_geometry.h"
#include "disktune/surface_sizing.h"
#include "box_tree.h"
#include "curve_clearance.h"
#include "surface_sizing_util.h"
#include "thickness_limits.h"

namespace disktune {
namespace {

constexpr double kNone = std::numeric_limits<double>::infinity();  // a triangle that does not count

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

}  // namespace

namespace detail {

std::vector<double> thickness_limits(const SurfaceDomain& domain, double reach) {
  std::vector<detail::BoxTree::Box> boxes;
  for (const auto& tri : domain.triangles())
    boxes.push_back(detail::BoxTree::box_of(std::array<Vec3, 3>{domain.vertices()[tri[0]], domain.vertices()[tri[1]], domain.vertices()[tri[2]]}));
  const detail::BoxTree tree(boxes);
  const std::vector<Vec3> normal = vertex_normals(domain), facing = triangle_normals(domain);
  const auto& triangles = domain.triangles();
  const auto& points = domain.vertices();
  std::vector<double> limits = detail::curve_clearance(domain, reach);
  for (std::size_t v = 0; v < limits.size(); ++v) {
    const Vec3 p = points[v];
    const double thickness = tree.nearest(p, reach, [&](std::uint32_t t) {
      const auto& tri = triangles[t];
      if (tri[0] == v || tri[1] == v || tri[2] == v || !(dot(facing[t], normal[v]) < -0.5)) return kNone;
      const Vec3 q = closest_point_on_triangle(p, points[tri[0]], points[tri[1]], points[tri[2]]);
      const double d = norm(q - p);
      return std::abs(dot(q - p, normal[v])) >= 0.5 * d ? d : kNone;
    });
    // Nothing within reach gives reach back: no limit (kFeatureShare x (r_max /
    // kFeatureShare) can round below r_max, which made radii 1 ulp short everywhere).
    const auto share = [&](double share, double d) { return d < reach ? share * d : kNone; };
    limits[v] = std::min(share(kFeatureShare, thickness), share(kCurveGapShare, limits[v]));
  }
  return limits;
}

SurfaceSizing thickness_sizing_from(const SurfaceDomain& domain, double r_max, const std::vector<double>& limits,
                                    double gradation) {
  using detail::number_text;
  using detail::short_text;
  if (!std::isfinite(r_max) || !(r_max > 0) || !std::isfinite(gradation) || !(gradation > 0) || !(gradation < 0.5)) {
    throw InvalidInput("thickness sizing with r_max = " + number_text(r_max) + ", gradation " + number_text(gradation) +
                       " is not valid: it needs r_max > 0 and 0 < gradation < 0.5 (e.g. auto:0.02 or auto:0.02,0.3)");
  }
  std::vector<double> radii(limits.size(), r_max);
  std::size_t thinnest = 0;
  for (std::size_t v = 0; v < radii.size(); ++v) {
    radii[v] = std::min(r_max, limits[v]);
    if (radii[v] < radii[thinnest]) thinnest = v;
  }
  const double smallest = radii[thinnest];
  if (!(smallest > 0)) {
    throw InvalidInput("thickness sizing: at " + detail::vertex_text(domain, thinnest) +
                       " another part of the surface touches it (thickness 0); the surface intersects itself there");
  }
  limit_gradation(domain, radii, gradation);
  std::string description = "thickness sizing min(" + number_text(r_max) + ", " + number_text(kFeatureShare) +
                            " thickness, " + number_text(kCurveGapShare) + " curve gap) graded at " + number_text(gradation) + ", smallest " + short_text(smallest);
  if (smallest < r_max) {
    const Vec3 at = domain.vertices()[thinnest];
    description += " near (" + short_text(at.x) + ", " + short_text(at.y) + ", " + short_text(at.z) + ")";
  }
  return SurfaceSizing::per_vertex(domain, std::move(radii), std::move(description));
}

}  // namespace detail

SurfaceSizing thickness_sizing(const SurfaceDomain& domain, double r_max, double gradation) {
  // Bad values are refused before the search (thickness_sizing_from says why).
  if (!std::isfinite(r_max) || !(r_max > 0) || !(gradation > 0) || !(gradation < 0.5)) {
    return detail::thickness_sizing_from(domain, r_max, {}, gradation);
  }
  return detail::thickness_sizing_from(domain, r_max, detail::thickness_limits(domain, r_max / kFeatureShare),
                                       gradation);
}

}  // namespace disktune
