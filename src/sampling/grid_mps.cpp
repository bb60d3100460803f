// SPDX-License-Identifier: GPL-3.0-or-later
// Maximal Poisson-disk sampling on a background grid, for planar domains and for
// spatially varying radii: boundary disks (planar), then darts on a grid of cells
// covering the domain, then exact void filling through the void corners.
#include <algorithm>
#include <cmath>

#include "disktune/boundary.h"
#include "disktune/sampling.h"
#include "disktune/sizing.h"
#include "disktune/voids.h"
#include "../voids/final_check.h"

namespace disktune {
namespace {

struct GridCell {
  Vec2 lo;
};

// A uniform point of the void next to the uncovered corner x: darts into the bounding
// box of the uncovered corners near x (the void there lies in their hull), then into ever
// smaller squares around x. Only a void thinner than a millionth of r gets its corner x,
// which would put the center on two circles (a biased spacing).
Vec2 point_in_void(const Packing& packing, Vec2 x, Rng& rng) {
  const double r = packing.radius_at(x);
  std::vector<Corner> corners;
  corners_in_region(packing, x, r, {}, corners);
  Vec2 lo = x, hi = x;
  for (const Corner& c : corners) {
    lo = {std::min(lo.x, c.point.x), std::min(lo.y, c.point.y)};
    hi = {std::max(hi.x, c.point.x), std::max(hi.y, c.point.y)};
  }
  for (double half = 0; half > 1e-6 * r || half == 0; half = (half == 0 ? r / 4 : half / 4)) {
    if (half > 0) lo = x - Vec2{half, half}, hi = x + Vec2{half, half};
    for (int t = 0; t < 16; ++t) {
      const Vec2 z{lo.x + uniform01(rng) * (hi.x - lo.x), lo.y + uniform01(rng) * (hi.y - lo.y)};
      if (packing.inside(z) && !packing.covered(z)) return z;
    }
  }
  return x;  // on two circles, in no disk: a valid center
}

// Darts and void filling into a packing set up with its frame, domain and sizing (the
// boundary disks already in, for a planar domain). `r_min` bounds the radii from below.
void fill_maximal(Packing& packing, double r_min, Rng& rng) {
  const PlanarDomain* domain = packing.domain();
  // Darts: cells with a diagonal below r_min (one disk covers a cell holding its
  // center), kept while they may hold an uncovered point of the domain.
  const double side = r_min / std::sqrt(2.0) * (1 - 1e-9);
  const Frame& f = packing.frame();
  const int nx = std::max(1, static_cast<int>(std::ceil(f.extent.x / side)));
  const int ny = std::max(1, static_cast<int>(std::ceil(f.extent.y / side)));
  const double half_diagonal = side / std::sqrt(2.0);
  std::vector<GridCell> active;
  for (int iy = 0; iy < ny; ++iy) {
    for (int ix = 0; ix < nx; ++ix) {
      const Vec2 lo = f.origin + Vec2{ix * side, iy * side};
      const Vec2 mid = lo + Vec2{side / 2, side / 2};
      if (!domain || domain->contains(mid) || domain->distance_to_boundary(mid) <= half_diagonal) {
        active.push_back({lo});
      }
    }
  }
  auto covered_cell = [&](const GridCell& c) {
    const Vec2 corners[4] = {c.lo, c.lo + Vec2{side, 0}, c.lo + Vec2{0, side}, c.lo + Vec2{side, side}};
    return packing.any_near(c.lo + Vec2{side / 2, side / 2}, packing.max_radius(), [&](const Neighbor& n) {
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
      if (!packing.conflicts(z)) packing.insert(z, packing.radius_at(z));
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
    const Vec2 z = point_in_void(packing, corners.front().point, rng);
    queue.push_back(packing.insert(z, packing.radius_at(z)));
  }
}

}  // namespace

Packing sized_packing(const Frame& frame, std::shared_ptr<const PlanarDomain> domain,
                      std::shared_ptr<const Sizing> sizing, SizingStats* stats) {
  const SizingStats measured = measure_sizing(*sizing, frame, domain.get());
  check_gradation(measured);
  if (stats) *stats = measured;
  // The grid samples r: between samples it can exceed their maximum by a little.
  Packing packing(frame, measured.upper);
  packing.set_domain(std::move(domain));
  packing.set_sizing(std::move(sizing));
  return packing;
}

Packing sample_mps(std::shared_ptr<const PlanarDomain> domain, double r, Rng& rng) {
  domain->validate_radius(r);
  Packing packing(domain->frame(), r);
  packing.set_domain(domain);
  sample_boundary(packing, *domain, rng);
  fill_maximal(packing, r, rng);
  detail::check_sample(packing);
  return packing;
}

Packing sample_mps(std::shared_ptr<const PlanarDomain> domain, std::shared_ptr<const Sizing> sizing,
                   Rng& rng) {
  SizingStats stats;
  Packing packing = sized_packing(domain->frame(), domain, std::move(sizing), &stats);
  sample_boundary(packing, *domain, rng);
  fill_maximal(packing, stats.min, rng);
  detail::check_sample(packing);
  return packing;
}

Packing sample_mps(const PeriodicBox& box, std::shared_ptr<const Sizing> sizing, Rng& rng) {
  SizingStats stats;
  Packing packing = sized_packing(box.frame(), nullptr, std::move(sizing), &stats);
  box.validate_radius(packing.max_radius());
  fill_maximal(packing, stats.min, rng);
  detail::check_sample(packing);
  return packing;
}

}  // namespace disktune
