// SPDX-License-Identifier: GPL-3.0-or-later
// Unequal fibers (polydisperse RVEs, beyond the paper): fiber i of diameter d_i keeps its
// center at least (d_i + d_j) / 2 + g from fiber j's, and the arrangement is maximal when
// no fiber of the smallest diameter fits anywhere: every point lies closer than
// (d_i + d_min) / 2 + g to some center i. make_rve draws the diameters, tunes equal
// fibers of the same mean square diameter to the count, then grows each fiber to its own
// diameter (private to rve.cpp).
#pragma once

#include <cstddef>
#include <vector>

#include "disktune/geometry.h"
#include "disktune/periodic_box.h"
#include "disktune/random.h"
#include "disktune/rve.h"

namespace disktune::detail {

/// The mean and the extremes of one fiber's diameter under `spec`'s distribution, and
/// the mean of its square (the truncated normal's, or the list's).
struct DiameterLaw {
  double mean = 0, smallest = 0, largest = 0, mean_square = 0;
};
/// Throws InvalidInput for a coefficient of variation outside [0, 0.2], a list entry that
/// is not finite and positive, or a list together with a coefficient.
DiameterLaw diameter_law(const RveSpec& spec);

/// The fibers' diameters: `spec.fibers` of them, or, for a fiber fraction, the count whose
/// areas sum nearest to fraction x cell area. Each from the normal law of mean
/// `spec.diameter` and standard deviation cv x diameter, redrawn beyond two standard
/// deviations, or one of `spec.diameter_list` at random.
std::vector<double> draw_diameters(const RveSpec& spec, Rng& rng);

/// Grows equal fibers, conflict-free at center distance sqrt(mean d^2) + gap, to their own
/// diameters (center i to diameters[i]) in small steps, pushing apart each pair that
/// comes closer than its distance, then moves the fibers around any room left for the
/// smallest fiber into it. True when the result is conflict-free and maximal under the
/// rule above; false when the fibers jam or room is left (the centers then hold the last
/// state, not conflict-free or not maximal).
bool grow_to_diameters(const PeriodicBox& cell, double gap, double equal, const std::vector<double>& diameters,
                       std::vector<Vec2>& centers, Rng& rng);

}  // namespace disktune::detail
