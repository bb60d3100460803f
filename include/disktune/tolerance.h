// SPDX-License-Identifier: GPL-3.0-or-later
// The one tolerance policy of disktune. Equality is the normal case here: injected
// disks sit exactly r from two neighbours and crystals make cocircular corners
// everywhere, so both predicates lean towards "nothing to do" by a margin relative to r.
#pragma once

namespace disktune {

/// Relative tolerance used by every conflict and coverage decision.
inline constexpr double kRelTol = 1e-9;

/// True when a center at distance `d` from a disk of radius `r` is strictly inside it,
/// by more than the tolerance: a conflict.
inline bool is_conflict(double d2, double r) {
  const double lim = r * (1.0 - kRelTol);
  return d2 < lim * lim;
}

/// True when a point at squared distance `d2` from a center of radius `r` is covered
/// (inside the closed disk, with the tolerance).
inline bool is_covered(double d2, double r) {
  const double lim = r * (1.0 + kRelTol);
  return d2 <= lim * lim;
}

}  // namespace disktune
