// SPDX-License-Identifier: GPL-3.0-or-later
// The reference every benchmark prints its ratio against.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "disktune/vec3.h"

namespace disktune::bench {

/// Seconds (best of `reps`) for CGAL's Delaunay_triangulation_2 (Epick) to triangulate
/// n uniform random points of the unit square, inserted as a range (CGAL sorts them
/// spatially first, its fastest path).
double delaunay_seconds(std::size_t n, int reps, std::uint64_t seed);

/// Seconds (best of `reps`) for CGAL's Delaunay_triangulation_3 (Epick) to triangulate
/// these points, inserted as a range (spatially sorted first); the floor of the surface
/// benchmark, which passes the sample's own centers.
double delaunay3_seconds(const std::vector<Vec3>& points, int reps);

}  // namespace disktune::bench
