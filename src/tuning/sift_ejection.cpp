// SPDX-License-Identifier: GPL-3.0-or-later
// Sifted-disks ejection (Ebeida et al., "Sifted disks", EG 2013; the paper's analogue
// of void injection): replace two overlapping disks by one placed where it alone
// covers what they covered, outside every other disk.
#include <algorithm>

#include "disktune/tuning.h"
#include "void_repair.h"

namespace disktune {
namespace {

// A point whose disk holds every corner, outside every disk, or nothing: uniform darts
// into the box around the corners' common disk D(c, r) intersection first (keeps the
// result random), then the center of their smallest enclosing circle.
bool replacement(const Packing& packing, const std::vector<Corner>& corners, Rng& rng, Vec2& z) {
  const double r = packing.max_radius();  // the box below holds every candidate
  Vec2 lo{-1e300, -1e300}, hi{1e300, 1e300};
  for (const Corner& c : corners) {
    lo = {std::max(lo.x, c.point.x - r), std::max(lo.y, c.point.y - r)};
    hi = {std::min(hi.x, c.point.x + r), std::min(hi.y, c.point.y + r)};
  }
  if (lo.x > hi.x || lo.y > hi.y) return false;
  auto fits = [&](Vec2 x) {
    return !packing.conflicts(x) && detail::covers_all(packing, x, corners);
  };
  for (int t = 0; t < 32; ++t) {
    z = {lo.x + uniform01(rng) * (hi.x - lo.x), lo.y + uniform01(rng) * (hi.y - lo.y)};
    if (fits(z)) return true;
  }
  std::vector<Vec2> points;
  for (const Corner& c : corners) points.push_back(c.point);
  const Circle mec = min_enclosing_circle(points);
  z = mec.center;
  return fits(z);
}

}  // namespace

std::size_t sift_eject(Packing& packing, DiskId p, Rng& rng, std::size_t max_removed) {
  if (max_removed == 0 || (packing.flags(p) & (kFixed | kFrozen))) return 0;
  const double r = packing.radius(p);
  const Vec2 pc = packing.center(p);
  const std::vector<Neighbor> near = detail::mobile_neighbors(packing, pc, p, rng);

  std::vector<Corner> corners;
  for (const Neighbor& q : near) {
    if (!packing.alive(q.id)) continue;
    // The void the pair leaves lies in D(p) and D(q).
    corners.clear();
    corners_in_region(packing, pc, r, {p, q.id}, corners);
    corners_in_region(packing, q.image, q.radius, {p, q.id}, corners);
    detail::UndoLog log(packing);
    log.remove(p);
    if (corners.empty()) {  // p may not be needed at all
      if (detail::void_free_near(packing, pc, r)) return 1;
      log.revert();
      continue;
    }
    log.remove(q.id);
    Vec2 z;
    if (!replacement(packing, corners, rng, z)) {
      log.revert();
      continue;
    }
    log.insert(z, packing.radius_at(z));
    // Exact check of the two regions: the corners bound the void only when its arcs
    // are short, and this does not rely on it.
    if (detail::void_free_near(packing, pc, r) && detail::void_free_near(packing, q.image, q.radius)) return 1;
    log.revert();
  }
  return 0;
}

}  // namespace disktune
