// SPDX-License-Identifier: GPL-3.0-or-later
// Six nearest neighbours of each disk from the packing's grid (the search widened until
// six are found), local psi6 from their bonds, and grains by union-find over the bonds
// between hexagonal disks of nearly one orientation.
#include "disktune/bond_order.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <utility>

#include "../domain/union_find.h"
#include "local_psi6.h"

namespace disktune {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The six nearest other disks' ids and bonds (nearest first); ties broken by id.
struct Nearest {
  std::array<std::size_t, 6> index;  // into the ids() order
  std::array<Vec2, 6> bond;
};

}  // namespace

BondOrder bond_order(const Packing& packing) {
  BondOrder order;
  const std::vector<DiskId> ids = packing.ids();
  const std::size_t n = ids.size();
  if (n < 7) return order;
  std::vector<std::size_t> index_of(packing.id_bound(), 0);
  for (std::size_t i = 0; i < n; ++i) index_of[ids[i]] = i;
  const Vec2 extent = packing.frame().extent;
  const double spacing = std::sqrt(extent.x * extent.y / static_cast<double>(n));

  std::vector<Nearest> nearest(n);
  std::vector<std::complex<double>> psi(n);
  std::vector<std::pair<double, std::pair<DiskId, Vec2>>> near;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 c = packing.center(ids[i]);
    for (double reach = 2 * spacing;; reach *= 2) {
      near.clear();
      packing.for_each_near(c, reach, [&](const Neighbor& q) {
        if (q.d2 > 0) near.push_back({q.d2, {q.id, q.image - c}});  // its own images too (a torus)
      });
      if (near.size() >= 6 || reach > 4 * std::max(extent.x, extent.y)) break;
    }
    if (near.size() < 6) return order;  // an open domain with its disks far apart
    std::partial_sort(near.begin(), near.begin() + 6, near.end(), [](const auto& a, const auto& b) {
      return a.first != b.first ? a.first < b.first : a.second.first < b.second.first;
    });
    for (int k = 0; k < 6; ++k) {
      nearest[i].index[k] = index_of[near[k].second.first];
      nearest[i].bond[k] = near[k].second.second;
    }
    psi[i] = detail::local_psi6(nearest[i].bond);
  }

  order.count = n;
  order.local.resize(n);
  order.orientation.resize(n);
  std::complex<double> sum = 0;
  std::size_t hexagonal = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sum += psi[i];
    order.local[i] = std::abs(psi[i]);
    order.psi6_local_mean += order.local[i];
    hexagonal += order.local[i] > kHexagonalPsi6;
    double angle = std::arg(psi[i]) / 6 * 180 / kPi;  // (-30, 30]
    if (angle < 0) angle += 60;
    order.orientation[i] = angle >= 60 ? 0 : angle;
  }
  order.psi6_global = std::abs(sum) / static_cast<double>(n);
  order.psi6_local_mean /= static_cast<double>(n);
  order.hexagonal_share = static_cast<double>(hexagonal) / static_cast<double>(n);

  // Grains: the orientation is defined modulo 60 degrees.
  const auto is_hexagonal = [&](std::size_t i) { return order.local[i] > kHexagonalPsi6; };
  const auto aligned = [&](std::size_t i, std::size_t j) {
    const double d = std::fabs(order.orientation[i] - order.orientation[j]);
    return std::min(d, 60 - d) < kGrainAngle;
  };
  detail::UnionFind grains(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (!is_hexagonal(i)) continue;
    for (const std::size_t j : nearest[i].index)
      if (is_hexagonal(j) && aligned(i, j)) grains.unite(i, j);
  }
  std::vector<std::size_t> size(n, 0);
  for (std::size_t i = 0; i < n; ++i)
    if (is_hexagonal(i)) ++size[grains.find(i)];
  std::vector<int> number(n, -1);
  order.grain.assign(n, -1);
  std::size_t in_grains = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!is_hexagonal(i)) continue;
    const std::size_t root = grains.find(i);
    if (size[root] < kMinGrain) continue;
    if (number[root] < 0) {
      number[root] = static_cast<int>(order.grain_count++);
      order.largest_grain = std::max(order.largest_grain, size[root]);
    }
    order.grain[i] = number[root];
    ++in_grains;
  }
  order.grain_share = static_cast<double>(in_grains) / static_cast<double>(n);
  order.grain_mean_size =
      order.grain_count ? static_cast<double>(in_grains) / static_cast<double>(order.grain_count)
                        : 0;
  return order;
}

}  // namespace disktune
