// SPDX-License-Identifier: GPL-3.0-or-later
// Whether a corner (a point x where the circles of two disks A and B meet) is covered
// by the other disks (internal). A disk that holds x strictly inside covers it. Disks
// whose circles pass through x too, within the tolerance, cover it only together with
// A and B, when they surround x: when the directions from x to their centers are not
// all in one closed half-plane. Such cocircular corners are normal (hexagonal states,
// disks placed at corners), and a corner that merely lies on a third circle can still
// open a wedge of void. Feed the other disks one by one with add().
#pragma once

#include <algorithm>
#include <cmath>

#include "disktune/geometry.h"
#include "disktune/tolerance.h"

namespace disktune::detail {

class CornerCover {
 public:
  CornerCover(Vec2 x, Vec2 a, Vec2 b) : x_(x), through_{a - x, b - x} {}

  /// Takes one other disk into account; true once x is known to be covered (strictly
  /// inside that disk), so callers can stop.
  bool add(Vec2 center, double r) {
    const double d2 = squared_distance(x_, center);
    if (!is_covered(d2, r)) return false;
    if (is_conflict(d2, r)) return strictly_ = true;
    if (n_ < kMax) through_[n_++] = center - x_;
    return false;
  }

  /// The verdict once every other disk near x was added.
  bool covered() const { return strictly_ || (n_ > 2 && !leaves_a_wedge()); }

 private:
  // True when the directions to the centers through x lie in a closed half-plane: a
  // gap between sorted angles of pi or more (up to rounding) is an uncovered wedge.
  // Exactly pi matters: two circles tangent at x with their other circles through x on
  // one side leave a void on the other (a hexagonal crystal missing the three disks in
  // a triangle of side 2r has a hole there, of circumradius 2r/sqrt3).
  bool leaves_a_wedge() const {
    constexpr double kPi = 3.14159265358979323846;
    double angle[kMax];
    for (int k = 0; k < n_; ++k) angle[k] = std::atan2(through_[k].y, through_[k].x);
    std::sort(angle, angle + n_);
    double gap = angle[0] + 2 * kPi - angle[n_ - 1];
    for (int k = 1; k < n_; ++k) gap = std::max(gap, angle[k] - angle[k - 1]);
    return gap > kPi - 1e-9;
  }

  static constexpr int kMax = 16;
  Vec2 x_;
  Vec2 through_[kMax];
  int n_ = 2;
  bool strictly_ = false;
};

}  // namespace disktune::detail
