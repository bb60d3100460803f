// SPDX-License-Identifier: GPL-3.0-or-later
// The weight picker that chooses the cells of the surface MPS's darts, against
// std::upper_bound over the running sums, which it must match exactly.
#include "../src/sampling/weight_picker.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "disktune/random.h"

using namespace disktune;

namespace {

// std::upper_bound over the running sums, as the sampler did before the picker.
std::size_t by_binary_search(const std::vector<double>& running, double u) {
  const auto at =
      std::upper_bound(running.begin(), running.end(), u * running.back()) - running.begin();
  return std::min<std::size_t>(static_cast<std::size_t>(at), running.size() - 1);
}

void expect_same_picks(const std::vector<double>& w, Rng& rng) {
  const detail::WeightPicker pick(w.size(), [&](std::size_t k) { return w[k]; });
  std::vector<double> us{0.0, 0.5, std::nextafter(1.0, 0.0)};
  for (int k = 0; k < 2000; ++k) us.push_back(uniform01(rng));
  // The running sums' own places and their neighbours, where rounding decides.
  std::vector<double> running;
  double total = 0;
  for (const double x : w) running.push_back(total += x);
  for (const double sum : running) {
    const double u = sum / total;
    for (const double v : {std::nextafter(u, 0.0), u, std::nextafter(u, 1.0)}) us.push_back(v);
  }
  // And the edges of the picker's n equal slices of the total (its guide's).
  for (std::size_t b = 1; b < w.size(); ++b) {
    double u = static_cast<double>(b) / static_cast<double>(w.size());
    for (int k = 0; k < 4; ++k) u = std::nextafter(u, 0.0);
    for (int k = 0; k < 9; ++k, u = std::nextafter(u, 1.0)) us.push_back(u);
  }
  for (const double u : us) {
    if (!(u >= 0 && u < 1)) continue;
    ASSERT_EQ(pick(u), by_binary_search(running, u))
        << "u = " << u << " over " << w.size() << " weights";
  }
}

}  // namespace

TEST(WeightPicker, PicksWhatABinarySearchPicks) {
  Rng rng(3);
  for (int trial = 0; trial < 40; ++trial) {
    const std::size_t n = 1 + uniform_index(rng, 3000);
    std::vector<double> w(n);
    for (double& x : w) {
      const double kind = uniform01(rng);
      // Equal weights, weights over many orders of magnitude, and zeros among them.
      x = kind < 0.3   ? 0.25
          : kind < 0.9 ? std::ldexp(uniform01(rng), -static_cast<int>(uniform_index(rng, 40)))
                       : 0.0;
    }
    if (std::all_of(w.begin(), w.end(), [](double x) { return x == 0; })) w[0] = 1;
    expect_same_picks(w, rng);
  }
}

TEST(WeightPicker, AllZeroWeightsPickTheLastAsABinarySearchDoes) {
  const std::vector<double> w(5, 0.0);
  const detail::WeightPicker pick(w.size(), [&](std::size_t k) { return w[k]; });
  EXPECT_EQ(pick(0.0), 4u);
  EXPECT_EQ(pick(0.7), 4u);
}
