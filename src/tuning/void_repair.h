// SPDX-License-Identifier: GPL-3.0-or-later
// Shared steps of the tuning operations (internal).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "disktune/random.h"
#include "disktune/voids.h"
#include "undo_log.h"

namespace disktune::detail {

/// The index, among n void points, of largest weighted diameter max_j |p_i - p_j| -
/// radius(i) (d2(i, j): the squared distance), ties within `tie` broken at random: a
/// fixed choice would add a direction bias to every injected disk. Planar corners and
/// surface void points both choose through it.
template <class Distance2, class Radius>
std::size_t weighted_diameter_index(std::size_t n, Distance2&& d2, Radius&& radius, double tie, Rng& rng) {
  std::vector<double> weighted(n, 0);
  double best = -1e300;
  for (std::size_t i = 0; i < n; ++i) {
    double far2 = 0;
    for (std::size_t j = 0; j < n; ++j) far2 = std::max(far2, d2(i, j));
    weighted[i] = std::sqrt(far2) - radius(i);
    best = std::max(best, weighted[i]);
  }
  std::vector<std::size_t> top;
  for (std::size_t i = 0; i < n; ++i) {
    if (weighted[i] >= best - tie) top.push_back(i);
  }
  return top[uniform_index(rng, top.size())];
}

/// The index, among n void points, of largest weighted distance w(c_i, point) =
/// |c_i - point| - radius(i) from a repeller point (paper, 2.2 and 6.1.2): where a
/// repelled disk goes, so that with varying radii it favours corners its new, smaller
/// disk still reaches. `distance(i)` is |c_i - point|; the first of equal ones wins.
/// Planar corners and surface void points both choose through it.
template <class Distance, class Radius>
std::size_t farthest_weighted_index(std::size_t n, Distance&& distance, Radius&& radius) {
  std::size_t best = 0;
  double best_w = -1e300;
  for (std::size_t i = 0; i < n; ++i) {
    const double w = distance(i) - radius(i);
    if (w > best_w) best = i, best_w = w;
  }
  return best;
}

/// The corner a new disk goes to (paper 2.1 and 6.1.1): the one of largest weighted
/// diameter max_j |c - c_j| - r(c), r from the packing's sizing; for one radius, an end
/// of the diameter pair. Ties (both ends, for one radius) are broken at random: a fixed
/// choice would add a direction bias to every injected disk.
Vec2 void_corner(const Packing& packing, const std::vector<Corner>& corners, Rng& rng);

/// The disks that can move (not fixed, not frozen) overlapping a disk at `point` (of
/// radius radius_at(point); for one radius: centers within 2r), except `self`: one
/// image each, seen from `point`, in random order.
std::vector<Neighbor> mobile_neighbors(const Packing& packing, Vec2 point, DiskId self, Rng& rng);

/// True when a disk centered at c (radius radius_at(c)) contains every corner: then it
/// covers the whole void they bound (a void lies in the convex hull of its corners), and
/// nothing needs repair. With one radius a corner on the circle counts (the tolerance);
/// with a sizing every corner must lie inside by 1e-7 r, because a corner left exactly
/// on a circle whose radius just changed can open a sliver of void beside it.
bool covers_all(const Packing& packing, Vec2 c, const std::vector<Corner>& corners);

/// A point whose disk (radius radius_at) holds every corner and that lies in no disk,
/// into `z`, or false: uniform darts into the box around the corners' common region first
/// (keeps the choice random), then the center of their smallest enclosing circle.
bool covering_point(const Packing& packing, const std::vector<Corner>& corners, Rng& rng, Vec2& z);

/// True when no circle of a disk that can reach D(center, r) borders a void (no
/// uncovered corner, no uncovered isolated circle). An exact local maximality check for
/// the region D(center, r) after disks there were removed; unlike the corners inside the
/// region alone, it also sees a void with no corner at all (possible when only a few
/// disks are left).
bool void_free_near(const Packing& packing, Vec2 center, double r);

/// Where disk p alone covers the corners around it (p's own disk ignored), into `z`:
/// the center of their smallest enclosing circle, pushed out of a disk it landed in;
/// false when that point conflicts or leaves a corner uncovered.
bool sole_cover_point(const Packing& packing, const std::vector<Corner>& corners, DiskId p, Vec2& z);

/// Moves neighbour q (an image of it) as far toward `to` as it can while it still covers
/// its own void and its center enters no disk but `passable`'s (attractor ejection's pull).
void pull_toward(UndoLog& log, Packing& packing, const Neighbor& q, Vec2 to, DiskId passable);

/// Restores maximality inside D(center, r) after a disk there was lifted or moved: while
/// the region holds uncovered corners, injects a disk at void_corner (paper, 2.1). Corners are the only place voids can hide: everything outside the
/// region was covered before. Returns the number injected; stops early, returning
/// max_added + 1, when more than max_added would be needed.
std::size_t repair_void(UndoLog& log, const Packing& packing, Vec2 center, double r, Rng& rng,
                        std::size_t max_added);

}  // namespace disktune::detail
