// SPDX-License-Identifier: GPL-3.0-or-later
#include "radius_limits.h"

#include <cmath>
#include <sstream>

#include "disktune/errors.h"

namespace disktune::detail {

void check_radius_for_area(double r, double area, const std::string& domain) {
  if (!(std::isfinite(r) && r > 0)) {
    std::ostringstream msg;
    msg << "radius must be a finite positive number, got " << r;
    throw InvalidInput(msg.str());
  }
  // A maximal packing holds about 0.7 A / r^2 disks. Past kMaxDisks the ids and cell
  // indices would overflow, whatever the memory; below it, check_resources decides.
  const double expected = 0.7 * area / (r * r);
  if (expected > kMaxDisks) {
    std::ostringstream msg;
    msg.precision(4);
    msg << "radius " << r << " is too small for " << domain << ": a maximal packing would hold about "
        << expected << " disks, more than the " << kMaxDisks << " a packing can number; use r >= "
        << std::sqrt(0.7 * area / kMaxDisks) * 1.0001;
    throw InvalidInput(msg.str());
  }
}

}  // namespace disktune::detail
