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
    if (surrounded_with_room()) return false;  // most calls: no angle needed
    constexpr double kPi = 3.14159265358979323846;
    double angle[kMax];
    for (int k = 0; k < n_; ++k) angle[k] = std::atan2(through_[k].y, through_[k].x);
    std::sort(angle, angle + n_);
    double gap = angle[0] + 2 * kPi - angle[n_ - 1];
    for (int k = 1; k < n_; ++k) gap = std::max(gap, angle[k] - angle[k - 1]);
    return gap > kPi - 1e-9;
  }

  // True when three of the directions turn one into the next (going round) by angles
  // each between 1e-6 and pi - 1e-6: the sine of each turn, their cross product over
  // their lengths, above 1e-6, all three the same way round. The three turns then make
  // one full turn, so no gap between any of the directions comes within 1e-6 of pi:
  // the sorted angles would say the same (their rounding is ~1e-16), without atan2.
  bool surrounded_with_room() const {
    constexpr double kSin2 = 1e-12;        // (1e-6)^2
    const auto turn = [&](int i, int j) {  // +1 or -1 for a turn with room, else 0
      const double c = cross(through_[i], through_[j]);
      if (c * c <= kSin2 * squared_norm(through_[i]) * squared_norm(through_[j])) return 0;
      return c > 0 ? 1 : -1;
    };
    for (int i = 0; i < n_; ++i)
      for (int j = i + 1; j < n_; ++j) {
        const int ij = turn(i, j);
        if (ij == 0) continue;
        for (int k = j + 1; k < n_; ++k)
          if (turn(j, k) == ij && turn(k, i) == ij) return true;
      }
    return false;
  }

  static constexpr int kMax = 16;
  Vec2 x_;
  Vec2 through_[kMax];
  int n_ = 0;
  bool strictly_ = false;
};

}  // namespace disktune::detail
