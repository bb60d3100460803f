// SPDX-License-Identifier: GPL-3.0-or-later
// Lattices with known answers for the oracles' own tests (plain numbers, no library).
#pragma once

#include <algorithm>
#include <cmath>

#include "oracle/oracle.h"

namespace oracle::test {

struct Lattice {
  Box box;
  Points pts;
  double s;  // spacing
};

// Hexagonal lattice tiling the torus: m columns of spacing s = width/m, `rows` (even)
// rows at height h = s*sqrt(3)/2, odd rows shifted by s/2.
inline Lattice hex(int m, int rows, double width = 1.0) {
  const double s = width / m, h = s * std::sqrt(3.0) / 2;
  Lattice L{{width, rows * h}, {}, s};
  for (int row = 0; row < rows; ++row)
    for (int col = 0; col < m; ++col) L.pts.push_back({s * (col + 0.5 * (row % 2)), row * h});
  return L;
}

// Rectangular lattice: mx by my points with spacings sx, sy.
inline Lattice rect(int mx, int my, double sx, double sy) {
  Lattice L{{mx * sx, my * sy}, {}, std::min(sx, sy)};
  for (int y = 0; y < my; ++y)
    for (int x = 0; x < mx; ++x) L.pts.push_back({x * sx, y * sy});
  return L;
}

}  // namespace oracle::test
