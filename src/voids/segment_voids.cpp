// SPDX-License-Identifier: GPL-3.0-or-later
// 1D voids: the parts of a straight boundary segment outside every disk.
#include <algorithm>
#include <cmath>

#include "disktune/vec3.h"
#include "disktune/voids.h"

namespace disktune {

std::vector<std::array<double, 2>> uncovered_on_segment(const Packing& packing, Vec2 a, Vec2 b,
                                                        bool fixed_only) {
  const Vec2 d = b - a;
  const double len = norm(d);
  // Slightly grown disks: a point within the tolerance of a circle counts as covered,
  // as everywhere else, so rounding leaves no sliver voids.
  const double reach = packing.max_radius() * (1 + kRelTol);
  std::vector<std::array<double, 2>> covered;
  // Query along the segment in pieces about r long: one query over a long segment
  // would visit the cells of its whole bounding disk.
  const int pieces = std::max(1, static_cast<int>(std::ceil(len / packing.max_radius())));
  for (int k = 0; k < pieces; ++k) {
    const Vec2 mid = a + d * ((k + 0.5) / pieces);
    packing.for_each_near(mid, 0.5 * len / pieces + reach, [&](const Neighbor& n) {
      if (fixed_only && !(packing.flags(n.id) & kFixed)) return;
      if (const auto in = segment_in_ball(a, b, n.image, n.radius * (1 + kRelTol))) covered.push_back(*in);
    });
  }
  std::sort(covered.begin(), covered.end());
  std::vector<std::array<double, 2>> gaps;
  double t = 0;
  for (const auto& c : covered) {
    if (c[0] > t) gaps.push_back({t, c[0]});
    t = std::max(t, c[1]);
  }
  if (t < 1) gaps.push_back({t, 1});
  return gaps;
}

}  // namespace disktune
