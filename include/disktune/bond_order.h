// SPDX-License-Identifier: GPL-3.0-or-later
// Bond-orientational order of a packing's centers (issue #19): how hexagonal each disk's
// neighbourhood is (local psi6 over its six nearest neighbours), how far one
// orientation runs over the whole packing (global psi6), and the crystalline grains,
// patches of hexagonal disks that share an orientation. A maximal sample has global
// psi6 near 1/sqrt(N) and few hexagonal disks; dense tuning by crystal growth raises
// both (docs/quality.md).
#pragma once

#include <cstddef>
#include <vector>

#include "disktune/packing.h"

namespace disktune {

/// A disk is locally hexagonal when its local abs(psi6) exceeds this.
constexpr double kHexagonalPsi6 = 0.9;
/// Two hexagonal neighbours lie in one grain when their lattice orientations differ by
/// less than this many degrees.
constexpr double kGrainAngle = 10;
/// Only patches of at least this many disks count as grains.
constexpr std::size_t kMinGrain = 10;

struct BondOrder {
  std::size_t count = 0;  // disks measured (0: fewer than 7, nothing measured)
  /// The modulus of the mean local psi6: 1 for one lattice, about 1/sqrt(N) for no
  /// common orientation.
  double psi6_global = 0;
  double psi6_local_mean = 0;  // mean of the local moduli
  double hexagonal_share = 0;  // share of disks with local modulus > kHexagonalPsi6
  /// Per disk, in the order of packing.ids(): the local modulus, and the orientation of
  /// the hexagonal lattice it implies (arg(psi6) / 6, degrees in [0, 60)).
  std::vector<double> local, orientation;
  /// Grains: hexagonal disks joined through neighbour bonds (one among the other's six
  /// nearest) whose orientations differ by less than kGrainAngle, kMinGrain or more.
  std::size_t grain_count = 0, largest_grain = 0;
  double grain_mean_size = 0;
  double grain_share = 0;  // share of all disks that lie in a grain
  /// Per disk, its grain's number (0, 1, ... by first disk), or -1 outside any grain.
  std::vector<int> grain;
};

/// The bond order of the packing's live disks, each bond to a neighbour's nearest
/// image in a periodic box. Disks of an open planar domain near its boundary see a
/// one-sided neighbourhood (their local psi6 is lower). Returns count 0 for fewer than
/// 7 disks.
BondOrder bond_order(const Packing& packing);

}  // namespace disktune
