// SPDX-License-Identifier: GPL-3.0-or-later
// How far from the origin a domain or a packing can lie for its size or radius
// (internal). The exact checks
// decide within 1e-9 r (tolerance.h); a coordinate of size X is stored only to about
// X * 2.2e-16, so X / r must stay far below 1e7 for those decisions to mean anything.
// Far out (a domain at 1e10, r = 0.01: positions exact to 2e-6 = 2e-4 r) a sample came
// out with an empty interior and its own checks disagreed with it; such a packing is
// refused instead.
#pragma once

#include <cmath>
#include <sstream>
#include <string>

#include "disktune/errors.h"

namespace disktune::detail {

/// The largest coordinate over the smallest radius a packing accepts: a few units in
/// the last place there are still below 1e-9 r. Jobs near the origin stay far below it
/// (a 2e8-disk packing of a unit box has 1.7e4).
inline constexpr double kMaxCoordinateOverRadius = 1e6;

/// Throws InvalidInput when coordinates up to `reach` (in absolute value) are too far
/// from the origin for features of size `scale`, named by `what` ("the radius 0.01",
/// "the domain's size 1"); `smallest` says what to use instead, when there is a choice.
inline void check_coordinates_for_scale(double reach, double scale, const std::string& what,
                                        const std::string& instead = "") {
  if (!(reach / scale > kMaxCoordinateOverRadius)) return;
  std::ostringstream msg;
  msg.precision(3);
  msg << "the domain reaches " << reach << " from the origin, " << reach / scale << " times " << what
      << ": there a coordinate is exact only to about " << reach * 2.2e-16
      << ", too coarse for the 1e-9 r the packing's checks need; move the domain near the origin (translate "
         "it by minus its center) and translate the result back"
      << instead;
  throw InvalidInput(msg.str());
}

/// The same for a packing's smallest radius r.
inline void check_coordinates_for_radius(double reach, double r) {
  std::ostringstream what, instead;
  what << "the radius " << r;
  instead << ", or use a radius of at least " << reach / kMaxCoordinateOverRadius;
  check_coordinates_for_scale(reach, r, what.str(), instead.str());
}

}  // namespace disktune::detail
