// SPDX-License-Identifier: GPL-3.0-or-later
// Maximal Poisson-disk sampling of a planar domain: boundary disks, then darts on a
// background grid of the domain, then exact void filling through the void corners.
#include <algorithm>
#include <cmath>

#include "disktune/boundary.h"
#include "disktune/sampling.h"
#include "disktune/voids.h"

namespace disktune {
namespace {

struct GridCell {
  Vec2 lo;
};

// A point of the void next to the uncovered corner x: darts into the bounding box of
// the uncovered corners within r of x (the void there lies in their hull), else x.
Vec2 point_in_void(const Packing& packing, Vec2 x, Rng& rng) {
  const double r = packing.max_radius();
  std::vector<Corner> corners;
  corners_in_region(packing, x, r, {}, corners);
  Vec2 lo = x, hi = x;
  for (const Corner& c : corners) {
    lo = {std::min(lo.x, c.point.x), std::min(lo.y, c.point.y)};
    hi = {std::max(hi.x, c.point.x), std::max(hi.y, c.point.y)};
  }
  for (int t = 0; t < 16; ++t) {
    const Vec2 z{lo.x + uniform01(rng) * (hi.x - lo.x), lo.y + uniform01(rng) * (hi.y - lo.y)};
    if (packing.inside(z) && !packing.covered(z)) return z;
  }
  return x;  // on two circles, in no disk: a valid center
}

}  // namespace

Packing sample_mps(std::shared_ptr<const PlanarDomain> domain, double r, Rng& rng) {
  domain->validate_radius(r);
  Packing packing(domain->frame(), r);
  packing.set_domain(domain);
  sample_boundary(packing, *domain, r, rng);

  // Darts: cells with a diagonal below r (one disk covers a cell holding its center),
  // kept while they may hold an uncovered point of the domain.
  const double side = r / std::sqrt(2.0) * (1 - 1e-9);
  const Frame& f = domain->frame();
  const int nx = std::max(1, static_cast<int>(std::ceil(f.extent.x / side)));
  const int ny = std::max(1, static_cast<int>(std::ceil(f.extent.y / side)));
  const double half_diagonal = side / std::sqrt(2.0);
  std::vector<GridCell> active;
  for (int iy = 0; iy < ny; ++iy) {
    for (int ix = 0; ix < nx; ++ix) {
      const Vec2 lo = f.origin + Vec2{ix * side, iy * side};
      const Vec2 mid = lo + Vec2{side / 2, side / 2};
      if (domain->contains(mid) || domain->distance_to_boundary(mid) <= half_diagonal) {
        active.push_back({lo});
      }
    }
  }
  auto covered_cell = [&](const GridCell& c) {
    const Vec2 corners[4] = {c.lo, c.lo + Vec2{side, 0}, c.lo + Vec2{0, side}, c.lo + Vec2{side, side}};
    return packing.any_near(c.lo + Vec2{side / 2, side / 2}, r, [&](const Neighbor& n) {
      for (const Vec2 q : corners) {
        if (!is_covered(squared_distance(q, n.image), n.radius)) return false;
      }
      return true;
    });
  };
  for (int round = 0; round < 8 && !active.empty(); ++round) {
    const std::size_t throws = active.size();
    for (std::size_t t = 0; t < throws; ++t) {
      const GridCell& c = active[uniform_index(rng, active.size())];
      const Vec2 z = c.lo + Vec2{uniform01(rng) * side, uniform01(rng) * side};
      if (!packing.conflicts(z)) packing.insert(z, r);
    }
    active.erase(std::remove_if(active.begin(), active.end(), covered_cell), active.end());
  }

  // Exact void filling: while some disk's circle borders a void in the domain, a disk
  // goes into that void. Every disk added is checked in turn.
  std::vector<DiskId> queue = packing.ids();
  std::vector<Corner> corners;
  while (!queue.empty()) {
    const DiskId id = queue.back();
    queue.pop_back();
    if (!packing.alive(id)) continue;
    corners.clear();
    corners_on_circle(packing, id, corners);
    if (corners.empty()) continue;
    queue.push_back(id);  // look again once this void is filled
    queue.push_back(packing.insert(point_in_void(packing, corners.front().point, rng), r));
  }
  return packing;
}

}  // namespace disktune
