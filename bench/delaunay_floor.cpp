// SPDX-License-Identifier: GPL-3.0-or-later
// The only CGAL translation unit of the benchmark (each costs ~40 s to compile).
#include "delaunay_floor.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <chrono>
#include <vector>

#include "disktune/random.h"

namespace disktune::bench {

double delaunay_seconds(std::size_t n, int reps, std::uint64_t seed) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  Rng rng(seed);
  std::vector<K::Point_2> points;
  points.reserve(n);
  for (std::size_t i = 0; i < n; ++i) points.emplace_back(uniform01(rng), uniform01(rng));
  double best = 1e300;
  for (int k = 0; k < reps; ++k) {
    const auto t0 = std::chrono::steady_clock::now();
    CGAL::Delaunay_triangulation_2<K> dt(points.begin(), points.end());
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (dt.number_of_vertices() != n) return -1;  // never: the points are distinct
    best = std::min(best, s);
  }
  return best;
}

double delaunay3_seconds(const std::vector<Vec3>& points, int reps) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<K::Point_3> cgal_points;
  cgal_points.reserve(points.size());
  for (const Vec3& p : points) cgal_points.emplace_back(p.x, p.y, p.z);
  double best = 1e300;
  for (int k = 0; k < reps; ++k) {
    const auto t0 = std::chrono::steady_clock::now();
    CGAL::Delaunay_triangulation_3<K> dt(cgal_points.begin(), cgal_points.end());
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (dt.number_of_vertices() == 0) return -1;  // never: keeps dt from being optimised away
    best = std::min(best, s);
  }
  return best;
}

}  // namespace disktune::bench
