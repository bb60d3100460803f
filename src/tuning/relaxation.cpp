// SPDX-License-Identifier: GPL-3.0-or-later
// Relaxation, once for the plane and surfaces (space.h): each free disk is pulled toward
// the place where spring forces from its neighbours put it, as in bubble packing
// (Shimada and Gossard), the rest length a hexagonal spacing. A step is taken (or half,
// or a quarter of it) only where the disk meets no other and still covers what only it
// covers, so the packing stays conflict-free and maximal and its count does not change;
// what changes is its shape: the triangles of its mesh come closer to equilateral.
#include <algorithm>
#include <cmath>
#include <numeric>

#include "disktune/surface_tuning.h"
#include "disktune/tuning.h"
#include "space.h"

namespace disktune {
namespace {

// The bubble-packing force at distance w rest lengths: pushes below 1, pulls between 1
// and 1.5, nothing beyond.
double spring(double w) { return w >= 1.5 ? 0.0 : (1.25 * w - 2.375) * w * w + 1.125; }

template <class P>
bool relax_disk(P& packing, DiskId p, double spacing) {
  using S = detail::Space<P>;
  if (packing.flags(p) & (kFixed | kFrozen)) return false;
  const auto c = packing.center(p);
  const double r = packing.radius(p), rest = spacing * r;
  auto force = c - c;
  S::for_each_near(packing, c, 1.5 * rest, [&](const auto& q) {
    if (q.id == p || q.d2 <= 0) return;
    const double d = std::sqrt(q.d2);
    // A fixed disk (a boundary or a crease) only pushes: pulled toward a crease, a disk
    // can end where its Voronoi cell reaches across it.
    const double f = packing.flags(q.id) & kFixed ? std::max(spring(d / rest), 0.0) : spring(d / rest);
    force = force + (c - q.image) * (f / d);
  });
  // Half the force, at most a quarter of the rest length: steps that do not overshoot.
  auto step = S::along_surface(packing, p, force) * (0.5 * rest);
  const double length = norm(step);
  if (!(length > 1e-3 * rest)) return false;  // at rest already
  if (length > 0.25 * rest) step = step * (0.25 * rest / length);
  // What only p covers (found once, when a first step meets no disk): wherever p goes,
  // its disk must still hold all of it (a void lies in the convex hull of its points in
  // each plane, and a disk is convex).
  std::vector<typename S::VoidPoint> voids;
  bool found = false;
  for (int halvings = 0; halvings < 3; ++halvings, step = step * 0.5) {
    typename S::Point x;
    if (!S::project(packing, p, c + step, x) || packing.conflicts(S::location(x), p)) continue;
    if (!found) voids = S::voids_in(packing, c, S::void_reach(r), {p}), found = true;
    if (!S::covers_all(packing, x, voids)) continue;
    detail::BasicUndoLog<P> log(packing);
    log.move(p, x);
    // With one radius covers_all is exact; with a sizing p's radius changed on the way.
    if (S::one_radius(packing) || S::void_free_near(packing, c, r)) return true;
    log.revert();
    return false;
  }
  return false;
}

template <class P>
std::size_t relax_in(P& packing, double spacing, Rng& rng) {
  if (!(spacing > 0 && std::isfinite(spacing))) {
    throw InvalidInput("relax: the spacing must be a positive factor of the radius, got " + std::to_string(spacing));
  }
  std::vector<DiskId> order = packing.ids();
  for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[uniform_index(rng, i)]);
  std::size_t moved = 0;
  for (const DiskId p : order) moved += relax_disk(packing, p, spacing);
  return moved;
}

}  // namespace

std::size_t relax(Packing& packing, double spacing, Rng& rng) { return relax_in(packing, spacing, rng); }

std::size_t relax(SurfacePacking& packing, double spacing, Rng& rng) { return relax_in(packing, spacing, rng); }

}  // namespace disktune
