// SPDX-License-Identifier: GPL-3.0-or-later
// The reference every benchmark prints its ratio against.
#pragma once

#include <cstddef>
#include <cstdint>

namespace disktune::bench {

/// Seconds (best of `reps`) for CGAL's Delaunay_triangulation_2 (Epick) to triangulate
/// n uniform random points of the unit square, inserted as a range (CGAL sorts them
/// spatially first, its fastest path).
double delaunay_seconds(std::size_t n, int reps, std::uint64_t seed);

}  // namespace disktune::bench
