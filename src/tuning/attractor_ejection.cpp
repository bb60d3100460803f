// SPDX-License-Identifier: GPL-3.0-or-later
// Attractor ejection (paper, 3.1), once for the plane and surfaces (space.h): pull each
// neighbour q of p as close to p as it can go while still covering its own void and
// staying out of every disk but p's; then p is removed if nothing needs it any more,
// or moved to where it alone covers what is left, or everything goes back. The wide
// variant first pulls further rings of neighbours, each toward the disk nearer p
// (outer rings first), to make room.
#include "disktune/surface_tuning.h"
#include "disktune/tuning.h"
#include "attractor_rings.h"
#include "space.h"

namespace disktune {
namespace detail {

template <class P>
std::size_t attractor_eject(BasicUndoLog<P>& log, P& packing, DiskId p, Rng& rng, std::size_t max_removed, int rings) {
  using S = Space<P>;
  using Near = typename S::Near;
  if (max_removed == 0 || (packing.flags(p) & (kFixed | kFrozen))) return 0;
  const std::size_t mark = log.mark();
  const double r = packing.radius(p);
  const auto pc = packing.center(p);
  // Each disk moves toward the one nearer p that reached it (on the torus, its image
  // as seen from there), the outer rings first so that they make room; only the first
  // ring may enter p's disk: p will go, or move where it conflicts with none.
  const auto pulls = rings_around(
      Near{p, pc, 0, r}, rings,
      [&](const Near& q) { return S::mobile_neighbors(packing, q.image, q.radius, q.id, rng); },
      [](const Near& q) { return q.id; });
  for (std::size_t i = pulls.size(); i-- > 1;) {
    const Near& toward = pulls[pulls[i].toward].item;
    S::pull_toward(log, packing, pulls[i].item, toward.image, toward.id == p ? p : kNoDisk);
  }
  // The pulls kept the packing maximal, so what lifting p leaves lies in p's disk and
  // its void points bound it. None: the neighbours now cover everything p did (the scan
  // just made is the one its removal would be checked by).
  const auto voids = S::voids_in(packing, pc, S::void_reach(r), {p});
  if (voids.empty()) {
    log.remove(p);
    return 1;
  }
  typename S::Point z;
  if (!S::sole_cover_point(packing, voids, p, pc, r, z)) {
    log.revert_to(mark);  // no place for p: everything back
    return 0;
  }
  const std::size_t moved = log.mark();
  log.move(p, z);
  // At z p covers all of its void points (covers_all), so only a crossing on its new
  // rim can be open: the check around z (placed_void_free); the pulls checked their own.
  if (!placed_void_free(log, packing, moved)) log.revert_to(mark);
  return 0;
}

template std::size_t attractor_eject(UndoLog&, Packing&, DiskId, Rng&, std::size_t, int);
template std::size_t attractor_eject(SurfaceUndoLog&, SurfacePacking&, DiskId, Rng&, std::size_t, int);

}  // namespace detail

namespace {

// One attractor step as a single operation: its edits in one log, which the step
// itself takes back when it fails.
template <class P>
std::size_t attract(P& packing, DiskId p, Rng& rng, std::size_t max_removed, int rings) {
  detail::BasicUndoLog<P> log(packing);
  return detail::attractor_eject(log, packing, p, rng, max_removed, rings);
}

}  // namespace

std::size_t attractor_eject(Packing& packing, DiskId p, Rng& rng, std::size_t max_removed) {
  return attract(packing, p, rng, max_removed, 1);
}
std::size_t wide_attractor_eject(Packing& packing, DiskId p, Rng& rng, std::size_t max_removed) {
  return attract(packing, p, rng, max_removed, detail::kWideAttractorRings);
}
std::size_t attractor_eject(SurfacePacking& packing, DiskId p, Rng& rng, std::size_t max_removed) {
  return attract(packing, p, rng, max_removed, 1);
}
std::size_t wide_attractor_eject(SurfacePacking& packing, DiskId p, Rng& rng, std::size_t max_removed) {
  return attract(packing, p, rng, max_removed, detail::kWideAttractorRings);
}

}  // namespace disktune
