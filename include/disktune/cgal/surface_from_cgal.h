// SPDX-License-Identifier: GPL-3.0-or-later
// A surface domain from a CGAL Surface_mesh. Header-only: include it where CGAL is at
// hand; the library itself stays free of CGAL in its public headers.
#pragma once

#include <CGAL/Surface_mesh.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "disktune/errors.h"
#include "disktune/surface_domain.h"

namespace disktune {

/// The mesh's vertices (in index order, removed ones skipped) and triangles, validated
/// by the SurfaceDomain constructor. Throws InvalidInput for a face that is no triangle.
template <class P>
SurfaceDomain surface_domain_from(const CGAL::Surface_mesh<P>& mesh) {
  using Mesh = CGAL::Surface_mesh<P>;
  // Removed-but-not-collected elements leave gaps in the indices: renumber densely.
  std::vector<std::size_t> index(mesh.number_of_vertices() + mesh.number_of_removed_vertices());
  std::vector<Vec3> vertices;
  vertices.reserve(mesh.number_of_vertices());
  for (const typename Mesh::Vertex_index v : mesh.vertices()) {
    index[static_cast<std::size_t>(v)] = vertices.size();
    const P& p = mesh.point(v);
    vertices.push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
  }
  std::vector<SurfaceDomain::Triangle> triangles;
  triangles.reserve(mesh.number_of_faces());
  std::size_t f_number = 0;
  for (const typename Mesh::Face_index f : mesh.faces()) {
    SurfaceDomain::Triangle t;
    std::size_t n = 0;
    for (const typename Mesh::Vertex_index v : mesh.vertices_around_face(mesh.halfedge(f))) {
      if (n < 3) t[n] = index[static_cast<std::size_t>(v)];
      ++n;
    }
    if (n != 3) {
      throw InvalidInput("face " + std::to_string(f_number) + " of the CGAL mesh has " +
                         std::to_string(n) +
                         " corners; a surface domain needs triangles: triangulate the mesh "
                         "first (CGAL::Polygon_mesh_processing::triangulate_faces)");
    }
    triangles.push_back(t);
    ++f_number;
  }
  return SurfaceDomain(std::move(vertices), std::move(triangles));
}

}  // namespace disktune
