// SPDX-License-Identifier: GPL-3.0-or-later
// The statistics composite modellers check on a fiber arrangement in a periodic cell
// (rve.h), every distance taken to the nearest periodic image and measured in fiber
// diameters D: nearest-neighbour distances (1st to 6th) and the nearest bond's
// orientation, Ripley's K and L and the pair correlation g(r), the bond-orientational
// order psi6, the Voronoi cells' area spread and the fiber fraction over windows; with the values of complete spatial
// randomness (a Poisson process of the same intensity) and of the hexagonal lattice of
// the same count beside them.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "disktune/geometry.h"
#include "disktune/periodic_box.h"
#include "disktune/quality.h"

namespace disktune {

struct FiberStatistics {
  std::size_t count = 0;
  /// D: the fibers' mean diameter, the unit of the distances below.
  double width = 0, height = 0, diameter = 0;
  /// The fibers' areas over W H: N pi (D/2)^2 / (W H) for equal fibers.
  double fiber_fraction = 0;
  /// The diameters' spread (all D for equal fibers), and their root mean square (the
  /// diameter of equal fibers of the same fraction, which the references below use).
  Statistics diameters;
  double diameter_rms = 0;
  /// The k-th nearest neighbour's distance over D (k = 1..6 at [0..5]), and their
  /// histograms (bins of 0.02 over [0, 4)).
  std::array<Statistics, 6> nearest;
  std::array<Histogram, 6> nearest_histogram;
  /// The direction of each fiber's bond to its nearest neighbour, in degrees over
  /// [0, 180) (a bond has no sense), bins of 10 degrees.
  Histogram nearest_orientation;
  /// At r_i = (i + 1) dr, in units of D, up to the smaller of 5 D and half the cell's
  /// smaller side: Ripley's K(r) = W H / (N (N - 1)) times the ordered pairs at most r
  /// apart, over D^2; L(r) = sqrt(K / pi); and g(r), the pairs in the ring (r - dr, r]
  /// over those a Poisson process would put there.
  double dr = 0.05;
  std::vector<double> r, ripley_k, ripley_l, pair_correlation;
  /// Local psi6 of a fiber: (1/6) sum of exp(6 i theta) over the bonds to its six nearest
  /// neighbours. Global: the modulus of their mean (1 for the lattice, about 1/sqrt(N)
  /// without a common orientation); then the mean modulus, the share above 0.9 (locally
  /// hexagonal), and the moduli's histogram (bins of 0.05 over [0, 1]).
  double psi6_global = 0, psi6_local_mean = 0, psi6_hexagonal_share = 0;
  Histogram psi6_local;
  /// The Voronoi cells' areas (periodic): standard deviation over mean.
  double voronoi_area_cv = 0;
  /// The local fiber fraction: square windows `side` D wide (2, 4, 8, 16, as many as fit
  /// the cell) laid edge to edge from the cell's corner, each the exact area of the
  /// fibers (and their periodic images) inside it over its own; their count, mean and
  /// spread. Where the windows tile the cell, the mean is the fiber fraction exactly.
  struct LocalFraction {
    double side = 0;
    std::size_t windows = 0;
    Statistics fraction;
  };
  std::vector<LocalFraction> local_fraction;
};

/// Fiber i of diameter diameters[i]. Throws InvalidInput for fewer than 7 fibers, not
/// one diameter per fiber, a diameter that is not finite and positive, or two coinciding
/// centers. The centers are wrapped into the cell.
FiberStatistics fiber_statistics(const PeriodicBox& cell, const std::vector<Vec2>& centers,
                                 const std::vector<double>& diameters);
/// Equal fibers of one diameter.
FiberStatistics fiber_statistics(const PeriodicBox& cell, const std::vector<Vec2>& centers, double diameter);

/// Complete spatial randomness at `intensity` points per unit area: the mean distance
/// to the k-th nearest point, Gamma(k + 1/2) / ((k - 1)! sqrt(pi intensity)).
double poisson_nearest_mean(int k, double intensity);
/// Complete spatial randomness: the standard deviation of the local fiber fraction of a
/// square window `side` wide, for fibers of `diameter` whose centers are a Poisson
/// process of `intensity` (overlaps allowed, counted twice). Campbell's theorem gives the
/// variance, intensity times the integral over all centers x of (a(x) / side^2)^2, a(x)
/// the area of the fiber at x inside the window; the integral is taken numerically
/// (midpoint rule, 256 x 256 points over the window grown by D/2).
double poisson_local_fraction_stddev(double side, double diameter, double intensity);

/// The hexagonal lattice at `intensity` (spacing sqrt(2 / (sqrt(3) intensity)), one
/// lattice point at the origin, rows along x): the local fraction of `per_row` x `per_row`
/// square windows `side` wide laid edge to edge from the origin, as fiber_statistics
/// lays them; count, and min, mean, max, stddev.
FiberStatistics::LocalFraction hexagonal_local_fraction(double side, double diameter, double intensity,
                                                         std::size_t per_row);

/// The area coefficient of variation of Poisson-Voronoi cells in the plane (sqrt of the
/// normalised area variance 0.280, a known numerical constant).
constexpr double kPoissonVoronoiAreaCv = 0.529;

}  // namespace disktune
