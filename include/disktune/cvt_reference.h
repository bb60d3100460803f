// SPDX-License-Identifier: GPL-3.0-or-later
// The reference tuned packings are compared with: a centroidal Voronoi tessellation
// (CVT) mesh from CGAL's 2D mesher and its Lloyd optimizer, the usual way to get
// well-shaped triangles at a chosen vertex count.
#pragma once
#include <cstddef>
#include "disktune/geometry.h"
#include "disktune/mesh.h"
#include "disktune/planar_domain.h"

namespace disktune {

struct CvtReference {
  PlanarMesh mesh;
  int lloyd_iterations = 0;   // the most the optimizer was allowed
  double refine_seconds = 0;  // the last (kept) refinement
  double lloyd_seconds = 0;
};

/// A CVT mesh of the rectangle [0, extent.x] x [0, extent.y] with about `count`
/// vertices: CGAL's refine_Delaunay_mesh_2 (shape bound 0.125, i.e. angles above
/// about 20.7 degrees, and a uniform size bound calibrated over a few refinements to
/// land near `count`), then lloyd_optimize_mesh_2 for at most `max_iterations`
/// iterations. The vertex count is close to `count`, not equal: read it off the mesh.
/// Throws InvalidInput for an empty rectangle, count < 8 or max_iterations < 1.
CvtReference cvt_reference_mesh(Vec2 extent, std::size_t count, int max_iterations = 100);

/// The same over a planar domain: its loops as constraints, its holes left out, the
/// size bound calibrated to the domain's area (what a user with Triangle or CGAL would
/// make of a .poly instead). Throws InvalidInput for count < 8 or max_iterations < 1.
CvtReference cvt_reference_mesh(const PlanarDomain& domain, std::size_t count, int max_iterations = 100);

}  // namespace disktune
