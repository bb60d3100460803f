// SPDX-License-Identifier: GPL-3.0-or-later
// Disjoint sets over 0..n-1 with path halving (internal): components and boundary loops
// of the surface domain and the surface mesh check.
#pragma once

#include <cstddef>
#include <numeric>
#include <vector>

namespace disktune::detail {

struct UnionFind {
  std::vector<std::size_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  std::size_t find(std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  /// False when a and b were already in one set.
  bool unite(std::size_t a, std::size_t b) {
    a = find(a), b = find(b);
    if (a == b) return false;
    parent[a] = b;
    return true;
  }
};

}  // namespace disktune::detail
