// SPDX-License-Identifier: GPL-3.0-or-later
// The shape measures shared by planar and surface meshes (internal): each path computes
// its triangles' angles and circumradii in its own space, then the statistics, the edge
// lengths and local beta are gathered here once; and the histogram and statistics
// helpers every analysis file uses.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "disktune/quality.h"

namespace disktune::detail {

/// A corner's angle in degrees from |u x v| and u . v of its two sides: atan2 stays
/// accurate near 0 and 180 degrees, where acos of a rounded cosine does not.
inline double corner_angle_deg(double cross_norm, double dot) {
  return std::atan2(cross_norm, dot) * 57.295779513082320876798;
}

/// An empty histogram: `bins` bins `bin_width` wide from `lo`.
Histogram make_histogram(double lo, double bin_width, std::size_t bins);
/// Counts v in its bin: a value within 1e-9 of a bin under its upper boundary counts in
/// the next bin, one below `lo` in the first, one past the last bin in `overflow`.
void add(Histogram& h, double v);
/// Min, mean, max and the population's standard deviation (all 0 for no values).
Statistics statistics(const std::vector<double>& values);

/// One triangle as the measures see it.
struct TriangleShape {
  std::array<double, 3> angles_deg;  // at its three corners
  double circumradius;
};

/// Angle statistics over the triangles. Throws InvalidInput when there are none.
QualityReport::Angles angle_statistics(const std::vector<TriangleShape>& shapes);

struct MeshShape {
  QualityReport::Angles angles;
  QualityReport::Edges edges;           // each edge over the mean radius of its ends
  QualityReport::LocalBeta local_beta;  // vertices off the boundary only
  std::size_t interior_vertex_count = 0;
};

/// Angles, edges (each once) and local beta: the largest circumradius around a vertex
/// over its shortest edge, for vertices on no boundary edge (an edge of one triangle).
/// Throws InvalidInput when there are no triangles.
MeshShape measure_mesh_shape(std::size_t vertex_count,
                             const std::vector<std::array<std::uint32_t, 3>>& triangles,
                             const std::vector<TriangleShape>& shapes,
                             const std::function<double(std::uint32_t, std::uint32_t)>& edge_length,
                             const std::vector<double>& vertex_radius);

/// The public measures of a mesh (PlanarMeshQuality or SurfaceMeshQuality) from its
/// counts and shape.
template <class MeshQuality>
MeshQuality mesh_quality(std::size_t vertex_count, std::size_t triangle_count, const MeshShape& m) {
  MeshQuality q;
  q.vertex_count = vertex_count;
  q.triangle_count = triangle_count;
  q.interior_vertex_count = m.interior_vertex_count;
  q.angles = m.angles;
  q.edges = m.edges;
  q.local_beta = m.local_beta;
  return q;
}

}  // namespace disktune::detail
