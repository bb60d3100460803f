// SPDX-License-Identifier: GPL-3.0-or-later
// The open boundary of a surface before tuning (the surface form of tune_boundary): its
// fixed disks are laid out again at even arc length, at about the spacing of a
// hexagonal packing of the target count, so the interior can reach that density near
// the boundary too. Interior disks the new boundary disks conflict with go, and the
// voids left behind are refilled.
#include <algorithm>
#include <cmath>

#include "disktune/surface_tuning.h"
#include "surface_repair.h"

namespace disktune {

void respace_surface_boundary(SurfacePacking& packing, double spacing_factor, Rng& rng) {
  const SurfaceDomain& d = packing.domain();
  if (d.is_closed() || !packing.sizing().is_constant()) return;
  const double r = packing.max_radius();
  // Arc steps of at least 1.05 r keep chords above r on all but sharp bends (checked
  // below); at most 1.9 r keeps every boundary point within r of a disk.
  const double step = std::clamp(spacing_factor, 1.05, 1.9) * r;
  std::vector<SurfacePoint> fresh;
  for (std::size_t l = 0; l < d.boundary_loops().size(); ++l) {
    const auto& loop = d.boundary_loops()[l];
    std::vector<double> length;
    double total = 0;
    for (std::size_t k = 0; k < loop.size(); ++k) {
      length.push_back(norm(d.vertices()[loop[(k + 1) % loop.size()]] - d.vertices()[loop[k]]));
      total += length.back();
    }
    const std::size_t n = std::max<std::size_t>(3, static_cast<std::size_t>(std::ceil(total / step)));
    const double gap = total / n;
    if (gap < 1.02 * r) return;  // a loop too short for this spacing keeps its disks
    double at = gap * uniform01(rng);  // a random phase: no loop starts at a vertex by rule
    std::size_t k = 0;
    double before = 0;  // arc length up to edge k
    for (std::size_t i = 0; i < n; ++i, at += gap) {
      while (before + length[k] < at && k + 1 < loop.size()) before += length[k++];
      fresh.push_back(packing.index().on_boundary(l, k, std::clamp((at - before) / length[k], 0.0, 1.0)));
    }
  }
  // Every pair of new boundary disks must keep r apart (sharp bends, loops that pass
  // close to each other); else the boundary stays as it is.
  for (std::size_t i = 0; i < fresh.size(); ++i)
    for (std::size_t j = i + 1; j < fresh.size(); ++j)
      if (squared_norm(fresh[i].p - fresh[j].p) < r * r * (1 + 1e-6)) return;

  detail::SurfaceUndoLog log(packing);
  std::vector<Vec3> holes;
  for (const DiskId id : packing.ids()) {
    if (packing.flags(id) & kFixed) {
      holes.push_back(packing.center(id));
      log.remove(id);
    }
  }
  for (const SurfacePoint& b : fresh) {
    std::vector<DiskId> doomed;
    packing.for_each_near(b.p, r, [&](DiskId j) {
      if (is_conflict(squared_norm(packing.center(j) - b.p), r)) doomed.push_back(j);
    });
    for (const DiskId j : doomed) {
      holes.push_back(packing.center(j));
      log.remove(j);
    }
    log.insert(b, 0, kFixed);
  }
  for (const Vec3& h : holes) detail::repair_void(log, packing, h, detail::void_reach(r), rng, packing.id_bound());
  log.commit();
}

}  // namespace disktune
