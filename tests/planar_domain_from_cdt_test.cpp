// SPDX-License-Identifier: GPL-3.0-or-later
// A planar domain from a CGAL constrained Delaunay triangulation with marked faces.
#include <gtest/gtest.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <list>

#include "disktune/cgal/planar_domain_from_cdt.h"
#include "disktune/errors.h"

namespace disktune {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Tds = CGAL::Triangulation_data_structure_2<CGAL::Delaunay_mesh_vertex_base_2<K>,
                                                 CGAL::Delaunay_mesh_face_base_2<K>>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds>;

void add_square(Cdt& cdt, double lo, double hi) {
  const K::Point_2 p[4] = {{lo, lo}, {hi, lo}, {hi, hi}, {lo, hi}};
  for (int k = 0; k < 4; ++k) cdt.insert_constraint(p[k], p[(k + 1) % 4]);
}

TEST(PlanarDomainFromCdt, TheMesherMarksASquareWithAHole) {
  Cdt cdt;
  add_square(cdt, 0, 1);
  add_square(cdt, 0.3, 0.7);
  const std::list<K::Point_2> seeds{{0.5, 0.5}};  // the hole
  CGAL::refine_Delaunay_mesh_2(cdt, seeds.begin(), seeds.end(),
                               CGAL::Delaunay_mesh_size_criteria_2<Cdt>(0.125, 0.1));
  const PlanarDomain d = planar_domain_from_cdt(cdt, [](auto f) { return f->is_in_domain(); });
  ASSERT_EQ(d.loops().size(), 2u);
  EXPECT_NEAR(d.area(), 1 - 0.16, 1e-12);
  EXPECT_TRUE(d.contains({0.1, 0.1}));
  EXPECT_FALSE(d.contains({0.5, 0.5}));
  EXPECT_FALSE(d.contains({1.1, 0.5}));
}

TEST(PlanarDomainFromCdt, NoFaceInTheDomainIsAClearError) {
  Cdt cdt;
  add_square(cdt, 0, 1);
  EXPECT_THROW(planar_domain_from_cdt(cdt, [](auto) { return false; }), InvalidInput);
}

}  // namespace
}  // namespace disktune
