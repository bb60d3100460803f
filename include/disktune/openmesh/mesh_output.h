// SPDX-License-Identifier: GPL-3.0-or-later
// disktune's surface mesh (plain arrays) into an OpenMesh mesh. Header-only: include it
// where OpenMesh is at hand; the library itself stays free of OpenMesh in its public
// headers.
#pragma once

#include <string>

#include "disktune/errors.h"
#include "disktune/surface_mesh.h"

namespace disktune {

/// Replaces `out` (an OpenMesh TriMesh or PolyMesh) by the mesh: vertex i is
/// mesh.vertices[i] (isolated ones too), faces in the order of mesh.triangles. Throws
/// InvalidInput, leaving `out` as it was, for a mesh OpenMesh cannot hold (non-manifold,
/// or inconsistently oriented).
template <class OpenMeshMesh>
void copy_into(const SurfaceMesh& mesh, OpenMeshMesh& out) {
  const SurfaceMeshCheck check = check_surface_mesh(mesh);
  if (!check.manifold || !check.oriented) {
    throw InvalidInput("the mesh is not an oriented manifold, which an OpenMesh mesh cannot hold: " +
                       check.problems);
  }
  using Point = typename OpenMeshMesh::Point;
  using Scalar = typename Point::value_type;
  OpenMeshMesh result;
  result.reserve(mesh.vertices.size(), 3 * mesh.triangles.size() / 2 + 3, mesh.triangles.size());
  for (const Vec3& p : mesh.vertices)
    result.add_vertex(Point(static_cast<Scalar>(p.x), static_cast<Scalar>(p.y), static_cast<Scalar>(p.z)));
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const auto v = [&](int k) { return result.vertex_handle(static_cast<unsigned>(tri[k])); };
    if (!result.add_face(v(0), v(1), v(2)).is_valid()) {
      throw InvalidInput("triangle " + std::to_string(t) + " cannot join the OpenMesh mesh");
    }
  }
  out = result;
}

}  // namespace disktune
