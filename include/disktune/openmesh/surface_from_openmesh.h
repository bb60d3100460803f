// SPDX-License-Identifier: GPL-3.0-or-later
// A surface domain from an OpenMesh mesh. Header-only: include it where OpenMesh is at
// hand; the library itself stays free of OpenMesh in its public headers.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "disktune/errors.h"
#include "disktune/surface_domain.h"

namespace disktune {

/// The vertices (in index order) and triangles of an OpenMesh TriMesh (any mesh type with
/// OpenMesh's interface: a PolyMesh works too), validated by the SurfaceDomain
/// constructor. Throws InvalidInput for a face that is no triangle. Call
/// garbage_collection() after deleting elements: deleted ones still hold indices.
template <class OpenMeshMesh>
SurfaceDomain surface_domain_from(const OpenMeshMesh& mesh) {
  std::vector<Vec3> vertices;
  vertices.reserve(mesh.n_vertices());
  for (const auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    vertices.push_back({static_cast<double>(p[0]), static_cast<double>(p[1]),
                        static_cast<double>(p[2])});
  }
  std::vector<SurfaceDomain::Triangle> triangles;
  triangles.reserve(mesh.n_faces());
  for (const auto f : mesh.faces()) {
    SurfaceDomain::Triangle t;
    std::size_t n = 0;
    for (const auto v : mesh.fv_range(f)) {
      if (n < 3) t[n] = static_cast<std::size_t>(v.idx());
      ++n;
    }
    if (n != 3) {
      throw InvalidInput("face " + std::to_string(f.idx()) + " of the OpenMesh mesh has " +
                         std::to_string(n) +
                         " corners; a surface domain needs triangles: triangulate the mesh "
                         "first (mesh.triangulate())");
    }
    triangles.push_back(t);
  }
  return SurfaceDomain(std::move(vertices), std::move(triangles));
}

}  // namespace disktune
