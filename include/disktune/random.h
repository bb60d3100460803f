// SPDX-License-Identifier: GPL-3.0-or-later
// The seeded generator every random choice comes from. Distributions are written here
// rather than taken from <random> so that a seed gives the same output on every
// standard library, bit for bit.
#pragma once

#include <cstdint>
#include <limits>

namespace disktune {

/// xoshiro256** (Blackman and Vigna, 2018): 256 bits of state, period 2^256 - 1, and a
/// few instructions per draw, which matters when sampling throws ~8 darts per disk.
/// The seed is spread over the state with splitmix64, as its authors recommend.
class Rng {
 public:
  using result_type = std::uint64_t;
  explicit Rng(std::uint64_t seed = 1) {
    for (std::uint64_t& s : state_) {
      seed += 0x9e3779b97f4a7c15ULL;
      std::uint64_t z = seed;
      z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
      z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
      s = z ^ (z >> 31);
    }
  }
  static constexpr result_type min() { return 0; }
  static constexpr result_type max() { return std::numeric_limits<result_type>::max(); }
  result_type operator()() {
    const std::uint64_t result = rotl(state_[1] * 5, 7) * 9;
    const std::uint64_t t = state_[1] << 17;
    state_[2] ^= state_[0];
    state_[3] ^= state_[1];
    state_[1] ^= state_[2];
    state_[0] ^= state_[3];
    state_[2] ^= t;
    state_[3] = rotl(state_[3], 45);
    return result;
  }

 private:
  static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  std::uint64_t state_[4];
};

/// Uniform double in [0, 1) with 53 random bits.
inline double uniform01(Rng& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

/// Uniform integer in [0, n), n > 0 (Lemire's multiply-shift; the bias is below 2^-32
/// for any n this library uses).
inline std::uint64_t uniform_index(Rng& rng, std::uint64_t n) {
  return static_cast<std::uint64_t>((static_cast<unsigned __int128>(rng()) * n) >> 64);
}

}  // namespace disktune
