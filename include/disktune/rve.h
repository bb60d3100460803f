// SPDX-License-Identifier: GPL-3.0-or-later
// Fiber-composite cross sections (representative volume elements, RVEs): a random
// periodic arrangement of circular fibers at an exact fiber count or volume fraction,
// the application of the paper's section 8. Equal fibers of diameter D with a matrix
// gap of at least g between any two are disks of conflict radius D + g (centers at
// least that far apart); an MPS of the periodic cell at that radius is tuned to the
// count by the automatic schedule (the random phases first), so the arrangement is
// conflict-free and maximal: no room is left for one more fiber. Unequal fibers
// (diameters drawn from a law) keep centers (d_i + d_j) / 2 + g apart and leave no room
// for one more fiber of the smallest diameter: equal fibers of their mean square
// diameter are tuned to the count, then each grows to its own diameter.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "disktune/geometry.h"
#include "disktune/periodic_box.h"
#include "disktune/tuning.h"

namespace disktune {

struct RveSpec {
  /// The periodic cell, W x H.
  double width = 1, height = 1;
  /// The fibers' diameter D (their mean, for unequal fibers) and the least matrix gap g
  /// between two fibers (g >= 0).
  double diameter = 0, gap = 0;
  /// Unequal fibers: diameters from the normal law of mean D and standard deviation
  /// diameter_cv x D, redrawn beyond two standard deviations (0 <= diameter_cv <= 0.2;
  /// 0: equal fibers).
  double diameter_cv = 0;
  /// Or diameters drawn at random from this list (measured ones, say), each entry equally
  /// likely; `diameter` is then ignored.
  std::vector<double> diameter_list;
  /// The fiber count asked for; 0: the count nearest `fiber_fraction`.
  std::size_t fibers = 0;
  /// The fiber volume fraction vf = N pi (D/2)^2 / (W H) asked for, when `fibers` is 0
  /// (unequal fibers: the sum of their areas over W H, the count of the diameters drawn
  /// whose sum comes nearest).
  double fiber_fraction = 0;
  std::uint64_t seed = 1;
  /// The tuning's schedule, and a progress callback that can cancel.
  TuneOptions tune;
  /// The memory the job may use, in bytes; 0: what the process may still allocate.
  double max_memory = 0;
};

struct Rve {
  PeriodicBox cell;
  /// The fibers' mean diameter (the one diameter of equal fibers), and the gap.
  double diameter = 0, gap = 0;
  /// Fiber centers in [0, W) x [0, H); a fiber cut by the cell's edges continues in its
  /// periodic images. The arrangement is translated so that the sides of the cell lie
  /// as far as they can from the lines where a fiber boundary would touch them.
  std::vector<Vec2> centers;
  /// Fiber i's diameter (all `diameter` for equal fibers).
  std::vector<double> diameters;
  /// The fibers' areas over W H (exactly the count asked for when tuning.reached).
  double fiber_fraction = 0;
  /// The area fraction of the disks of diameter d_i + g (D + g: what the tuning counts in).
  double packing_fraction = 0;
  /// The maximal sample's fiber centers, before tuning: random sequential adsorption of
  /// the same fibers to saturation, the reference the statistics compare with; and
  /// their diameter (D; for unequal fibers, equal ones of their root mean square
  /// diameter: the same fraction).
  std::vector<Vec2> sample_centers;
  double sample_diameter = 0;
  TuneResult tuning;
};

/// The fiber count `spec` asks for (unequal fibers at a fiber fraction: the count of the
/// diameters' mean area; each arrangement's own count differs by a few). Throws
/// InvalidInput (saying what to change) for a diameter or gap that is not finite, a
/// non-positive diameter, a negative gap, fibers (with their gap) too wide for the cell
/// (the largest diameter + g must be under half its smaller side), both or neither of a
/// count and a fraction, a fraction outside (0, 1), a count above what the hexagonal
/// packing of these fibers holds (vf_max = 0.9069 (D / (D + g))^2, D the root mean square
/// diameter), or a diameter law that diameter_law (below) refuses.
std::size_t rve_fiber_count(const RveSpec& spec);

/// Makes the arrangement: an MPS at conflict radius D + g, tuned to rve_fiber_count.
/// Same spec, same fibers. Where no phase reaches the count (close to the hexagonal
/// limit) `tuning.reached` is false and the result is the closest arrangement reached,
/// still conflict-free and maximal. Unequal fibers: the diameters are drawn, equal
/// fibers of their mean square diameter are made so, then grown to their diameters (in
/// five steps, each pair pushed apart when it comes too close) and moved into any room
/// left for the smallest fiber. Throws InvalidInput when they jam or room is left: there
/// is then no valid arrangement to return (the message asks for a lower fraction, a
/// smaller gap or spread, or another seed).
Rve make_rve(const RveSpec& spec);

/// `count` independent arrangements of one spec (an ensemble, as the paper averaged four
/// RVEs): realization k has seed spec.seed + k, so it is the one make_rve gives for that
/// seed, on whichever thread it runs. They run on up to `threads` threads (0: every
/// core); spec.tune.on_progress, when set, is then called from several threads at once.
/// The memory check counts all of them running together. An exception from any
/// realization is rethrown once all have stopped.
std::vector<Rve> make_rves(const RveSpec& spec, std::size_t count, unsigned threads = 0);

}  // namespace disktune
