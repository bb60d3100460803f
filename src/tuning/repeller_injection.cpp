// SPDX-License-Identifier: GPL-3.0-or-later
// Repeller injection (paper, 2.2): push the disks around a repeller point away from
// it, one at a time, each to the corner of its own void farthest from the point,
// until one leaves a gap, which is filled.
#include <algorithm>

#include "disktune/tuning.h"
#include "void_repair.h"

namespace disktune {

std::size_t repel_from(Packing& packing, Vec2 point, DiskId self, Rng& rng, std::size_t max_added) {
  // The disks overlapping a disk at `point`, seen in its frame (one image each).
  const std::vector<Neighbor> near = detail::mobile_neighbors(packing, point, self, rng);
  std::vector<Corner> corners;
  for (const Neighbor& q : near) {
    const double r = q.radius;  // the region q leaves
    corners.clear();
    corners_in_region(packing, q.image, r, {q.id}, corners);
    if (corners.empty()) continue;
    // The corner of largest weighted distance w(c, point) = |c - point| - r(c) (6.1.2).
    auto w = [&](const Corner& c) { return distance(c.point, point) - packing.radius_at(c.point); };
    const auto far = std::max_element(corners.begin(), corners.end(),
                                      [&](const Corner& a, const Corner& b) { return w(a) < w(b); });
    detail::UndoLog log(packing);
    log.move(q.id, far->point);
    if (detail::covers_all(packing, far->point, corners)) continue;  // no gap opened
    const std::size_t added = detail::repair_void(log, packing, q.image, r, rng, max_added);
    if (added > max_added) {
      log.revert();
      return 0;
    }
    if (added > 0) return added;
  }
  return 0;
}

std::size_t repeller_inject(Packing& packing, DiskId p, Rng& rng, std::size_t max_added) {
  const std::size_t added = repel_from(packing, packing.center(p), p, rng, max_added);
  return added > 0 ? added : void_inject(packing, p, rng, max_added);
}

}  // namespace disktune
