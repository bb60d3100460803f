// SPDX-License-Identifier: GPL-3.0-or-later
// Surface sizing as radii at the mesh vertices: construction and checks, interpolation,
// expressions in x, y, z, the gradation limit and the command line's --sizing. The
// curvature sizing (CGAL) is in curvature_sizing.cpp.
#include "disktune/surface_sizing.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <queue>
#include <string>
#include <utility>
#include <vector>

#include "disktune/errors.h"
#include "disktune/sizing.h"
#include "expression_formula.h"
#include "sizing_text.h"
#include "surface_sizing_util.h"

namespace disktune {
namespace {

using detail::number_text;
using detail::parse_number;
using detail::trimmed;
using detail::vertex_text;

bool is_radius(double r) { return std::isfinite(r) && r > 0; }

void check_radii_count(const SurfaceDomain& domain, const std::vector<double>& radii,
                       const char* what) {
  if (radii.size() != domain.vertices().size()) {
    throw InvalidInput(std::string(what) + ": " + std::to_string(radii.size()) +
                       " radii for a surface of " + std::to_string(domain.vertices().size()) +
                       " vertices; give one radius per vertex, in the vertices' order");
  }
}

SurfaceSizing parse_curvature(const std::string& spec, const std::string& args,
                              const SurfaceDomain& domain) {
  const std::size_t comma = args.find(',');
  CurvatureSizingOptions options;
  if (comma == std::string::npos || args.find(',', comma + 1) != std::string::npos ||
      !parse_number(trimmed(args.substr(0, comma)), options.r_min) ||
      !parse_number(trimmed(args.substr(comma + 1)), options.r_max)) {
    throw InvalidInput("sizing \"" + spec +
                       "\": expected curvature:RMIN,RMAX with two numbers, e.g. "
                       "curvature:0.01,0.1 (or plain \"curvature\" for the defaults)");
  }
  // 0 would silently mean "default" in the options; written out, it is a mistake.
  if (!(options.r_min > 0) || !(options.r_max > 0)) {
    throw InvalidInput("sizing \"" + spec + "\": RMIN and RMAX must be positive");
  }
  try {
    return curvature_sizing(domain, options);
  } catch (const InvalidInput& e) {
    throw InvalidInput("sizing \"" + spec + "\": " + e.what());
  }
}

// "auto:RMAX" or "auto:RMAX,G": thickness_sizing.
SurfaceSizing parse_thickness(const std::string& spec, const std::string& args, const SurfaceDomain& domain) {
  const std::size_t comma = args.find(',');
  double r_max = 0, gradation = kFeatureGradation;
  if (!parse_number(trimmed(args.substr(0, comma)), r_max) ||
      (comma != std::string::npos && !parse_number(trimmed(args.substr(comma + 1)), gradation))) {
    throw InvalidInput("sizing \"" + spec + "\": expected auto:RMAX or auto:RMAX,G with numbers, e.g. auto:0.02");
  }
  try {
    return thickness_sizing(domain, r_max, gradation);
  } catch (const InvalidInput& e) {
    throw InvalidInput("sizing \"" + spec + "\": " + e.what());
  }
}

}  // namespace

SurfaceSizing SurfaceSizing::constant(double r) {
  if (!is_radius(r)) {
    throw InvalidInput("a constant surface sizing r = " + number_text(r) +
                       " is not a finite positive radius; give r > 0");
  }
  SurfaceSizing s;
  s.min_ = s.max_ = r;
  s.description_ = number_text(r);
  return s;
}

SurfaceSizing SurfaceSizing::per_vertex(const SurfaceDomain& domain, std::vector<double> radii,
                                        std::string description) {
  check_radii_count(domain, radii, ("the sizing (" + description + ")").c_str());
  for (std::size_t v = 0; v < radii.size(); ++v) {
    if (!is_radius(radii[v])) {
      throw InvalidInput("the sizing (" + description + ") gives r = " + number_text(radii[v]) +
                         " at " + vertex_text(domain, v) +
                         "; every vertex needs a finite positive radius");
    }
  }
  SurfaceSizing s;
  const auto [lo, hi] = std::minmax_element(radii.begin(), radii.end());
  s.min_ = *lo;
  s.max_ = *hi;
  s.vertex_radius_ = std::move(radii);
  s.description_ = std::move(description);
  return s;
}

double SurfaceSizing::radius(const SurfaceDomain& domain, Vec3 p, std::size_t t) const {
  if (is_constant()) return min_;
  const auto& tri = domain.triangles()[t];
  const auto& pts = domain.vertices();
  const Vec3 a = pts[tri[0]], e0 = pts[tri[1]] - a, e1 = pts[tri[2]] - a, w = p - a;
  // Barycentric coordinates of p's projection onto the triangle's plane ...
  const double d00 = dot(e0, e0), d01 = dot(e0, e1), d11 = dot(e1, e1);
  const double d20 = dot(w, e0), d21 = dot(w, e1);
  const double denom = d00 * d11 - d01 * d01;  // > 0: the domain has no flat triangles
  double l1 = (d11 * d20 - d01 * d21) / denom;
  double l2 = (d00 * d21 - d01 * d20) / denom;
  double l0 = 1 - l1 - l2;
  // ... clamped into the triangle, so a point a rounding outside stays within the
  // corners' radii.
  l0 = std::max(l0, 0.0);
  l1 = std::max(l1, 0.0);
  l2 = std::max(l2, 0.0);
  const double sum = l0 + l1 + l2;
  return (l0 * vertex_radius_[tri[0]] + l1 * vertex_radius_[tri[1]] +
          l2 * vertex_radius_[tri[2]]) /
         sum;
}

double density_integral(const SurfaceSizing& sizing, const SurfaceDomain& domain) {
  constexpr double pi = 3.14159265358979323846;
  if (sizing.is_constant()) return domain.area() / (pi * sizing.max_radius() * sizing.max_radius() / 4);
  // The integral of 4 / (pi r^2) by the edge-midpoint rule on every triangle.
  double sum = 0;
  for (std::size_t t = 0; t < domain.triangles().size(); ++t) {
    const auto& tri = domain.triangles()[t];
    const Vec3 a = domain.vertices()[tri[0]], b = domain.vertices()[tri[1]], c = domain.vertices()[tri[2]];
    double mean = 0;
    for (const Vec3 m : {(a + b) * 0.5, (b + c) * 0.5, (c + a) * 0.5}) {
      const double r = sizing.radius(domain, m, t);
      mean += 4 / (pi * r * r) / 3;
    }
    sum += mean * 0.5 * norm(cross(b - a, c - a));
  }
  return sum;
}

SurfaceSizing surface_expression_sizing(const SurfaceDomain& domain, const std::string& expression) {
  const detail::Formula formula(expression, true);
  const auto& pts = domain.vertices();
  std::vector<double> radii(pts.size());
  for (std::size_t v = 0; v < pts.size(); ++v) {
    radii[v] = formula(pts[v].x, pts[v].y, pts[v].z);
    if (!is_radius(radii[v])) {
      throw InvalidInput("the sizing expression \"" + expression + "\" gives r = " +
                         number_text(radii[v]) + " at " + vertex_text(domain, v) +
                         "; it must be finite and positive at every vertex of the surface "
                         "(clamp it, e.g. max(0.001, ...))");
    }
  }
  return SurfaceSizing::per_vertex(domain, std::move(radii), expression);
}

void limit_gradation(const SurfaceDomain& domain, std::vector<double>& radii, double gradation) {
  check_radii_count(domain, radii, "the gradation limit");
  if (!std::isfinite(gradation) || !(gradation >= 0)) {
    throw InvalidInput("the gradation limit g = " + number_text(gradation) +
                       " is not valid; give a finite g >= 0 (e.g. 0.3)");
  }
  for (std::size_t v = 0; v < radii.size(); ++v) {
    if (!is_radius(radii[v])) {
      throw InvalidInput("the gradation limit got r = " + number_text(radii[v]) + " at " +
                         vertex_text(domain, v) + "; every vertex needs a finite positive radius");
    }
  }
  // Dijkstra with r as the distance: once popped, r_u is final (every later candidate
  // is >= r_u), and each edge is relaxed from both ends, so afterwards
  // r_v <= r_u + g |u - v| holds exactly as computed here, and a second pass changes
  // nothing.
  const auto neighbours = detail::vertex_neighbours(domain);
  const auto& pts = domain.vertices();
  using Item = std::pair<double, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for (std::size_t v = 0; v < radii.size(); ++v) queue.push({radii[v], v});
  while (!queue.empty()) {
    const auto [r, u] = queue.top();
    queue.pop();
    if (r > radii[u]) continue;  // stale entry
    for (const std::size_t v : neighbours[u]) {
      const double candidate = r + gradation * norm(pts[v] - pts[u]);
      if (candidate < radii[v]) {
        radii[v] = candidate;
        queue.push({candidate, v});
      }
    }
  }
}

SurfaceSizing parse_surface_sizing(const std::string& spec, const SurfaceDomain& domain) {
  const std::string text = detail::sizing_text(
      spec, "a radius (0.01), \"curvature\", curvature:RMIN,RMAX, or an expression in x, y and z (\"0.01 + 0.02*z\")");
  if (double r = 0; detail::constant_radius(text, r)) return SurfaceSizing::constant(r);
  if (text == "curvature") return curvature_sizing(domain);
  const std::string prefix = "curvature:";
  if (text.compare(0, prefix.size(), prefix) == 0) {
    return parse_curvature(text, text.substr(prefix.size()), domain);
  }
  if (text.compare(0, 5, "auto:") == 0) return parse_thickness(text, text.substr(5), domain);
  if (text.compare(0, 9, "boundary:") == 0) {
    throw InvalidInput("sizing \"" + text + "\": boundary: sizings are for planar domains; on a surface give a "
                       "radius, \"curvature\", curvature:RMIN,RMAX, auto:RMAX (thinner where the surface faces "
                       "itself), or an expression in x, y and z");
  }
  return surface_expression_sizing(domain, text);
}

}  // namespace disktune
