// SPDX-License-Identifier: GPL-3.0-or-later
// How close a surface's fixed curves come to other parts of themselves (internal; the
// public side is curves_fit in surface_sizing.h, and thickness_sizing uses it).
#pragma once

#include <vector>

#include "disktune/surface_domain.h"

namespace disktune::detail {

/// At each vertex of a fixed curve, the distance to the nearest edge of a fixed curve it
/// does not meet (curves_fit in surface_sizing.h says which), or `reach` if none is closer; `reach`
/// at every other vertex.
std::vector<double> curve_clearance(const SurfaceDomain& domain, double reach);

}  // namespace disktune::detail
