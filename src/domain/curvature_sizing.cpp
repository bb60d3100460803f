// SPDX-License-Identifier: GPL-3.0-or-later
// Curvature-based surface sizing: the principal curvatures at each vertex from a
// degree-2 jet fitted to its mesh neighbourhood (CGAL's Monge_via_jet_fitting, solved
// with Eigen). The only file of the surface sizing that includes CGAL.
#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "disktune/errors.h"
#include "disktune/surface_sizing.h"
#include "surface_sizing_util.h"

namespace disktune {
namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Fitting = CGAL::Monge_via_jet_fitting<Kernel>;

// Enough points for a well-posed least-squares fit of the 6 coefficients of a degree-2
// jet, but a neighbourhood small enough to stay local.
constexpr std::size_t kWantedPoints = 16;
constexpr std::size_t kMaxPoints = 60;
constexpr int kMaxRings = 3;
constexpr std::size_t kJetCoefficients = 6;  // (d + 1)(d + 2) / 2 for d = 2

// The vertex v first (CGAL's fit is centered at the first point), then whole rings of
// mesh neighbours until there are kWantedPoints or kMaxRings rings; the farthest are
// dropped beyond kMaxPoints.
void gather_neighbourhood(std::size_t v, const std::vector<std::vector<std::size_t>>& neighbours,
                          const std::vector<Vec3>& pts, std::vector<std::size_t>& stamp,
                          std::vector<std::size_t>& hood) {
  hood.assign(1, v);
  stamp[v] = v + 1;  // stamps, not flags: nothing to clear between vertices
  std::size_t ring_begin = 0;
  for (int ring = 0; ring < kMaxRings && hood.size() < kWantedPoints; ++ring) {
    const std::size_t ring_end = hood.size();
    for (std::size_t i = ring_begin; i < ring_end; ++i) {
      for (const std::size_t w : neighbours[hood[i]]) {
        if (stamp[w] != v + 1) {
          stamp[w] = v + 1;
          hood.push_back(w);
        }
      }
    }
    if (hood.size() == ring_end) break;  // the whole component is gathered
    ring_begin = ring_end;
  }
  if (hood.size() > kMaxPoints) {
    const Vec3 p = pts[v];
    std::nth_element(hood.begin() + 1, hood.begin() + kMaxPoints, hood.end(),
                     [&](std::size_t a, std::size_t b) {
                       return squared_norm(pts[a] - p) < squared_norm(pts[b] - p);
                     });
    hood.resize(kMaxPoints);
  }
}

}  // namespace

SurfaceSizing curvature_sizing(const SurfaceDomain& domain, const CurvatureSizingOptions& options) {
  CurvatureSizingOptions o = options;
  const double diagonal = norm(domain.bbox_max() - domain.bbox_min());
  if (o.r_max == 0) o.r_max = diagonal / 25;
  if (o.r_min == 0) o.r_min = o.r_max / 8;
  using detail::number_text;
  const std::string params = "r_min = " + number_text(o.r_min) + ", r_max = " +
                             number_text(o.r_max) + ", angle = " + number_text(o.angle) +
                             ", gradation = " + number_text(o.gradation);
  if (!std::isfinite(o.r_min) || !std::isfinite(o.r_max) || !(o.r_min > 0) ||
      !(o.r_min <= o.r_max) || !std::isfinite(o.angle) || !(o.angle > 0) ||
      !std::isfinite(o.gradation) || !(o.gradation > 0)) {
    throw InvalidInput("the curvature sizing with " + params +
                       " is not valid: it needs 0 < r_min <= r_max, angle > 0 (radians) and "
                       "gradation > 0 (r_min or r_max 0 picks the default: r_max = the bounding "
                       "box's diagonal / 25 = " +
                       number_text(diagonal / 25) + ", r_min = r_max / 8)");
  }

  const auto& pts = domain.vertices();
  const auto neighbours = detail::vertex_neighbours(domain);
  std::vector<std::size_t> stamp(pts.size(), 0), hood;
  std::vector<Kernel::Point_3> points;
  Fitting fitting;
  std::vector<double> radii(pts.size());
  for (std::size_t v = 0; v < pts.size(); ++v) {
    gather_neighbourhood(v, neighbours, pts, stamp, hood);
    // A component too small to fit a jet to (a tetrahedron, say) is all corners: as
    // bent as a mesh can be, so the smallest radius.
    if (hood.size() < kJetCoefficients) {
      radii[v] = o.r_min;
      continue;
    }
    points.clear();
    for (const std::size_t w : hood) points.emplace_back(pts[w].x, pts[w].y, pts[w].z);
    const Fitting::Monge_form form = fitting(points.begin(), points.end(), 2, 2);
    const double kmax =
        std::max(std::abs(form.principal_curvatures(0)), std::abs(form.principal_curvatures(1)));
    // A flat neighbourhood gives kmax = 0 and r = angle / 0 = inf, clamped to r_max; a
    // degenerate fit (NaN) gets the safe end, r_min.
    const double r = std::isnan(kmax) ? o.r_min : o.angle / kmax;
    radii[v] = std::clamp(r, o.r_min, o.r_max);
  }
  limit_gradation(domain, radii, o.gradation);
  return SurfaceSizing::per_vertex(domain, std::move(radii),
                                   "curvature " + number_text(o.r_min) + ".." +
                                       number_text(o.r_max) + " (angle " + number_text(o.angle) +
                                       ", gradation " + number_text(o.gradation) + ")");
}

}  // namespace disktune
