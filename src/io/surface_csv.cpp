// SPDX-License-Identifier: GPL-3.0-or-later
// Surface samples as CSV (x,y,z,r), sharing the planar files' number format, atomic
// writer and CSV parser (points_csv.cpp).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <unordered_set>
#include <vector>

#include "../domain/point_text.h"
#include "csv_numbers.h"
#include "disktune/errors.h"
#include "disktune/io.h"
#include "disktune/surface_io.h"
#include "polygon_soup.h"
#include "radius_mismatch.h"

namespace disktune {
namespace {

// Relative tolerances of a point read back: its distance to the surface, its radius
// against the sizing's, and (tighter: they are placed there exactly) a boundary disk's
// distance to its fixed curve.
constexpr double kOnSurface = 1e-6, kRadiusMatch = 1e-6, kOnBoundary = 1e-9;

std::uint64_t edge_key(std::size_t a, std::size_t b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint64_t>(b);
}

}  // namespace

void write_surface_csv(const std::string& path, const SurfacePacking& packing) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << "x,y,z,r\n";
    for (const DiskId id : packing.ids()) {
      const Vec3 c = packing.center(id);
      detail::put_csv_row(out, {c.x, c.y, c.z, packing.radius(id)});
    }
  });
}

void read_surface_csv(const std::string& path, SurfacePacking& packing) {
  const detail::CsvNumbers rows = detail::read_csv_numbers(path, {"x,y,z,r", "x,y,z"});
  if (rows.rows() == 0) {
    throw InvalidInput("'" + path +
                       "' holds no disks, only a header; give at least one point x,y,z");
  }
  const SurfaceDomain& domain = packing.domain();
  const SurfaceIndex& index = packing.index();
  std::unordered_set<std::uint64_t> curve_edges;
  for (const SurfaceCurve& curve : domain.fixed_curves()) {
    const auto& v = curve.vertices;
    for (std::size_t k = 0; k < curve.edge_count(); ++k)
      curve_edges.insert(edge_key(v[k], v[(k + 1) % v.size()]));
  }
  const bool has_r = rows.columns == 4;
  // Triangles are searched within the largest radius: farther points are refused anyway.
  const double reach = packing.max_radius();
  std::vector<std::uint32_t> near;
  for (std::size_t k = 0; k < rows.rows(); ++k) {
    const Vec3 p{rows.at(k, 0), rows.at(k, 1), rows.at(k, 2)};
    std::ostringstream where;
    where << path << ":" << rows.lines[k] << ": ";
    if (has_r && !(rows.at(k, 3) > 0)) {
      where << "radius must be positive, found " << rows.at(k, 3);
      throw InvalidInput(where.str());
    }
    index.triangles_near(p, reach, near);
    double best = INFINITY;
    SurfacePoint q;
    for (const std::uint32_t t : near) {
      const Vec3 c = index.closest_point(t, p);
      const double d = norm(c - p);
      if (d < best) best = d, q = {c, t};
    }
    const double r = std::isfinite(best) ? packing.radius_at(q) : reach;
    const double r_given = has_r ? rows.at(k, 3) : r;
    if (!(best <= kOnSurface * std::min(r, r_given))) {
      where << "point " << detail::point_text(p) << " lies ";
      if (std::isfinite(best)) {
        where << best << " from the surface";
      } else {
        where << "farther than " << reach << " from the surface";
      }
      where << ", more than 1e-6 r; give the surface the samples were made on";
      throw InvalidInput(where.str(), InvalidInput::Remedy::domain);
    }
    if (std::abs(r_given - r) > kRadiusMatch * r) {
      where << "radius " << r_given << " differs from the radius " << r;
      if (packing.sizing().is_constant()) {
        where << " asked for";
      } else {
        where << " the sizing " << packing.sizing().description() << " gives at " << detail::point_text(p);
      }
      double lo = r_given, hi = r_given;
      for (std::size_t i = 0; i < rows.rows(); ++i) lo = std::min(lo, rows.at(i, 3)), hi = std::max(hi, rows.at(i, 3));
      detail::throw_radius_mismatch(where, lo, hi, "samples were");
    }
    // A disk on an edge of a fixed curve (open boundary, feature) is fixed, as sampling
    // made it.
    std::uint8_t flags = 0;
    if (!curve_edges.empty()) {
      for (const std::uint32_t t : near) {
        const auto& tri = domain.triangles()[t];
        for (int e = 0; e < 3 && !flags; ++e) {
          const std::size_t a = tri[e], b = tri[(e + 1) % 3];
          if (curve_edges.count(edge_key(a, b)) &&
              distance_to_segment(p, domain.vertices()[a], domain.vertices()[b]) <= kOnBoundary * r) {
            flags = kFixed;
          }
        }
        if (flags) break;
      }
    }
    packing.insert(q, flags);
  }
}

bool is_flat_mesh_file(const std::string& path) {
  const detail::PolygonSoup soup = detail::read_polygon_soup(path);
  if (soup.points.empty()) return false;
  const auto& first = soup.points[0];
  double extent = 0;
  for (const auto& p : soup.points) {
    extent = std::max({extent, std::abs(p[0] - first[0]), std::abs(p[1] - first[1])});
  }
  for (const auto& p : soup.points) {
    if (!(std::abs(p[2] - first[2]) <= 1e-9 * extent)) return false;
  }
  return true;
}

}  // namespace disktune
