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
#include <string>
#include <vector>

#include "disktune/errors.h"
#include "disktune/planar_domain.h"

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

/// Constraints along every loop, refined with edges at most `size` long; Mesh_2 leaves
/// the regions of the seeds (points in the holes) unmeshed.
void refine_loops(Cdt& cdt, const std::vector<std::vector<Vec2>>& loops, const std::vector<K::Point_2>& seeds,
                  double size) {
  cdt.clear();
  for (const auto& loop : loops)
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const Vec2 a = loop[k], b = loop[(k + 1) % loop.size()];
      cdt.insert_constraint(K::Point_2(a.x, a.y), K::Point_2(b.x, b.y));
    }
  CGAL::refine_Delaunay_mesh_2(cdt, seeds.begin(), seeds.end(), Criteria(0.125, size));
}

/// A point inside each hole: the centroids of the faces of the loops' constrained
/// triangulation that the domain does not contain.
std::vector<K::Point_2> hole_seeds(const PlanarDomain& domain) {
  Cdt cdt;
  for (std::size_t l = 1; l < domain.loops().size(); ++l) {
    const auto& loop = domain.loops()[l];
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const Vec2 a = loop[k], b = loop[(k + 1) % loop.size()];
      cdt.insert_constraint(K::Point_2(a.x, a.y), K::Point_2(b.x, b.y));
    }
  }
  std::vector<K::Point_2> seeds;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    const K::Point_2 c = CGAL::centroid(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
    if (!domain.contains({c.x(), c.y()})) seeds.push_back(c);
  }
  return seeds;
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


/// Refines over the loops at the size that lands near `count` vertices (a few tries,
/// vertices growing as size^-2), then runs Lloyd.
CvtReference refine_and_smooth(const std::vector<std::vector<Vec2>>& loops, const std::vector<K::Point_2>& seeds,
                               double area, std::size_t count, int max_iterations) {
  // Start from the edge length of a hexagonal mesh with `count` vertices, then scale by
  // how far each refinement lands from the count.
  double size = std::sqrt(2 * area / (std::sqrt(3.0) * static_cast<double>(count)));
  CvtReference result;
  Cdt cdt;
  for (int attempt = 0; attempt < 4; ++attempt) {
    const auto t0 = std::chrono::steady_clock::now();
    refine_loops(cdt, loops, seeds, size);
    result.refine_seconds = seconds_since(t0);
    const double ratio = static_cast<double>(cdt.number_of_vertices()) / static_cast<double>(count);
    if (std::abs(ratio - 1) < 0.01) break;
    size *= std::sqrt(ratio);
  }
  const auto t0 = std::chrono::steady_clock::now();
  // Lloyd marks the domain again from its own seeds: the holes' too.
  if (seeds.empty()) {
    CGAL::lloyd_optimize_mesh_2(cdt, CGAL::parameters::max_iteration_number = max_iterations);
  } else {
    CGAL::lloyd_optimize_mesh_2(cdt, CGAL::parameters::max_iteration_number = max_iterations,
                                CGAL::parameters::seeds_begin = seeds.begin(),
                                CGAL::parameters::seeds_end = seeds.end());
  }
  result.lloyd_seconds = seconds_since(t0);
  result.lloyd_iterations = max_iterations;
  result.mesh = to_planar_mesh(cdt);
  return result;
}

void check_request(std::size_t count, int max_iterations) {
  if (count < 8 || max_iterations < 1) {
    throw InvalidInput("cvt_reference_mesh: need at least 8 vertices and 1 iteration; got " + std::to_string(count) +
                       " vertices, " + std::to_string(max_iterations) + " iterations");
  }
}

}  // namespace

CvtReference cvt_reference_mesh(Vec2 extent, std::size_t count, int max_iterations) {
  if (!(extent.x > 0 && extent.y > 0 && std::isfinite(extent.x) && std::isfinite(extent.y))) {
    std::ostringstream msg;
    msg << "cvt_reference_mesh: need a non-empty rectangle; got " << extent.x << " x " << extent.y;
    throw InvalidInput(msg.str());
  }
  check_request(count, max_iterations);
  const std::vector<std::vector<Vec2>> rectangle{{{0, 0}, {extent.x, 0}, {extent.x, extent.y}, {0, extent.y}}};
  return refine_and_smooth(rectangle, {}, extent.x * extent.y, count, max_iterations);
}

CvtReference cvt_reference_mesh(const PlanarDomain& domain, std::size_t count, int max_iterations) {
  check_request(count, max_iterations);
  return refine_and_smooth(domain.loops(), hole_seeds(domain), domain.area(), count, max_iterations);
}

}  // namespace disktune
