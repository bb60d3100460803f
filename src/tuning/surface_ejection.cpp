// SPDX-License-Identifier: GPL-3.0-or-later
// Attractor ejection on a surface (paper, 3.1 and 7.2): as in the plane, with covering
// positions found among the vertices of the balls around the void points. (Sifting is
// one template for both spaces: sift_ejection.cpp.)
#include <algorithm>
#include <cmath>

#include "disktune/surface_tuning.h"
#include "attractor_rings.h"
#include "surface_repair.h"

namespace disktune {
namespace detail {
namespace {

// Moves q as close to `to` as it can while it still covers its own void and conflicts
// with no disk but `passable`'s; nothing when no covering position is closer.
void pull_toward(SurfaceUndoLog& log, SurfacePacking& packing, DiskId q, Vec3 to, DiskId passable) {
  const Vec3 cq = packing.center(q);
  const double rq = packing.radius(q);
  const auto voids = voids_near(packing, cq, void_reach(rq), {q});
  if (voids.empty()) return;
  const auto spots = covering_positions(packing, voids, cq, 2 * rq, q, passable, &to);
  const SurfacePoint* best = nullptr;
  double best_d2 = squared_norm(cq - to) * (1 - 1e-9);
  for (const SurfacePoint& s : spots) {
    const double d2 = squared_norm(s.p - to);
    if (d2 < best_d2) best = &s, best_d2 = d2;
  }
  if (!best) return;
  const std::size_t before = log.mark();
  log.move(q, *best);
  if (!void_free_near(packing, cq, rq)) log.revert_to(before);
}

}  // namespace

std::size_t attractor_eject(SurfaceUndoLog& log, SurfacePacking& packing, DiskId p, Rng& rng, std::size_t max_removed,
                            int rings) {
  if ((packing.flags(p) & (kFixed | kFrozen)) || max_removed == 0) return 0;
  const std::size_t mark = log.mark();
  const Vec3 cp = packing.center(p);
  const double rp = packing.radius(p);
  // Each disk moves as close as it can to the one nearer p that reached it, the outer
  // rings first so that they make room; the first ring may enter p's disk: p will go,
  // or move where it conflicts with none.
  const auto pulls = rings_around(
      p, rings, [&](DiskId q) { return mobile_neighbors(packing, packing.center(q), packing.radius(q), q, rng); },
      [](DiskId q) { return q; });
  for (std::size_t i = pulls.size(); i-- > 1;) {
    const DiskId toward = pulls[pulls[i].toward].item;
    pull_toward(log, packing, pulls[i].item, packing.center(toward), toward == p ? p : kNoDisk);
  }
  log.remove(p);
  const auto voids = voids_near(packing, cp, void_reach(rp));
  if (voids.empty()) return 1;
  // p's void is still there: p comes back where it covers it best, if it can.
  const auto spots = covering_positions(packing, voids, cp, 2 * rp, kNoDisk);
  if (spots.empty()) {
    log.revert_to(mark);
    return 0;
  }
  std::size_t pick = 0;
  double pick_far = 1e300;
  for (std::size_t i = 0; i < spots.size(); ++i) {
    double far = 0;
    for (const SurfaceVoidPoint& v : voids) far = std::max(far, squared_norm(v.at.p - spots[i].p));
    if (far < pick_far) pick = i, pick_far = far;
  }
  log.insert(spots[pick], 0);
  if (!void_free_near(packing, cp, rp)) log.revert_to(mark);
  return 0;
}

}  // namespace detail

// The single attractor operations (one and three rings) are in attractor_ejection.cpp.

}  // namespace disktune
