// SPDX-License-Identifier: GPL-3.0-or-later
#include "disktune/fiber_statistics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <string>
#include <utility>

#include "disktune/errors.h"
#include "disktune/mesh.h"
#include "disktune/packing.h"
#include "local_psi6.h"
#include "mesh_shape.h"

namespace disktune {
namespace {

constexpr double kPi = 3.14159265358979323846;

using detail::add;
using detail::make_histogram;
using detail::statistics;

// Each Voronoi cell's area from the periodic Delaunay triangulation: a triangle gives
// each corner the signed areas of the two triangles (corner, edge midpoint,
// circumcenter), which sum to the cell (obtuse triangles give negative parts).
std::vector<double> voronoi_areas(const Packing& packing) {
  const TriangleMesh mesh = periodic_delaunay(packing);
  std::vector<double> area(mesh.disk_count, 0.0);
  for (const auto& t : mesh.triangles) {
    const Vec2 a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
    const Vec2 ab = b - a, ac = c - a;
    const double d = 2 * cross(ab, ac);
    const Vec2 o = a + Vec2{ac.y * dot(ab, ab) - ab.y * dot(ac, ac), ab.x * dot(ac, ac) - ac.x * dot(ab, ab)} * (1 / d);
    for (int k = 0; k < 3; ++k) {
      const Vec2 p = mesh.vertices[t[k]], q = mesh.vertices[t[(k + 1) % 3]], s = mesh.vertices[t[(k + 2) % 3]];
      const Vec2 to_q = (q - p) * 0.5, to_s = (s - p) * 0.5, to_o = o - p;
      area[mesh.vertex_disk[t[k]]] += 0.5 * (cross(to_q, to_o) + cross(to_o, to_s));
    }
  }
  return area;
}

// The signed area of the disk of radius R about the origin inside the triangle (origin,
// a, b): along ab, the parts inside the circle add their triangles, the parts outside
// their circular sectors.
double disk_in_triangle(Vec2 a, Vec2 b, double R) {
  const Vec2 e = b - a;
  const double A = dot(e, e), B = dot(a, e), C = dot(a, a) - R * R, disc = B * B - A * C;
  Vec2 points[4] = {a, a, a, a};
  int n = 1;
  if (A > 0 && disc > 0) {
    for (const double t : {(-B - std::sqrt(disc)) / A, (-B + std::sqrt(disc)) / A})
      if (t > 0 && t < 1) points[n++] = a + e * t;
  }
  points[n++] = b;
  double area = 0;
  for (int k = 0; k + 1 < n; ++k) {
    const Vec2 u = points[k], v = points[k + 1], mid = (u + v) * 0.5;
    area += dot(mid, mid) <= R * R ? 0.5 * cross(u, v) : 0.5 * R * R * std::atan2(cross(u, v), dot(u, v));
  }
  return area;
}

// The area of the disk (c, R) inside the axis-aligned square [lo, lo + side]^2.
double disk_in_square(Vec2 c, double R, Vec2 lo, double side) {
  const Vec2 corners[4] = {lo - c, Vec2{lo.x + side, lo.y} - c, Vec2{lo.x + side, lo.y + side} - c,
                           Vec2{lo.x, lo.y + side} - c};
  double area = 0;
  for (int k = 0; k < 4; ++k) area += disk_in_triangle(corners[k], corners[(k + 1) % 4], R);
  return area;
}

// Windows `side_over_d` mean diameters wide; each fiber its own radius in `index`.
std::vector<FiberStatistics::LocalFraction> local_fractions(const Packing& index, double diameter, double widest) {
  std::vector<FiberStatistics::LocalFraction> out;
  const Vec2 cell = index.frame().extent;
  for (const double side_over_d : {2.0, 4.0, 8.0, 16.0}) {
    const double side = side_over_d * diameter;
    const auto nx = static_cast<std::size_t>(std::floor(cell.x / side * (1 + 1e-12)));
    const auto ny = static_cast<std::size_t>(std::floor(cell.y / side * (1 + 1e-12)));
    if (nx == 0 || ny == 0) break;
    std::vector<double> fractions;
    for (std::size_t j = 0; j < ny; ++j) {
      for (std::size_t i = 0; i < nx; ++i) {
        const Vec2 lo{static_cast<double>(i) * side, static_cast<double>(j) * side};
        const Vec2 mid = lo + Vec2{side, side} * 0.5;
        double covered = 0;
        index.for_each_near(mid, side * std::sqrt(0.5) + widest / 2, [&](const Neighbor& q) {
          covered += disk_in_square(q.image, q.radius, lo, side);
        });
        fractions.push_back(covered / (side * side));
      }
    }
    out.push_back({side_over_d, fractions.size(), statistics(fractions)});
  }
  return out;
}

}  // namespace

double poisson_local_fraction_stddev(double side, double diameter, double intensity) {
  constexpr int kSteps = 256;
  const double radius = diameter / 2, extent = side + diameter, step = extent / kSteps;
  double sum = 0;
  for (int j = 0; j < kSteps; ++j) {
    for (int i = 0; i < kSteps; ++i) {
      const Vec2 at{-radius + (i + 0.5) * step, -radius + (j + 0.5) * step};
      const double a = disk_in_square(at, radius, {0, 0}, side) / (side * side);
      sum += a * a;
    }
  }
  return std::sqrt(intensity * sum * step * step);
}

FiberStatistics::LocalFraction hexagonal_local_fraction(double side, double diameter, double intensity,
                                                         std::size_t per_row) {
  const double spacing = std::sqrt(2 / (std::sqrt(3.0) * intensity)), row = spacing * std::sqrt(3.0) / 2;
  const double radius = diameter / 2;
  std::vector<double> fractions;
  for (std::size_t j = 0; j < per_row; ++j) {
    for (std::size_t i = 0; i < per_row; ++i) {
      const Vec2 lo{static_cast<double>(i) * side, static_cast<double>(j) * side};
      double covered = 0;
      // Every lattice point whose fiber can reach the window: rows k, odd rows shifted.
      const auto k0 = static_cast<long>(std::floor((lo.y - radius) / row)), k1 = static_cast<long>(std::ceil((lo.y + side + radius) / row));
      for (long k = k0; k <= k1; ++k) {
        const double shift = (k % 2 != 0) ? spacing / 2 : 0, y = static_cast<double>(k) * row;
        const auto m0 = static_cast<long>(std::floor((lo.x - radius - shift) / spacing));
        const auto m1 = static_cast<long>(std::ceil((lo.x + side + radius - shift) / spacing));
        for (long m = m0; m <= m1; ++m) covered += disk_in_square({static_cast<double>(m) * spacing + shift, y}, radius, lo, side);
      }
      fractions.push_back(covered / (side * side));
    }
  }
  return {side / diameter, fractions.size(), statistics(fractions)};
}

double poisson_nearest_mean(int k, double intensity) {
  double factorial = 1;
  for (int i = 2; i < k; ++i) factorial *= i;
  return std::tgamma(k + 0.5) / (factorial * std::sqrt(kPi * intensity));
}

FiberStatistics fiber_statistics(const PeriodicBox& cell, const std::vector<Vec2>& centers, double diameter) {
  return fiber_statistics(cell, centers, std::vector<double>(centers.size(), diameter));
}

FiberStatistics fiber_statistics(const PeriodicBox& cell, const std::vector<Vec2>& centers,
                                 const std::vector<double>& diameters) {
  if (centers.size() < 7) {
    throw InvalidInput("fiber statistics need at least 7 fibers (six neighbours each), got " +
                       std::to_string(centers.size()));
  }
  if (diameters.size() != centers.size()) {
    throw InvalidInput("fiber statistics: " + std::to_string(centers.size()) + " fibers but " +
                       std::to_string(diameters.size()) + " diameters; give one diameter per fiber");
  }
  FiberStatistics s;
  const std::size_t n = centers.size();
  const double w = cell.width(), h = cell.height(), area = cell.area();
  double fibers = 0, squares = 0;
  for (const double d : diameters) {
    if (!(d > 0 && std::isfinite(d))) throw InvalidInput("fiber statistics: the diameter must be positive");
    fibers += kPi * d * d / 4, squares += d * d;
  }
  s.diameters = statistics(diameters);
  // Equal fibers: D itself, not a sum's rounding of it.
  const double diameter = s.diameters.min == s.diameters.max ? s.diameters.min : s.diameters.mean;
  s.diameter_rms = s.diameters.min == s.diameters.max ? diameter : std::sqrt(squares / static_cast<double>(n));
  s.count = n, s.width = w, s.height = h, s.diameter = diameter;
  s.fiber_fraction = s.diameters.min == s.diameters.max ? static_cast<double>(n) * kPi * diameter * diameter / 4 / area
                                                        : fibers / area;

  // The pairs up to r_max for K and g; six neighbours may lie farther (sparse cells).
  const double r_max = std::min(5 * diameter, 0.5 * std::min(w, h) * (1 - 1e-9));
  const auto rings = static_cast<std::size_t>(std::floor(r_max / (s.dr * diameter) + 1e-9));
  const double spacing = std::sqrt(area / static_cast<double>(n));
  Packing index(cell.frame(), std::max({r_max, 3 * spacing, s.diameters.max / 2}));
  for (std::size_t i = 0; i < n; ++i) index.insert(cell.wrap(centers[i]), diameters[i] / 2);

  std::vector<double> pairs(rings, 0.0);
  std::array<std::vector<double>, 6> nearest;
  for (int k = 0; k < 6; ++k) s.nearest_histogram[k] = make_histogram(0, 0.02, 200);
  s.nearest_orientation = make_histogram(0, 10, 18);
  s.psi6_local = make_histogram(0, 0.05, 21);  // the last bin holds 1 exactly
  std::complex<double> psi6_sum = 0;
  std::size_t hexagonal = 0;
  std::vector<std::pair<double, Vec2>> near;  // squared distance, bond
  for (DiskId i = 0; i < n; ++i) {
    const Vec2 c = index.center(i);
    for (double reach = 3 * spacing;; reach *= 2) {
      near.clear();
      index.for_each_near(c, std::max(reach, r_max), [&](const Neighbor& q) {
        if (q.d2 > 0) near.push_back({q.d2, q.image - c});
        else if (q.id != i) throw InvalidInput("fiber statistics: two fibers at one center");
      });
      if (near.size() >= 6 || reach > 2 * std::max(w, h)) break;
    }
    std::sort(near.begin(), near.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::array<Vec2, 6> bonds;
    for (int k = 0; k < 6; ++k) {
      const double d = std::sqrt(near[k].first) / diameter;
      nearest[k].push_back(d);
      add(s.nearest_histogram[k], d);
      bonds[k] = near[k].second;
    }
    const std::complex<double> local = detail::local_psi6(bonds);
    psi6_sum += local;
    s.psi6_local_mean += std::abs(local);
    hexagonal += std::abs(local) > 0.9;
    add(s.psi6_local, std::abs(local));
    double angle = std::atan2(near[0].second.y, near[0].second.x) * 180 / kPi;
    if (angle < 0) angle += 180;
    add(s.nearest_orientation, angle >= 180 - 1e-6 ? 0 : angle);  // 180 is 0: a bond has no sense
    for (const auto& [d2, bond] : near) {
      // d in ((ring - 1) dr, ring dr], a pair at r (to 1e-9) counted at r: fibers placed
      // at the gap's distance exactly are many (void corners), and within r.
      const double ring = std::ceil(std::sqrt(d2) / diameter / s.dr * (1 - 1e-9));
      if (ring >= 1 && ring <= static_cast<double>(rings)) pairs[static_cast<std::size_t>(ring) - 1] += 1;
    }
  }
  for (int k = 0; k < 6; ++k) s.nearest[k] = statistics(nearest[k]);
  s.psi6_global = std::abs(psi6_sum) / static_cast<double>(n);
  s.psi6_local_mean /= static_cast<double>(n);
  s.psi6_hexagonal_share = static_cast<double>(hexagonal) / static_cast<double>(n);

  const double per_pair = area / (static_cast<double>(n) * static_cast<double>(n - 1));
  double within = 0;
  for (std::size_t i = 0; i < rings; ++i) {
    const double r = static_cast<double>(i + 1) * s.dr, r_in = static_cast<double>(i) * s.dr;
    within += pairs[i];
    s.r.push_back(r);
    s.ripley_k.push_back(per_pair * within / (diameter * diameter));
    s.ripley_l.push_back(std::sqrt(s.ripley_k.back() / kPi));
    s.pair_correlation.push_back(per_pair * pairs[i] / (kPi * (r * r - r_in * r_in) * diameter * diameter));
  }
  const Statistics cells = statistics(voronoi_areas(index));
  s.voronoi_area_cv = cells.stddev / cells.mean;
  s.local_fraction = local_fractions(index, diameter, s.diameters.max);
  return s;
}

}  // namespace disktune
