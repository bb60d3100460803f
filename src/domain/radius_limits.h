// SPDX-License-Identifier: GPL-3.0-or-later
// The checks of a radius every domain shares (internal): finite and positive, and not
// so small that a maximal packing of the domain could not fit in memory.
#pragma once

#include <string>

namespace disktune::detail {

/// Throws InvalidInput unless r is finite and positive and a maximal packing of a
/// domain of this area (about 0.7 A / r^2 disks) holds at most 2e8 disks; `domain`
/// names it in the message ("the 1 x 1 box", "this domain of area 0.8").
void check_radius_for_area(double r, double area, const std::string& domain);

}  // namespace disktune::detail
