// SPDX-License-Identifier: GPL-3.0-or-later
// 1D tuning of a planar domain's boundary disks (paper, section 7), with the interior
// repaired around every change so the packing stays conflict-free and maximal.
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "disktune/boundary.h"
#include "void_repair.h"

namespace disktune {

namespace {

// Parameters t in (0, 1) of the disks between the ends of segment [a, b], spaced about
// `factor` times the local radius: n steps where the integral of dt / (factor r) along
// the segment says n, at equal shares of that integral (so spacing follows r), n kept
// where each step stays within [r, 2r] for one radius.
std::vector<double> spaced_sites(const Packing& packing, Vec2 a, Vec2 b, double factor) {
  const double len = distance(a, b);
  const int pieces = 64;
  std::vector<double> cumulative(pieces + 1, 0);
  double r_min = 1e300, r_max = 0;
  for (int k = 0; k < pieces; ++k) {  // midpoint rule
    const double r = packing.radius_at(a + (b - a) * ((k + 0.5) / pieces));
    r_min = std::min(r_min, r), r_max = std::max(r_max, r);
    cumulative[k + 1] = cumulative[k] + len / pieces / (factor * r);
  }
  const double lo = std::ceil(len / (2 * r_min) * (1 - 1e-12)), hi = std::floor(len / r_max * (1 + 1e-12));
  const double fewest = std::max(lo, 1.0), most = std::max(hi, fewest);
  const double n = std::clamp(std::round(cumulative[pieces]), fewest, most);
  std::vector<double> t;
  for (int i = 1, k = 0; i < static_cast<int>(n); ++i) {
    const double share = cumulative[pieces] * i / n;
    while (cumulative[k + 1] < share) ++k;
    const double f = (share - cumulative[k]) / (cumulative[k + 1] - cumulative[k]);
    t.push_back((k + f) / pieces);
  }
  return t;
}

}  // namespace

void tune_boundary(Packing& packing, const PlanarDomain& domain, double spacing_factor, Rng& rng) {
  const BoundaryLoops old = boundary_loops(packing, domain);
  // The corners keep their disks; sorted, so each boundary disk is looked up in log time.
  std::vector<std::pair<double, double>> corners;
  for (const auto& l : domain.loops()) {
    for (const Vec2 v : l) corners.push_back({v.x, v.y});
  }
  std::sort(corners.begin(), corners.end());
  // Where disks go, voids may open: only there does the interior need repair.
  std::vector<std::pair<Vec2, double>> lifted;
  for (const auto& loop : old) {
    for (const DiskId id : loop) {
      const Vec2 c = packing.center(id);
      if (std::binary_search(corners.begin(), corners.end(), std::make_pair(c.x, c.y))) continue;
      lifted.push_back({c, packing.radius(id)});
      packing.remove(id);
    }
  }
  for (const BoundarySegment& s : domain.segments()) {
    for (const double t : spaced_sites(packing, s.a, s.b, spacing_factor)) {
      const Vec2 x = s.a + (s.b - s.a) * t;
      // Near a sharp corner or another loop, a site may meet another boundary disk.
      const double r = packing.radius_at(x);
      const bool clash = packing.any_near(x, packing.max_radius(), [&](const Neighbor& n) {
        return (packing.flags(n.id) & kFixed) && is_conflict(n.d2, std::max(r, n.radius));
      });
      if (!clash) packing.insert(x, r, kFixed);
    }
  }
  fill_boundary_voids(packing, domain, rng);
  // Interior disks the new boundary disks conflict with make way
  // (the boundary disk counts as the latest arrival: it must not lie in their disks).
  for (const DiskId id : packing.ids()) {
    if (!(packing.flags(id) & kFixed)) continue;
    std::vector<DiskId> doomed;
    packing.for_each_near(packing.center(id), packing.max_radius(), [&](const Neighbor& n) {
      if (!(packing.flags(n.id) & kFixed) && is_conflict(n.d2, std::max(n.radius, packing.radius(id)))) {
        doomed.push_back(n.id);
      }
    });
    for (const DiskId d : doomed) {
      if (packing.alive(d)) lifted.push_back({packing.center(d), packing.radius(d)}), packing.remove(d);
    }
  }
  detail::UndoLog log(packing);
  for (const auto& [c, r] : lifted) {
    detail::repair_void(log, packing, c, r, rng, std::numeric_limits<std::size_t>::max() - 1);
  }
  log.commit();
}

}  // namespace disktune
