// SPDX-License-Identifier: GPL-3.0-or-later
// Local bond-orientational order psi6 of one center (internal): the mean of
// exp(6 i theta) over the bonds to its six nearest neighbours, theta each bond's
// direction. Shared by the bond order report and the fiber statistics.
#pragma once

#include <cmath>
#include <complex>

#include "disktune/geometry.h"

namespace disktune::detail {

/// `bonds`: at least six vectors from the center to its neighbours, nearest first.
template <class Bonds>
std::complex<double> local_psi6(const Bonds& bonds) {
  std::complex<double> sum = 0;
  for (int k = 0; k < 6; ++k) sum += std::polar(1.0, 6 * std::atan2(bonds[k].y, bonds[k].x));
  return sum / 6.0;
}

}  // namespace disktune::detail
