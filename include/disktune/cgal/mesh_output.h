// SPDX-License-Identifier: GPL-3.0-or-later
// disktune's meshes (plain arrays) into a CGAL::Surface_mesh, and a planar mesh into a
// CGAL constrained Delaunay triangulation. Header-only: include it where CGAL is at
// hand; the library itself stays free of CGAL in its public headers.
#pragma once

#include <CGAL/Dimension.h>
#include <CGAL/Surface_mesh.h>

#include <cstddef>
#include <map>
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

/// Replaces `cdt` (a CGAL::Constrained_Delaunay_triangulation_2, e.g. the one CGAL's 2D
/// mesher refines) by the triangulation of a planar mesh: its vertices, with its
/// boundary edges (those of one triangle) as constraints. Like every CGAL triangulation
/// it covers the convex hull, so each finite face f is told whether it lies in the
/// mesh's domain: in_domain(f, bool) (for Delaunay_mesh_face_base_2,
/// `[](auto f, bool in) { f->set_in_domain(in); }`). A face is inside when an odd number
/// of constraints separate it from the unbounded face (CGAL's own rule for its meshers),
/// so where four points are cocircular and the two triangulations pick different
/// diagonals, the domain is still the mesh's. Returns the vertex handle of each mesh
/// vertex, in order.
template <class Cdt, class InDomain>
std::vector<typename Cdt::Vertex_handle> copy_into(const PlanarMesh& mesh, Cdt& cdt, InDomain&& in_domain) {
  using Point = typename Cdt::Point;
  Cdt out;
  std::vector<typename Cdt::Vertex_handle> handles;
  handles.reserve(mesh.vertices.size());
  for (const Vec2 p : mesh.vertices) handles.push_back(out.insert(Point(p.x, p.y)));
  // Boundary edges: the edges of exactly one triangle.
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) ++uses[std::minmax(t[k], t[(k + 1) % 3])];
  }
  for (const auto& [edge, count] : uses) {
    if (count == 1) out.insert_constraint(handles[edge.first], handles[edge.second]);
  }
  // Nesting by flood fill from the unbounded face: a constrained edge adds one level.
  std::map<typename Cdt::Face_handle, int> level;
  std::vector<typename Cdt::Face_handle> front{out.infinite_face()}, next;
  level[out.infinite_face()] = 0;
  for (int depth = 0; !front.empty(); ++depth, front.swap(next), next.clear()) {
    while (!front.empty()) {
      const auto f = front.back();
      front.pop_back();
      for (int k = 0; k < 3; ++k) {
        const auto g = f->neighbor(k);
        if (level.count(g)) continue;
        if (out.is_constrained({f, k})) {
          next.push_back(g);
        } else {
          level[g] = depth;
          front.push_back(g);
        }
      }
    }
    for (const auto g : next) level.emplace(g, depth + 1);
  }
  cdt.swap(out);  // handles stay valid: the faces and vertices change owner, not place
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) in_domain(f, level[f] % 2 == 1);
  return handles;
}

}  // namespace disktune
