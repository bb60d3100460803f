// SPDX-License-Identifier: GPL-3.0-or-later
// The CVT reference mesh: CGAL's Delaunay refinement and Lloyd optimizer (Mesh_2).
#include "disktune/cvt_reference.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/lloyd_optimize_mesh_2.h>

#include <chrono>
#include <cmath>
#include <map>
#include <sstream>

#include "disktune/errors.h"

namespace disktune {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Delaunay_mesh_vertex_base_2<K>;
using Fb = CGAL::Delaunay_mesh_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// The rectangle's boundary as constraints, refined with edges at most `size` long.
void refine_rectangle(Cdt& cdt, Vec2 extent, double size) {
  cdt.clear();
  const K::Point_2 c[4] = {{0, 0}, {extent.x, 0}, {extent.x, extent.y}, {0, extent.y}};
  for (int k = 0; k < 4; ++k) cdt.insert_constraint(c[k], c[(k + 1) % 4]);
  CGAL::refine_Delaunay_mesh_2(cdt, Criteria(0.125, size));
}

PlanarMesh to_planar_mesh(const Cdt& cdt) {
  PlanarMesh mesh;
  std::map<Cdt::Vertex_handle, std::uint32_t> index;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    index.emplace(v, static_cast<std::uint32_t>(mesh.vertices.size()));
    mesh.vertices.push_back({v->point().x(), v->point().y()});
    mesh.vertex_disk.push_back(kNoDisk);
  }
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_in_domain()) continue;
    mesh.triangles.push_back({index.at(f->vertex(0)), index.at(f->vertex(1)), index.at(f->vertex(2))});
  }
  return mesh;
}

}  // namespace

CvtReference cvt_reference_mesh(Vec2 extent, std::size_t count, int max_iterations) {
  if (!(extent.x > 0 && extent.y > 0 && std::isfinite(extent.x) && std::isfinite(extent.y)) ||
      count < 8 || max_iterations < 1) {
    std::ostringstream msg;
    msg << "cvt_reference_mesh: need a non-empty rectangle, at least 8 vertices and 1 "
           "iteration; got "
        << extent.x << " x " << extent.y << ", " << count << " vertices, " << max_iterations
        << " iterations";
    throw InvalidInput(msg.str());
  }
  // Start from the edge length of a hexagonal mesh with `count` vertices, then scale by
  // how far each refinement lands from the count (vertices grow as size^-2).
  const double area = extent.x * extent.y;
  double size = std::sqrt(2 * area / (std::sqrt(3.0) * static_cast<double>(count)));
  CvtReference result;
  Cdt cdt;
  for (int attempt = 0; attempt < 4; ++attempt) {
    const auto t0 = std::chrono::steady_clock::now();
    refine_rectangle(cdt, extent, size);
    result.refine_seconds = seconds_since(t0);
    const double ratio = static_cast<double>(cdt.number_of_vertices()) / static_cast<double>(count);
    if (std::abs(ratio - 1) < 0.01) break;
    size *= std::sqrt(ratio);
  }
  const auto t0 = std::chrono::steady_clock::now();
  CGAL::lloyd_optimize_mesh_2(cdt, CGAL::parameters::max_iteration_number = max_iterations);
  result.lloyd_seconds = seconds_since(t0);
  result.lloyd_iterations = max_iterations;
  result.mesh = to_planar_mesh(cdt);
  return result;
}

}  // namespace disktune
