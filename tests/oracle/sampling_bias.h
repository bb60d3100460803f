// SPDX-License-Identifier: GPL-3.0-or-later
//
// Independent check of how a sample's disks were placed. A sampler that puts a new
// center at a vertex of a void (where two circles meet) leaves that center at distance
// exactly r_j from two other disks j; a sampler that draws centers uniformly from the
// uncovered area does so with probability zero. Standard library only, written apart
// from the library (a hash of cells, then brute force among neighbours).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace oracle {

// The number of disks i for which at least two other disks j have a center at distance
// r_j from c_i, to within tol * r_j (planar samples pass z = 0). Inputs must be finite,
// radii > 0 and one per center; otherwise std::invalid_argument is thrown.
std::size_t disks_on_two_circles(const std::vector<std::array<double, 3>>& centers,
                                 const std::vector<double>& radii, double tol = 1e-9);

}  // namespace oracle
