// SPDX-License-Identifier: GPL-3.0-or-later
// Density measures of a uniform-radius packing (paper section 4). A conflict radius r
// means non-overlapping disks of radius r/2, so the area fraction is
// eta = N pi (r/2)^2 / A; the relative radius is rho = r / r_max with
// r_max = sqrt(2A / (sqrt(3) N)), the spacing of a hexagonal lattice of N points.
// They are tied by eta = (pi / (2 sqrt 3)) rho^2.
#pragma once

#include <cstddef>

namespace disktune {

double area_fraction(std::size_t count, double r, double area);
double relative_radius(std::size_t count, double r, double area);

/// The relative radius rho = sqrt(eta 2 sqrt3 / pi) that goes with an area fraction.
double relative_radius_for(double eta);

/// The disk count whose area fraction is closest to `eta` (rounded to nearest).
std::size_t count_for_area_fraction(double eta, double r, double area);
/// The disk count whose relative radius is closest to `rho`.
std::size_t count_for_relative_radius(double rho, double r, double area);

/// The area fraction of a maximal Poisson-disk sample, measured in the periodic box
/// (docs/benchmarks.md); planar domains and surfaces come close to it.
constexpr double kMpsAreaFraction = 0.5474;

/// The radius at which `count` disks make area fraction `eta` in a domain of this area
/// (sqrt(4 A eta / (pi count))): with the default, the radius whose maximal Poisson-disk
/// sample has about `count` disks; with a target's eta, the radius at which tuning to
/// that eta gives `count` disks. Throws InvalidInput unless count >= 1, the area is
/// finite and positive and 0 < eta <= pi / (2 sqrt 3) (the hexagonal packing).
double radius_for_count(std::size_t count, double area, double eta = kMpsAreaFraction);

}  // namespace disktune
