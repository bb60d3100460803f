// SPDX-License-Identifier: GPL-3.0-or-later
// The seeded generator every random choice comes from. Distributions are written here
// rather than taken from <random> so that a seed gives the same output on every
// standard library, bit for bit.
#pragma once

#include <cstdint>
#include <random>

namespace disktune {

using Rng = std::mt19937_64;

/// Uniform double in [0, 1) with 53 random bits.
inline double uniform01(Rng& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

/// Uniform integer in [0, n), n > 0 (Lemire's multiply-shift; the bias is below 2^-32
/// for any n this library uses).
inline std::uint64_t uniform_index(Rng& rng, std::uint64_t n) {
  return static_cast<std::uint64_t>((static_cast<unsigned __int128>(rng()) * n) >> 64);
}

}  // namespace disktune
