// SPDX-License-Identifier: GPL-3.0-or-later
// The thickness sizing in two steps (internal): what the surface allows at each vertex,
// measured once, and the sizing for a given r_max from it, so that a search over r_max
// (remesh's graded try) measures the surface once instead of at every step.
#pragma once

#include <vector>

#include "disktune/surface_domain.h"
#include "disktune/surface_sizing.h"

namespace disktune::detail {

/// Per vertex, the largest radius its surroundings allow: min(kFeatureShare x thickness,
/// kCurveGapShare x curve gap), counting only parts within `reach` (infinity where none
/// is; thickness_sizing.cpp says what counts).
std::vector<double> thickness_limits(const SurfaceDomain& domain, double reach);

/// thickness_sizing(domain, r_max, gradation) from limits measured with a reach of at
/// least r_max / kFeatureShare (farther parts cannot lower a radius below r_max).
SurfaceSizing thickness_sizing_from(const SurfaceDomain& domain, double r_max, const std::vector<double>& limits,
                                    double gradation = 0.2);

}  // namespace disktune::detail
