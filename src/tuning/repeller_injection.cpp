// SPDX-License-Identifier: GPL-3.0-or-later
// Repeller injection (paper, 2.2, 6.1.2 and 7.2), once for the plane and surfaces
// (space.h): push the disks around a repeller point away from it, one at a time, each
// to the point of its own void of largest weighted distance from it, until one leaves
// a gap, which is filled.
#include "disktune/surface_tuning.h"
#include "disktune/tuning.h"
#include "space.h"

namespace disktune {
namespace {

// The disks overlapping a disk of radius r at `point`, except `self`.
template <class P>
std::size_t repel_in(P& packing, typename detail::Space<P>::Location point, double r, DiskId self, Rng& rng,
                     std::size_t max_added) {
  using S = detail::Space<P>;
  for (const auto& q : S::mobile_neighbors(packing, point, r, self, rng)) {
    const double reach = S::void_reach(q.radius);  // the region q leaves
    const auto voids = S::voids_in(packing, q.image, reach, {q.id});
    if (voids.empty()) continue;
    const std::size_t far = detail::farthest_weighted_index(
        voids.size(), [&](std::size_t i) { return norm(S::location(S::point_of(voids[i])) - point); },
        [&](std::size_t i) { return packing.radius_at(S::point_of(voids[i])); });
    detail::BasicUndoLog<P> log(packing);
    const auto to = S::point_of(voids[far]);
    log.move(q.id, to);
    if (S::covers_all(packing, to, voids)) {  // no gap opened; q stays moved
      if (detail::voids_on_rim<P>(to, q.radius, voids) && !detail::placed_void_free(log, packing))
        log.revert();
      continue;
    }
    const std::size_t added = S::repair_void(log, packing, q.image, reach, rng, max_added);
    if (added > max_added || !detail::placed_void_free(log, packing)) {
      log.revert();
      return 0;
    }
    if (added > 0) return added;
  }
  return 0;
}

// The repeller step around p's center, then void injection of p where it found no gap.
// Around a fixed or frozen p too: only its neighbours move.
template <class P>
std::size_t repeller_inject_in(P& packing, DiskId p, Rng& rng, std::size_t max_added) {
  const std::size_t added = repel_in(packing, packing.center(p), packing.radius(p), p, rng, max_added);
  return added > 0 ? added : void_inject(packing, p, rng, max_added);
}

}  // namespace

std::size_t repel_from(Packing& packing, Vec2 point, DiskId self, Rng& rng, std::size_t max_added) {
  return repel_in(packing, point, packing.radius_at(point), self, rng, max_added);
}

std::size_t repeller_inject(Packing& packing, DiskId p, Rng& rng, std::size_t max_added) {
  return repeller_inject_in(packing, p, rng, max_added);
}

std::size_t repeller_inject(SurfacePacking& packing, DiskId p, Rng& rng, std::size_t max_added) {
  return repeller_inject_in(packing, p, rng, max_added);
}

}  // namespace disktune
