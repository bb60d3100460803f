// SPDX-License-Identifier: GPL-3.0-or-later
#include "oracle/sampling_bias.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

namespace oracle {

std::size_t disks_on_two_circles(const std::vector<std::array<double, 3>>& centers,
                                 const std::vector<double>& radii, double tol) {
  if (centers.size() != radii.size()) throw std::invalid_argument("one radius per center");
  double r_max = 0;
  for (std::size_t i = 0; i < centers.size(); ++i) {
    for (const double v : centers[i])
      if (!std::isfinite(v)) throw std::invalid_argument("a center is not finite");
    if (!(radii[i] > 0) || !std::isfinite(radii[i])) throw std::invalid_argument("a radius is not positive");
    r_max = std::max(r_max, radii[i]);
  }
  if (centers.empty()) return 0;
  // Cells of side r_max (slightly more): every disk j with |c_i - c_j| = r_j lies in one
  // of the 27 cells around c_i's.
  const double side = r_max * (1 + 2 * tol) * 1.000001;
  auto cell = [&](double v) { return static_cast<std::int64_t>(std::floor(v / side)); };
  auto key = [](std::int64_t i, std::int64_t j, std::int64_t k) {
    return (static_cast<std::uint64_t>(i & 0x1fffff) << 42) | (static_cast<std::uint64_t>(j & 0x1fffff) << 21) |
           static_cast<std::uint64_t>(k & 0x1fffff);
  };
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells;
  for (std::size_t i = 0; i < centers.size(); ++i)
    cells[key(cell(centers[i][0]), cell(centers[i][1]), cell(centers[i][2]))].push_back(i);
  std::size_t count = 0;
  for (std::size_t i = 0; i < centers.size(); ++i) {
    const auto& c = centers[i];
    int on = 0;
    for (std::int64_t a = -1; a <= 1 && on < 2; ++a)
      for (std::int64_t b = -1; b <= 1 && on < 2; ++b)
        for (std::int64_t e = -1; e <= 1 && on < 2; ++e) {
          const auto it = cells.find(key(cell(c[0]) + a, cell(c[1]) + b, cell(c[2]) + e));
          if (it == cells.end()) continue;
          for (const std::size_t j : it->second) {
            if (j == i) continue;
            const double d = std::hypot(c[0] - centers[j][0], c[1] - centers[j][1], c[2] - centers[j][2]);
            if (std::abs(d - radii[j]) <= tol * radii[j]) ++on;
          }
        }
    if (on >= 2) ++count;
  }
  return count;
}

}  // namespace oracle
