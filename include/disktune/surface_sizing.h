// SPDX-License-Identifier: GPL-3.0-or-later
// Sizing on a surface: the radius r(x) a disk centered at x gets. One representation
// serves every kind: a radius per mesh vertex, interpolated linearly over each triangle
// (so r is continuous and its gradation is the largest over the mesh's edges). A
// constant sizing is exact everywhere; an expression or the curvature is evaluated at
// the vertices. Docs: docs/surfaces.md.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "disktune/surface_domain.h"
#include "disktune/vec3.h"

namespace disktune {

class SurfaceSizing {
 public:
  /// r everywhere. Throws InvalidInput unless r is finite and positive.
  static SurfaceSizing constant(double r);
  /// One radius per vertex of `domain`, interpolated over its triangles. Throws
  /// InvalidInput, naming the vertex, unless there is one finite positive radius per vertex.
  static SurfaceSizing per_vertex(const SurfaceDomain& domain, std::vector<double> radii,
                                  std::string description = "per-vertex field");

  bool is_constant() const { return vertex_radius_.empty(); }
  /// The radius at p, a point of triangle t of the domain the sizing was made for
  /// (barycentric interpolation of the corner radii; p is projected into the triangle).
  double radius(const SurfaceDomain& domain, Vec3 p, std::size_t t) const;
  double min_radius() const { return min_; }
  double max_radius() const { return max_; }
  /// Empty for a constant sizing.
  const std::vector<double>& vertex_radii() const { return vertex_radius_; }
  /// What the sizing is, for messages and reports (e.g. "curvature 0.01..0.05").
  const std::string& description() const { return description_; }

 private:
  std::vector<double> vertex_radius_;
  double min_ = 0, max_ = 0;
  std::string description_;
};

/// An expression in x, y and z (muParser syntax, as the planar expression sizing)
/// evaluated at every vertex. Throws InvalidInput for a syntax error or a value that is
/// not finite and positive at some vertex (naming it).
SurfaceSizing surface_expression_sizing(const SurfaceDomain& domain, const std::string& expression);

/// Curvature-based sizing (CGAL's Monge_via_jet_fitting, degree-2 jets over each
/// vertex's neighbourhood): r = clamp(angle / kmax, r_min, r_max) where kmax is the
/// largest absolute principal curvature, so a disk spans at most `angle` radians of the
/// surface's tightest bend; then the gradation limit (limit_gradation).
struct CurvatureSizingOptions {
  double r_min = 0, r_max = 0;  // 0: r_max = diagonal / 25 of the bounding box, r_min = r_max / 8
  double angle = 0.5;           // radians
  double gradation = 0.3;       // Lipschitz limit of r along the mesh
};
/// Throws InvalidInput unless 0 < r_min <= r_max (after defaults), angle > 0, gradation > 0.
SurfaceSizing curvature_sizing(const SurfaceDomain& domain, const CurvatureSizingOptions& options = {});

/// Lowers radii until |r_u - r_v| <= gradation * |u - v| along every mesh edge (a
/// shortest-path pass from the smallest radii outward); never raises one.
void limit_gradation(const SurfaceDomain& domain, std::vector<double>& radii, double gradation);

/// Whether one radius r everywhere keeps disks of their own on the surface's fixed
/// curves (SurfaceDomain::fixed_curves: open boundaries and feature curves): false when
/// a stretch of a curve longer than 3r lies closer than r to a part of the curves it
/// does not meet (a curve sharing no corner with it, at a corner one that does not end
/// there, or its own curve more than twice as far along it as in space): a chamfer's two
/// creases, a crease beside a rim, two close holes. A disk on one such part covers the
/// other, which then holds none, and the mesh cuts across that stretch. Shorter
/// stretches, two disks' worth at the curves' spacing or less (a few noisy feature
/// edges of a scan), are let go.
bool curves_fit(const SurfaceDomain& domain, double r);

/// The share of that gap a radius may take near such curves (thickness_sizing): below
/// the gap, each of the two parts keeps disks of its own, and the surface between them
/// is meshed from both (a facing thin wall needs kFeatureShare, far less).
constexpr double kCurveGapShare = 0.9;

/// Thickness sizing (`--sizing auto:RMAX[,G]` on a surface): at each vertex r =
/// min(r_max, kFeatureShare * thickness), the thickness being the distance to the
/// nearest other part of the surface that faces the vertex (a triangle whose normal
/// points against the vertex's, cosine below -1/2, whose closest point lies within 60
/// degrees of the vertex's normal line): a thin wall, or a face under a ledge; and at
/// a vertex of a fixed curve also r <= kCurveGapShare times its distance to the curve
/// parts it does not meet (as curves_fit). Then the gradation limit
/// (limit_gradation). Throws InvalidInput unless r_max > 0 and 0 < gradation < 0.5, or
/// where the surface touches itself.
SurfaceSizing thickness_sizing(const SurfaceDomain& domain, double r_max, double gradation = 0.2);

/// The integral of 4 / (pi r^2) over the surface: the disk count at area fraction 1
/// (exact for a constant sizing, else the edge-midpoint rule on every triangle).
double density_integral(const SurfaceSizing& sizing, const SurfaceDomain& domain);

/// The command line's --sizing for a surface: a number (constant),
/// "curvature" or "curvature:RMIN,RMAX", "auto:RMAX" or "auto:RMAX,G" (thickness_sizing),
/// else an expression in x, y, z.
SurfaceSizing parse_surface_sizing(const std::string& spec, const SurfaceDomain& domain);

}  // namespace disktune
