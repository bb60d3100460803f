// SPDX-License-Identifier: GPL-3.0-or-later
// Packings with known Delaunay answers: hexagonal and square lattices that tile their
// periodic box, and random points.
#pragma once

#include <cmath>

#include "disktune/packing.h"
#include "disktune/periodic_box.h"
#include "disktune/random.h"

namespace disktune::test {

/// nx x ny hexagonal lattice of spacing a (ny even, so rows tile the box period):
/// box nx*a x ny*a*sqrt(3)/2; every disk has radius r.
inline Packing hex_lattice(int nx, int ny, double a, double r) {
  const double row = a * std::sqrt(3.0) / 2;
  Packing p(PeriodicBox(nx * a, ny * row).frame(), r);
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) p.insert({(i + 0.5 * (j % 2)) * a, j * row}, r);
  }
  return p;
}

/// nx x ny square lattice of spacing a, offset by half a cell; radius r.
inline Packing square_lattice(int nx, int ny, double a, double r) {
  Packing p(PeriodicBox(nx * a, ny * a).frame(), r);
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) p.insert({(i + 0.5) * a, (j + 0.5) * a}, r);
  }
  return p;
}

/// n uniform random points in a W x H box (a packing only in name: no spacing).
inline Packing random_points(int n, double W, double H, double r, std::uint64_t seed) {
  const PeriodicBox box(W, H);
  Rng rng(seed);
  Packing p(box.frame(), r);
  for (int k = 0; k < n; ++k) p.insert(box.random_point(rng), r);
  return p;
}

}  // namespace disktune::test
