// SPDX-License-Identifier: GPL-3.0-or-later
// The checks a set of boundary loops must pass to bound a planar domain (loop 0 the
// outer one, the others holes), each failure an InvalidInput naming loop, segment or
// vertex (0-based) and position.
#pragma once

#include <vector>

#include "disktune/geometry.h"

namespace disktune::detail {

/// Twice the signed area of a loop (positive when counterclockwise).
double twice_signed_area(const std::vector<Vec2>& loop);

/// Even-odd test of p against one closed loop; p must not lie on it.
bool inside_loop(Vec2 p, const std::vector<Vec2>& loop);

/// Throws InvalidInput unless: every loop has 3 or more finite vertices, no point is a
/// vertex twice, no loop turns back on itself, no two segments meet except consecutive
/// ones at their shared vertex, and every hole lies inside loop 0 and outside the other
/// holes. Expected O(n log n) in the number of segments.
void validate_loops(const std::vector<std::vector<Vec2>>& loops);

}  // namespace disktune::detail
