// SPDX-License-Identifier: GPL-3.0-or-later
// disktune's meshes (plain arrays) into a CGAL::Surface_mesh. Header-only: include it
// where CGAL is at hand; the library itself stays free of CGAL in its public headers.
#pragma once

#include <CGAL/Dimension.h>
#include <CGAL/Surface_mesh.h>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "disktune/errors.h"
#include "disktune/mesh.h"
#include "disktune/surface_mesh.h"

namespace disktune {
namespace detail {

template <class P>
P to_cgal_point(Vec3 p) {
  return P(p.x, p.y, p.z);
}
template <class P>
P to_cgal_point(Vec2 p) {
  // A planar mesh goes into 2D or 3D points (z = 0).
  if constexpr (CGAL::Ambient_dimension<P>::value == 2) {
    return P(p.x, p.y);
  } else {
    return P(p.x, p.y, 0);
  }
}

// Vertex i of the result is vertex i of the input; `out` changes only on success.
template <class P, class Point, class Triangles>
void fill_cgal_mesh(const std::vector<Point>& points, const Triangles& triangles, CGAL::Surface_mesh<P>& out) {
  using Mesh = CGAL::Surface_mesh<P>;
  Mesh mesh;
  mesh.reserve(points.size(), 3 * triangles.size() / 2 + 3, triangles.size());
  for (const Point& p : points) mesh.add_vertex(to_cgal_point<P>(p));
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const auto& tri = triangles[t];
    const auto v = [&](int k) { return typename Mesh::Vertex_index(static_cast<typename Mesh::size_type>(tri[k])); };
    if (mesh.add_face(v(0), v(1), v(2)) == Mesh::null_face()) {
      throw InvalidInput("triangle " + std::to_string(t) +
                         " cannot join a CGAL::Surface_mesh: it would make an edge or a vertex "
                         "non-manifold or run an edge the same way as its neighbour (check the mesh "
                         "first with check_surface_mesh)");
    }
  }
  out = std::move(mesh);
}

}  // namespace detail

/// Replaces `out` by the surface mesh: vertex i is mesh.vertices[i] (isolated ones
/// too), faces in the order of mesh.triangles. Throws InvalidInput, leaving `out` as it
/// was, for a mesh a Surface_mesh cannot hold (non-manifold, or inconsistently oriented).
template <class P>
void copy_into(const SurfaceMesh& mesh, CGAL::Surface_mesh<P>& out) {
  const SurfaceMeshCheck check = check_surface_mesh(mesh);
  if (!check.manifold) {
    throw InvalidInput("the mesh is not a manifold, which a CGAL::Surface_mesh cannot hold: " + check.problems);
  }
  detail::fill_cgal_mesh(mesh.vertices, mesh.triangles, out);
}

/// The same for a planar mesh (constrained Delaunay), into 2D or 3D points (z = 0).
template <class P>
void copy_into(const PlanarMesh& mesh, CGAL::Surface_mesh<P>& out) {
  detail::fill_cgal_mesh(mesh.vertices, mesh.triangles, out);
}

}  // namespace disktune
