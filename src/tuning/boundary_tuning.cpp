// SPDX-License-Identifier: GPL-3.0-or-later
// 1D tuning of a planar domain's boundary disks (paper, section 7), with the interior
// repaired around every change so the packing stays conflict-free and maximal.
#include <algorithm>
#include <cmath>
#include <limits>

#include "disktune/boundary.h"
#include "void_repair.h"

namespace disktune {

void tune_boundary(Packing& packing, const PlanarDomain& domain, double spacing, Rng& rng) {
  const double r = packing.max_radius();
  const BoundaryLoops old = boundary_loops(packing, domain);
  // Where disks go, voids may open: only there does the interior need repair.
  std::vector<Vec2> lifted;
  for (const auto& loop : old) {
    for (const DiskId id : loop) {
      const Vec2 c = packing.center(id);
      const bool corner = std::any_of(domain.loops().begin(), domain.loops().end(), [&](const auto& l) {
        return std::find(l.begin(), l.end(), c) != l.end();
      });
      if (!corner) lifted.push_back(c), packing.remove(id);
    }
  }
  // Evenly spaced disks between the corners, as many as bring the spacing closest to
  // the target while staying in [r, 2r] (conflict-free, and covering the segment).
  for (const BoundarySegment& s : domain.segments()) {
    const double len = distance(s.a, s.b);
    const double lo = std::ceil(len / (2 * r) * (1 - 1e-12)), hi = std::floor(len / r * (1 + 1e-12));
    const double k = std::clamp(std::round(len / spacing), std::max(lo, 1.0), std::max(hi, 1.0));
    for (int i = 1; i < static_cast<int>(k); ++i) {
      const Vec2 x = s.a + (s.b - s.a) * (i / k);
      // Near a sharp corner or another loop, an even site may meet another boundary disk.
      const bool clash = packing.any_near(x, r, [&](const Neighbor& n) {
        return (packing.flags(n.id) & kFixed) && is_conflict(n.d2, n.radius);
      });
      if (!clash) packing.insert(x, r, kFixed);
    }
  }
  fill_boundary_voids(packing, domain, r, rng);
  // Interior disks the new boundary disks conflict with make way.
  for (const DiskId id : packing.ids()) {
    if (!(packing.flags(id) & kFixed)) continue;
    std::vector<DiskId> doomed;
    packing.for_each_near(packing.center(id), r, [&](const Neighbor& n) {
      if (!(packing.flags(n.id) & kFixed) && is_conflict(n.d2, n.radius)) doomed.push_back(n.id);
    });
    for (const DiskId d : doomed) {
      if (packing.alive(d)) lifted.push_back(packing.center(d)), packing.remove(d);
    }
  }
  detail::UndoLog log(packing);
  for (const Vec2 c : lifted) {
    detail::repair_void(log, packing, c, r, rng, std::numeric_limits<std::size_t>::max() - 1);
  }
  log.commit();
}

}  // namespace disktune
