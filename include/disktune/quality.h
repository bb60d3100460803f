// SPDX-License-Identifier: GPL-3.0-or-later
// Quality measures of a uniform-radius packing and its periodic Delaunay mesh: the
// numbers the paper judges packings by (its Figs. 5, 7, 9). Definitions in
// docs/quality.md.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "disktune/bond_order.h"
#include "disktune/mesh.h"
#include "disktune/packing.h"
#include "disktune/surface_mesh.h"

namespace disktune {

/// Counts of values in equal bins: bin k holds [lo + k*bin_width, lo + (k+1)*bin_width).
/// A value within 1e-9 bin widths below a bin's start counts in that bin (lattice
/// angles come out as 59.99999999999999). Values past the last bin count in `overflow`.
struct Histogram {
  double lo = 0;
  double bin_width = 1;
  std::vector<std::size_t> counts;
  std::size_t overflow = 0;
};

struct Statistics {
  double min = 0, mean = 0, max = 0, stddev = 0;  // stddev of the population
};

struct QualityReport {
  double radius = 0;               // r, the unit of the *_over_r numbers
  double width = 0, height = 0;    // the periodic box
  std::size_t count = 0;           // live disks
  std::size_t triangle_count = 0;  // 2 * count on the torus
  std::size_t edge_count = 0;      // 3 * count on the torus
  double area_fraction = 0;        // eta = N pi (r/2)^2 / (W H)
  double relative_radius = 0;      // rho = r / r_max
  double min_distance_over_r = 0;  // shortest center distance (a Delaunay edge) / r
  double max_coverage_over_r = 0;  // largest Delaunay circumradius / r
  bool maximal = false;            // is_maximal: no uncovered void corner
  bool conflict_free = false;      // no center pair closer than r (all pairs, exact)

  struct Angles {
    double min = 0, max = 0;               // degrees, over all triangle angles
    double mean_abs_dev_60 = 0;            // mean |angle - 60|
    double fraction_50_70 = 0;             // angles within [50, 70]
    double fraction_obtuse_triangles = 0;  // triangles with an angle above 90
    Histogram histogram;                   // 1-degree bins over [0, 180)
  } angles;

  struct Edges {
    double min_over_r = 0, max_over_r = 0;
    Histogram histogram;  // length / r, bins of 0.01 over [0, 3)
  } edges;

  struct LocalBeta {  // beta_i = Voronoi outradius / nearest-neighbour distance
    double min = 0, mean = 0, max = 0;
    Histogram histogram;  // bins of 0.01 over [0, 2)
  } local_beta;

  struct Voronoi {
    Statistics aspect_ratio;  // outradius / inradius about the site = 2 beta_i
    Statistics cell_area;     // the mean is W H / N: the cells tile the torus
    double cell_area_cv = 0;  // standard deviation / mean of the cell areas
  } voronoi;

  BondOrder order;  // psi6 and crystalline grains (bond_order.h)
};

/// Angle statistics (degrees) of any set of triangles: a torus mesh, a planar mesh, or
/// part of one. Throws InvalidInput when `triangles` is empty.
QualityReport::Angles measure_angles(const std::vector<Vec2>& vertices,
                                     const std::vector<std::array<std::uint32_t, 3>>& triangles);

/// The shape measures of a planar mesh with a boundary (a domain's constrained
/// Delaunay mesh, the CVT reference): angles and edges of all triangles, and local
/// beta of the vertices off the boundary, whose Voronoi cell the triangles around them
/// define (a boundary vertex's cell is cut by the boundary).
struct PlanarMeshQuality {
  std::size_t vertex_count = 0, triangle_count = 0, interior_vertex_count = 0;
  QualityReport::Angles angles;
  QualityReport::Edges edges;           // lengths over r
  QualityReport::LocalBeta local_beta;  // interior vertices only
};
/// Lengths are measured in units of r. Throws InvalidInput for a mesh without triangles.
PlanarMeshQuality measure_planar_mesh(const PlanarMesh& mesh, double r);
/// The same with a radius per vertex (varying radii): each edge's length is measured
/// in units of the mean radius of its two ends.
PlanarMeshQuality measure_planar_mesh(const PlanarMesh& mesh, const std::vector<double>& vertex_radius);

/// The report for a packing of a planar domain and its constrained Delaunay mesh: the
/// density and exact checks as for the torus, and the mesh's shape measures over all
/// triangles, the interior ones (no corner on a boundary disk) and the boundary ones.
struct PlanarQualityReport {
  double radius = 0;  // the one radius (0 with a sizing: radii vary)
  double area = 0;
  std::size_t count = 0, boundary_count = 0;  // all disks; the fixed boundary disks
  /// eta (relative to the sizing for varying radii: density_unit) and rho.
  double area_fraction = 0, relative_radius = 0;
  /// Shortest center distance over the smaller radius of the pair, over all pairs.
  double min_distance_over_r = 0;
  bool maximal = false, conflict_free = false;  // conflict: a pair covering each other's centers
  PlanarMeshQuality all, interior, boundary;   // edges over the mean radius of their ends
  BondOrder order;  // psi6 and grains, boundary disks included (bond_order.h)
};
/// Throws InvalidInput for an empty packing.
PlanarQualityReport measure_planar_quality(const Packing& packing, const PlanarMesh& mesh, double area);

/// The shape measures of a surface mesh (a restricted Delaunay mesh): 3D triangle
/// angles, edges over the mean radius of their ends, and local beta (the largest
/// circumradius of the triangles around a vertex over its shortest edge) of the vertices
/// on no boundary edge.
struct SurfaceMeshQuality {
  std::size_t vertex_count = 0, triangle_count = 0, interior_vertex_count = 0;
  QualityReport::Angles angles;
  QualityReport::Edges edges;
  QualityReport::LocalBeta local_beta;
  double hausdorff = 0;  // to the input surface: filled by the caller (hausdorff_distance)
};
/// `vertex_radius` holds one radius per vertex. Throws InvalidInput for a mesh without
/// triangles, a triangle naming a missing vertex, or a radius count that differs from
/// the vertex count.
SurfaceMeshQuality measure_surface_mesh(const SurfaceMesh& mesh, const std::vector<double>& vertex_radius);
/// Each triangle's smallest angle, in degrees (triangles naming missing vertices are the
/// caller's to avoid: measure_surface_mesh checks them).
std::vector<double> smallest_angles(const SurfaceMesh& mesh);

/// Measures `packing`, whose disks all have radius `r`, and its periodic Delaunay mesh
/// (from periodic_delaunay(packing)); distances are relative to r. Throws InvalidInput
/// when the packing is empty, a radius differs from r, or the mesh is not the packing's.
QualityReport measure_quality(const Packing& packing, const TriangleMesh& mesh, double r);

}  // namespace disktune
