// SPDX-License-Identifier: GPL-3.0-or-later
// Picking one of n items with a chance proportional to its weight (a cell by its area),
// in a step or two instead of a binary search.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace disktune::detail {

// For u uniform in [0, 1): the first item whose running sum of weights exceeds u times
// the total, the item std::upper_bound finds in the running sums, whatever the rounding.
// A guide (for each of n equal slices of the total, the first item the slice before it
// can fall in: a slice's worth of margin for rounding) leads there in a few steps, where
// a binary search's twenty-odd probes miss the cache once the sums outgrow it (10^6
// cells).
class WeightPicker {
 public:
  template <class Weight>
  WeightPicker(std::size_t n, Weight&& weight) : running_(n), guide_(n) {
    double total = 0;
    for (std::size_t k = 0; k < n; ++k) running_[k] = total += weight(k);
    total_ = total;
    scale_ = n > 0 && total > 0 ? static_cast<double>(n) / total : 0;
    std::size_t g = 0;  // guide_[0] = 0
    for (std::size_t b = 1; b < n; ++b) {
      while (g + 1 < n && running_[g] <= static_cast<double>(b - 1) / scale_) ++g;
      guide_[b] = static_cast<std::uint32_t>(g);
    }
  }
  /// The item for u (n must be at least one).
  std::size_t operator()(double u) const {
    const double x = u * total_;
    std::size_t g = guide_[std::min(static_cast<std::size_t>(x * scale_), guide_.size() - 1)];
    while (g < running_.size() && running_[g] <= x) ++g;
    return std::min(g, running_.size() - 1);
  }

 private:
  std::vector<double> running_;
  std::vector<std::uint32_t> guide_;
  double total_ = 0, scale_ = 0;
};

}  // namespace disktune::detail
