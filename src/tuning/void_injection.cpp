// SPDX-License-Identifier: GPL-3.0-or-later
// Void injection (paper, 2.1 and 7.2), once for the plane and surfaces (space.h): lift
// p, move it to one end of its void's weighted diameter, and refill what it left.
#include "disktune/surface_tuning.h"
#include "disktune/tuning.h"
#include "space.h"

namespace disktune {
namespace {

template <class P>
std::size_t void_inject_in(P& packing, DiskId p, Rng& rng, std::size_t max_added) {
  using S = detail::Space<P>;
  if (packing.flags(p) & (kFixed | kFrozen)) return 0;
  const auto c = packing.center(p);
  const double reach = S::void_reach(packing.radius(p));
  const auto voids = S::voids_in(packing, c, reach, {p});
  if (voids.empty()) return 0;  // no room: p's void is a point
  detail::BasicUndoLog<P> log(packing);
  const auto to = S::void_choice(packing, voids, rng);
  log.move(p, to);
  // Weighted diameter below 0: p covers its whole void from there, nothing to inject.
  if (S::covers_all(packing, to, voids)) {
    if (detail::voids_on_rim<P>(to, packing.radius(p), voids) &&
        !detail::placed_void_free(log, packing))
      log.revert();
    return 0;
  }
  const std::size_t added = S::repair_void(log, packing, c, reach, rng, max_added);
  if (added > max_added || !detail::placed_void_free(log, packing)) {
    log.revert();
    return 0;
  }
  return added;
}

}  // namespace

std::size_t void_inject(Packing& packing, DiskId p, Rng& rng, std::size_t max_added) {
  return void_inject_in(packing, p, rng, max_added);
}

std::size_t void_inject(SurfacePacking& packing, DiskId p, Rng& rng, std::size_t max_added) {
  return void_inject_in(packing, p, rng, max_added);
}

}  // namespace disktune
