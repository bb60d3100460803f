// SPDX-License-Identifier: GPL-3.0-or-later
// The seeds of the sweep tests: a few in CI, more with DISKTUNE_SWEEP=full (the
// invariant sweep, tests/invariant_sweep.sh). DISKTUNE_SWEEP_SEEDS sets how many and
// DISKTUNE_SWEEP_FIRST_SEED where they start, so a long sweep splits into shards
// (seeds 1-500 on one core, 501-1000 on the other); both only with DISKTUNE_SWEEP=full.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

namespace disktune::test {

inline bool full_sweep() {
  const char* v = std::getenv("DISKTUNE_SWEEP");
  return v && std::string(v) == "full";
}

/// `ci` seeds from 1, or in the full sweep `full` of them (or DISKTUNE_SWEEP_SEEDS) from
/// DISKTUNE_SWEEP_FIRST_SEED (or 1).
inline std::vector<std::uint64_t> sweep_seeds(std::size_t ci, std::size_t full) {
  std::size_t count = ci;
  std::uint64_t first = 1;
  if (full_sweep()) {
    const char* n = std::getenv("DISKTUNE_SWEEP_SEEDS");
    const char* f = std::getenv("DISKTUNE_SWEEP_FIRST_SEED");
    count = n ? static_cast<std::size_t>(std::max(1L, std::atol(n))) : full;
    first = f ? static_cast<std::uint64_t>(std::max(1L, std::atol(f))) : 1;
  }
  std::vector<std::uint64_t> out(count);
  for (std::size_t k = 0; k < count; ++k) out[k] = first + k;
  return out;
}

}  // namespace disktune::test
