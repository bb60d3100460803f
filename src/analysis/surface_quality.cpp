// SPDX-License-Identifier: GPL-3.0-or-later
// Shape measures of a surface mesh: the triangles' angles and circumradii in space, the
// rest shared with planar meshes (mesh_shape.h).
#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "disktune/errors.h"
#include "disktune/quality.h"
#include "mesh_shape.h"

namespace disktune {
namespace {

// The angles (degrees) at the three corners of triangle t.
std::array<double, 3> corner_angles(const SurfaceMesh& mesh,
                                    const std::array<std::uint32_t, 3>& t) {
  const Vec3 p[3] = {mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]};
  std::array<double, 3> out;
  for (int k = 0; k < 3; ++k) {
    const Vec3 u = p[(k + 1) % 3] - p[k], v = p[(k + 2) % 3] - p[k];
    out[k] = detail::corner_angle_deg(norm(cross(u, v)), dot(u, v));
  }
  return out;
}

}  // namespace

std::vector<double> smallest_angles(const SurfaceMesh& mesh) {
  std::vector<double> out;
  out.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    const auto a = corner_angles(mesh, t);
    out.push_back(std::min({a[0], a[1], a[2]}));
  }
  return out;
}

SurfaceMeshQuality measure_surface_mesh(const SurfaceMesh& mesh, const std::vector<double>& vertex_radius) {
  if (mesh.triangles.empty()) throw InvalidInput("measure_surface_mesh: the mesh has no triangles");
  if (vertex_radius.size() != mesh.vertices.size()) {
    throw InvalidInput("measure_surface_mesh: " + std::to_string(vertex_radius.size()) +
                       " radii for " + std::to_string(mesh.vertices.size()) +
                       " vertices; give one radius per vertex");
  }
  std::vector<detail::TriangleShape> shapes;
  shapes.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    for (const std::uint32_t v : t) {
      if (v >= mesh.vertices.size()) {
        throw InvalidInput("measure_surface_mesh: a triangle names vertex " + std::to_string(v) +
                           " of " + std::to_string(mesh.vertices.size()));
      }
    }
    const Vec3 p[3] = {mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]};
    detail::TriangleShape s;
    s.angles_deg = corner_angles(mesh, t);
    // R = abc / (4 area) = abc / (2 |u x v|).
    const Vec3 u = p[1] - p[0], v = p[2] - p[0];
    s.circumradius = norm(u) * norm(v) * norm(p[2] - p[1]) / (2 * norm(cross(u, v)));
    shapes.push_back(s);
  }
  const auto length = [&](std::uint32_t a, std::uint32_t b) {
    return norm(mesh.vertices[a] - mesh.vertices[b]);
  };
  return detail::mesh_quality<SurfaceMeshQuality>(
      mesh.vertices.size(), mesh.triangles.size(),
      detail::measure_mesh_shape(mesh.vertices.size(), mesh.triangles, shapes, length, vertex_radius));
}

}  // namespace disktune
