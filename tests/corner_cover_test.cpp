// SPDX-License-Identifier: GPL-3.0-or-later
// CornerCover's verdict on the directions through a corner, against the definition
// computed apart: the corner is covered when the largest angle between neighbouring
// directions (going round) is below pi - 1e-9, here in long double.
#include "../src/voids/corner_cover.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace {

using disktune::Vec2;

constexpr long double kPi = 3.141592653589793238462643383279502884L;

bool covered_by_definition(const std::vector<Vec2>& directions) {
  if (directions.size() < 3) return false;
  std::vector<long double> angle;
  for (const Vec2& d : directions) angle.push_back(std::atan2(static_cast<long double>(d.y), d.x));
  std::sort(angle.begin(), angle.end());
  long double widest = angle.front() + 2 * kPi - angle.back();
  for (std::size_t k = 1; k < angle.size(); ++k) widest = std::max(widest, angle[k] - angle[k - 1]);
  return widest <= kPi - 1e-9L;
}

bool covered_by_corner_cover(const std::vector<Vec2>& directions) {
  disktune::detail::CornerCover cover(Vec2{0.25, -0.5});
  for (const Vec2& d : directions) cover.through(d);
  return cover.covered();
}

Vec2 at_angle(double a, double length) { return {length * std::cos(a), length * std::sin(a)}; }

// Random directions of random lengths, three to six of them, most with one gap near pi
// (below or above it by 1e-3 down to 1e-8, or short of it by less than the tolerance,
// where the verdict turns), and the rest anywhere.
TEST(CornerCover, SaysCoveredExactlyWhenNoGapBetweenTheDirectionsComesToPi) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0, 1);
  int covered = 0, open = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const int n = 3 + static_cast<int>(unit(rng) * 4);
    const double start = 2 * M_PI * unit(rng);
    std::vector<Vec2> directions;
    if (trial % 5 == 0) {
      for (int k = 0; k < n; ++k)
        directions.push_back(at_angle(2 * M_PI * unit(rng), 0.01 + unit(rng)));
    } else {
      // One gap of pi + offset from `start`; the others spread over the rest. The last
      // kind of offset lies within the tolerance below pi (3e-10 to 7e-10 short of
      // it): still a wedge, by the definition.
      const double scale[] = {1e-3, 1e-5, 1e-8};
      const double offset =
          trial % 5 == 4 ? -(3e-10 + 4e-10 * unit(rng))
                         : (unit(rng) < 0.5 ? -1 : 1) * scale[trial % 5 - 1] * (1 + unit(rng));
      const double gap = M_PI + offset;
      directions.push_back(at_angle(start, 0.01 + unit(rng)));
      for (int k = 1; k < n; ++k)
        directions.push_back(at_angle(
            start + gap + (2 * M_PI - gap) * (k - 1) / (n - 1.0) * unit(rng), 0.01 + unit(rng)));
    }
    std::shuffle(directions.begin(), directions.end(), rng);
    const bool expected = covered_by_definition(directions);
    ASSERT_EQ(covered_by_corner_cover(directions), expected) << "trial " << trial;
    (expected ? covered : open)++;
  }
  EXPECT_GT(covered, 4000);  // both verdicts well represented
  EXPECT_GT(open, 4000);
}

// Exact cases: a hexagonal corner's directions, and those that leave exactly a half
// plane open (two opposite directions with others on one side), or nothing.
TEST(CornerCover, ExactHalfPlanesAreOpenAndThreeEvenlySpacedDirectionsCover) {
  const double third = 2 * M_PI / 3;
  EXPECT_TRUE(
      covered_by_corner_cover({at_angle(0, 1), at_angle(third, 1), at_angle(2 * third, 1)}));
  EXPECT_TRUE(covered_by_corner_cover({{1, 0}, {0, 1}, {-1, 0}, {0, -1}}));
  EXPECT_FALSE(covered_by_corner_cover({{1, 0}, {0, 1}, {-1, 0}}));          // gap exactly pi
  EXPECT_FALSE(covered_by_corner_cover({{1, 0}, {1, 1}, {0, 1}, {-1, 1}}));  // all in one half
  EXPECT_FALSE(covered_by_corner_cover({{1, 0}, {-1, 0}}));                  // two cover no corner
  // A gap short of pi by less than the tolerance still leaves a wedge.
  EXPECT_FALSE(covered_by_corner_cover(
      {at_angle(0, 1), at_angle(M_PI - 5e-10, 1), at_angle(1.5 * M_PI, 1)}));
  EXPECT_TRUE(
      covered_by_corner_cover({at_angle(0, 1), at_angle(M_PI - 1e-8, 1), at_angle(1.5 * M_PI, 1)}));
}

}  // namespace
