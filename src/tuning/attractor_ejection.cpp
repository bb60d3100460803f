// SPDX-License-Identifier: GPL-3.0-or-later
// Attractor ejection (paper, 3.1): pull each neighbour q of p as far toward p as it
// can go while still covering its own void and staying out of every disk but p's;
// then p is removed if nothing needs it any more, or moved to where it covers what
// is left, or everything goes back. The wide variant first pulls further rings of
// neighbours, each toward the disk nearer p (outer rings first), to make room.
#include <algorithm>
#include <cmath>

#include "disktune/surface_tuning.h"
#include "disktune/tuning.h"
#include "attractor_rings.h"
#include "surface_repair.h"
#include "void_repair.h"

namespace disktune {
namespace {

// How far along q + t v (t in [0, 1]) the disk at q can go, keeping its radius: it must
// keep every corner of its void within its radius (an interval of t around 0 per
// corner), and its center must not enter a disk other than `passable`'s and its own
// (the first entry bounds t) nor stay in one it lies in.
double reach_toward(const Packing& packing, DiskId passable, const Neighbor& q, Vec2 v,
                    const std::vector<Corner>& corners) {
  const double a = squared_norm(v), r = q.radius;
  double t = 1.0;
  for (const Corner& c : corners) {
    const Vec2 w = q.image - c.point;
    const double b = dot(v, w), c0 = std::min(squared_norm(w) - r * r, 0.0);
    t = std::min(t, (-b + std::sqrt(b * b - a * c0)) / a);
  }
  packing.for_each_near(q.image, std::sqrt(a) + packing.max_radius(), [&](const Neighbor& k) {
    if (k.id == passable || k.id == q.id) return;
    const Vec2 w = q.image - k.image;
    // q's center may lie in a larger disk that came later (the prior-disk rule), but
    // moved it is a new center there, whose radius may also grow past k's center.
    if (is_conflict(squared_norm(w), k.radius)) {
      t = 0;
      return;
    }
    const double b = dot(v, w), c0 = squared_norm(w) - k.radius * k.radius, disc = b * b - a * c0;
    if (disc <= 0 || b >= 0) return;  // the line misses the disk, or leads away from it
    t = std::min(t, std::max((-b - std::sqrt(disc)) / a, 0.0));
  });
  return t;
}

}  // namespace

namespace detail {

std::size_t attractor_eject(UndoLog& log, Packing& packing, DiskId p, Rng& rng, std::size_t max_removed, int rings) {
  if (max_removed == 0 || (packing.flags(p) & (kFixed | kFrozen))) return 0;
  const std::size_t mark = log.mark();
  const double r = packing.radius(p);
  const Vec2 pc = packing.center(p);
  // Each disk moves toward the one nearer p that reached it (its image as seen from
  // there), the outer rings first so that they make room; only the first ring may
  // enter p's disk.
  const auto pulls = rings_around(
      Neighbor{p, pc, 0, r}, rings,
      [&](const Neighbor& q) { return detail::mobile_neighbors(packing, q.image, q.id, rng); },
      [](const Neighbor& q) { return q.id; });

  std::vector<Corner> corners;
  for (std::size_t i = pulls.size(); i-- > 1;) {
    const Neighbor& q = pulls[i].item;
    const Neighbor& toward = pulls[pulls[i].toward].item;
    corners.clear();
    corners_in_region(packing, q.image, q.radius, {q.id}, corners);
    const Vec2 v = toward.image - q.image;
    double t = reach_toward(packing, toward.id == p ? p : kNoDisk, q, v, corners);
    // With varying radii q's radius changes on the way: where it no longer covers its
    // void, try 0.9 of the step, three times at most (6.2). Any shorter step still
    // keeps q out of the other disks. (A non-convex domain may not hold the target.)
    for (int tries = 0; tries < 3 && t > 0; ++tries, t *= 0.9) {
      const Vec2 to = q.image + v * t;
      if (packing.inside(to) && covers_all(packing, to, corners)) {
        log.move(q.id, to);  // still covers its void: no repair
        break;
      }
      if (!packing.sizing()) break;
    }
  }
  corners.clear();
  corners_in_region(packing, pc, r, {p}, corners);
  if (corners.empty()) {
    log.remove(p);  // the neighbours may now cover everything p did
    if (void_free_near(packing, pc, r)) return 1;
    log.revert_to(mark);
    return 0;
  }
  // Otherwise p goes where it alone covers its void's corners: the center of their
  // smallest enclosing circle, pushed out of a disk it landed in.
  std::vector<Vec2> points;
  for (const Corner& c : corners) points.push_back(c.point);
  const Circle mec = min_enclosing_circle(points);
  Vec2 z = mec.center;
  packing.for_each_near(z, packing.max_radius(), [&](const Neighbor& k) {
    if (k.id != p && is_conflict(k.d2, k.radius) && k.d2 > 0) {
      z = k.image + (z - k.image) * (k.radius / std::sqrt(k.d2));
    }
  });
  if (packing.conflicts(z, p) || !covers_all(packing, z, corners)) {
    log.revert_to(mark);  // no place for p: everything back
    return 0;
  }
  log.move(p, z);
  if (!void_free_near(packing, pc, r)) log.revert_to(mark);
  return 0;
}

}  // namespace detail

namespace {

// One attractor step as a single operation, for either packing kind (the surface's
// geometry is in surface_ejection.cpp): its edits in one log, which the step itself takes
// back when it fails.
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
