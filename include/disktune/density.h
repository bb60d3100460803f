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

}  // namespace disktune
