// SPDX-License-Identifier: GPL-3.0-or-later
// Void and repeller injection on a surface (paper, 2.1, 2.2 and 7.2): as in the plane,
// with the void points of the surface as corners, so every disk lands on the surface.
#include <cmath>

#include "disktune/surface_tuning.h"
#include "surface_repair.h"

namespace disktune {

std::size_t void_inject(SurfacePacking& packing, DiskId p, Rng& rng, std::size_t max_added) {
  if (packing.flags(p) & (kFixed | kFrozen)) return 0;
  const Vec3 c = packing.center(p);
  const double reach = detail::void_reach(packing.radius(p));
  const auto voids = detail::voids_near(packing, c, reach, {p});
  if (voids.empty()) return 0;  // no room: p's void is a point
  detail::SurfaceUndoLog log(packing);
  const SurfacePoint to = detail::void_point_choice(packing, voids, rng);
  log.move(p, to);
  if (detail::covers_all(packing, to, voids)) return 0;  // p alone covers its void from there
  const std::size_t added = detail::repair_void(log, packing, c, reach, rng, max_added);
  if (added > max_added) {
    log.revert();
    return 0;
  }
  return added;
}

namespace {

// The repeller step around p: each overlapping neighbour moves to the void point of its
// own void farthest from p, until one leaves a gap behind, which is filled.
std::size_t repel(SurfacePacking& packing, DiskId p, Rng& rng, std::size_t max_added) {
  const Vec3 c = packing.center(p);
  detail::SurfaceUndoLog log(packing);
  for (const DiskId q : detail::mobile_neighbors(packing, c, packing.radius(p), p, rng)) {
    const Vec3 from = packing.center(q);
    const double reach = detail::void_reach(packing.radius(q));
    const auto voids = detail::voids_near(packing, from, reach, {q});
    if (voids.empty()) continue;
    std::size_t far = 0;
    for (std::size_t i = 1; i < voids.size(); ++i)
      if (squared_norm(voids[i].at.p - c) > squared_norm(voids[far].at.p - c)) far = i;
    log.move(q, voids[far].at);
    const std::size_t added = detail::repair_void(log, packing, from, reach, rng, max_added);
    if (added == 0) continue;
    if (added > max_added) {
      log.revert();
      return 0;
    }
    return added;
  }
  return 0;
}

}  // namespace

std::size_t repeller_inject(SurfacePacking& packing, DiskId p, Rng& rng, std::size_t max_added) {
  if (packing.flags(p) & (kFixed | kFrozen)) return 0;
  const std::size_t added = repel(packing, p, rng, max_added);
  return added > 0 ? added : void_inject(packing, p, rng, max_added);
}

}  // namespace disktune
