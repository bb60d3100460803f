// SPDX-License-Identifier: GPL-3.0-or-later
// A planar domain from a CGAL constrained Delaunay triangulation whose in-domain faces
// are marked, for mesh generators that already hold one (e.g. after CGAL's 2D mesher).
// The only disktune header that needs CGAL: include it where CGAL is at hand.
#pragma once

#include <array>
#include <cstddef>
#include <map>
#include <vector>

#include "disktune/planar_domain.h"

namespace disktune {

/// The domain the faces f with in_domain(f) cover (f a Face_handle of `cdt`; for
/// CGAL's Delaunay_mesh_face_base_2, `[](auto f) { return f->is_in_domain(); }`): their
/// boundary edges chained into one outer loop and holes, as planar_domain_from_triangles
/// does for a triangle mesh, and validated the same way. Every boundary vertex of those
/// faces becomes a corner.
template <class Cdt, class InDomain>
PlanarDomain planar_domain_from_cdt(const Cdt& cdt, InDomain&& in_domain) {
  std::map<typename Cdt::Vertex_handle, std::size_t> index;
  std::vector<Vec2> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!in_domain(f)) continue;
    std::array<std::size_t, 3> t;
    for (int k = 0; k < 3; ++k) {
      const auto v = f->vertex(k);
      const auto [it, added] = index.emplace(v, points.size());
      if (added) points.push_back({CGAL::to_double(v->point().x()), CGAL::to_double(v->point().y())});
      t[k] = it->second;
    }
    triangles.push_back(t);
  }
  return planar_domain_from_triangles(points, triangles);
}

}  // namespace disktune
