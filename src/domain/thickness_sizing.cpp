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
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "disktune/errors.h"
#include "disktune/sizing.h"
#include "disktune/surface_packing.h"
#include "disktune/surface_sizing.h"
#include "surface_sizing_util.h"

namespace disktune {
namespace {

// Area-weighted vertex normals (unit; zero at a vertex of degenerate triangles only).
std::vector<Vec3> vertex_normals(const SurfaceIndex& index) {
  const SurfaceDomain& d = index.domain();
  std::vector<Vec3> n(d.vertices().size(), Vec3{0, 0, 0});
  for (std::size_t t = 0; t < d.triangles().size(); ++t) {
    const auto& tri = d.triangles()[t];
    const Vec3 a = d.vertices()[tri[0]];
    const double area = norm(cross(d.vertices()[tri[1]] - a, d.vertices()[tri[2]] - a)) / 2;
    for (const auto v : tri) n[v] = n[v] + index.plane(t).normal() * area;
  }
  for (Vec3& v : n) {
    const double len = norm(v);
    if (len > 0) v = v * (1 / len);
  }
  return n;
}

std::string short_text(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

}  // namespace

SurfaceSizing thickness_sizing(const SurfaceDomain& domain, double r_max, double gradation) {
  using detail::number_text;
  if (!std::isfinite(r_max) || !(r_max > 0) || !std::isfinite(gradation) || !(gradation > 0) || !(gradation < 0.5)) {
    throw InvalidInput("thickness sizing with r_max = " + number_text(r_max) + ", gradation " + number_text(gradation) +
                       " is not valid: it needs r_max > 0 and 0 < gradation < 0.5 (e.g. auto:0.02 or auto:0.02,0.3)");
  }
  const double reach = r_max / kFeatureShare;  // no part farther than this lowers r
  // The index keeps a pointer to the domain only for the call (no ownership).
  const SurfaceIndex index(std::shared_ptr<const SurfaceDomain>(std::shared_ptr<const SurfaceDomain>(), &domain), reach);
  const std::vector<Vec3> normal = vertex_normals(index);
  const auto& triangles = domain.triangles();
  std::vector<double> radii(domain.vertices().size(), r_max);
  std::vector<std::uint32_t> near;
  std::size_t thinnest = 0;
  for (std::size_t v = 0; v < radii.size(); ++v) {
    const Vec3 p = domain.vertices()[v];
    double thickness = reach;
    index.triangles_near(p, reach, near);
    for (const std::uint32_t t : near) {
      const auto& tri = triangles[t];
      if (tri[0] == v || tri[1] == v || tri[2] == v) continue;
      if (!(dot(index.plane(t).normal(), normal[v]) < -0.5)) continue;
      const Vec3 q = index.closest_point(t, p);
      const double d = norm(q - p);
      if (d < thickness && std::abs(dot(q - p, normal[v])) >= 0.5 * d) thickness = d;
    }
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
