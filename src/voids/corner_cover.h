// SPDX-License-Identifier: GPL-3.0-or-later
// Whether a vertex x of a void's boundary (where the circles of two disks A and B meet,
// or where a circle meets an edge of a surface triangle) is covered by the other disks
// (internal). A disk that holds x strictly inside covers it. Disks whose circles pass
// through x too, within the tolerance, cover it only together with A and B, when they
// surround x: when the directions from x to their centers are not all in one closed
// half-plane. Such cocircular corners are normal (hexagonal states, disks placed at
// corners), and a corner that merely lies on a third circle can still open a wedge of
// void. On a surface triangle an edge through x counts as a direction too (its
// outward normal: what lies beyond the edge is the next triangle's to cover). Feed the
// other disks one by one with add().
#pragma once

#include <algorithm>
#include <cmath>

#include "disktune/geometry.h"
#include "disktune/tolerance.h"

namespace disktune::detail {

class CornerCover {
 public:
  /// x on the circles of the disks centered at a and b.
  CornerCover(Vec2 x, Vec2 a, Vec2 b) : x_(x) {
    through(a - x);
    through(b - x);
  }
  /// x on no circle yet: give the directions with through().
  explicit CornerCover(Vec2 x) : x_(x) {}

  /// A closed half-plane of directions from x, {d : dot(d, direction) >= 0}, that is
  /// covered next to x: toward the center of a disk whose circle passes through x, or
  /// out of a triangle across an edge through x.
  void through(Vec2 direction) {
    if (n_ < kMax) through_[n_++] = direction;
  }

  /// Takes one other disk into account; true once x is known to be covered (strictly
  /// inside that disk), so callers can stop.
  bool add(Vec2 center, double r) {
    const double d2 = squared_distance(x_, center);
    if (!is_covered(d2, r)) return false;
    if (is_conflict(d2, r)) return strictly_ = true;
    through(center - x_);
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
  int n_ = 0;
  bool strictly_ = false;
};

}  // namespace disktune::detail
