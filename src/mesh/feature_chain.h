// SPDX-License-Identifier: GPL-3.0-or-later
// The fixed disks along each sharp feature curve, in order (internal): which mesh edges
// follow a feature, so the mesh output can show the curves.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "disktune/surface_packing.h"

namespace disktune::detail {

/// Pairs of fixed disks consecutive along a feature curve of the packing's surface (a
/// closed curve's last and first too), as vertex numbers: positions in packing.ids().
std::vector<std::array<std::uint32_t, 2>> feature_neighbours(const SurfacePacking& packing);

}  // namespace disktune::detail
