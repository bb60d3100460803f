// SPDX-License-Identifier: GPL-3.0-or-later
// Sifted-disks ejection (Ebeida et al., "Sifted disks", EG 2013; the paper's analogue
// of void injection, and 7.2 on surfaces), once for the plane and surfaces (space.h):
// a disk nothing needs goes; otherwise p and an overlapping neighbour are replaced by one
// disk placed where it alone covers what they covered, outside every other disk.
#include <algorithm>
#include <vector>

#include "disktune/surface_tuning.h"
#include "disktune/tuning.h"
#include "space.h"

namespace disktune {
namespace {

template <class P>
std::size_t sift_in(P& packing, DiskId p, Rng& rng, std::size_t max_removed) {
  using S = detail::Space<P>;
  if (max_removed == 0 || (packing.flags(p) & (kFixed | kFrozen))) return 0;
  const double r = packing.radius(p);
  const auto c = packing.center(p);
  const double reach = S::void_reach(r);
  detail::BasicUndoLog<P> log(packing);
  // p alone: the others may already cover all it did.
  const auto own = S::voids_in(packing, c, reach, {p});
  if (own.empty()) {
    log.remove(p);
    if (S::void_free_near(packing, c, r)) return 1;
    log.revert();
  }
  for (const auto& q : S::mobile_neighbors(packing, c, r, p, rng)) {
    if (!packing.alive(q.id) || S::pair_too_wide(packing, own, q)) continue;
    // The void the pair leaves lies in D(p) and D(q).
    auto voids = S::voids_in(packing, c, reach, {p, q.id});
    const auto more = S::voids_in(packing, q.image, S::void_reach(q.radius), {p, q.id});
    voids.insert(voids.end(), more.begin(), more.end());
    log.remove(p);
    if (voids.empty()) {  // p may not be needed beside q
      if (S::void_free_near(packing, c, r)) return 1;
      log.revert();
      continue;
    }
    log.remove(q.id);
    typename S::Point z;
    const double search = 0.5 * norm(c - q.image) + std::max(r, q.radius);
    if (!S::covering_point(packing, voids, (c + q.image) * 0.5, search, rng, z)) {
      log.revert();
      continue;
    }
    log.insert(z, packing.radius_at(z));
    // Exact check of the two regions: the void points bound the void only when its arcs
    // are short, and this does not rely on it; and around z (placed_void_free).
    if (S::void_free_near(packing, c, r) && S::void_free_near(packing, q.image, q.radius) &&
        detail::placed_void_free(log, packing))
      return 1;
    log.revert();
  }
  return 0;
}

}  // namespace

std::size_t sift_eject(Packing& packing, DiskId p, Rng& rng, std::size_t max_removed) {
  return sift_in(packing, p, rng, max_removed);
}

std::size_t sift_eject(SurfacePacking& packing, DiskId p, Rng& rng, std::size_t max_removed) {
  return sift_in(packing, p, rng, max_removed);
}

}  // namespace disktune
