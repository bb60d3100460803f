// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <sstream>

#include "../domain/point_text.h"
#include "../geometry/threads.h"
#include "corner_cover.h"
#include "disktune/errors.h"
#include "disktune/voids.h"
#include "packing_checks.h"

namespace disktune {
namespace {


// True when the corner x of the circles of a and b (indices i and j in `near`, if there)
// is covered by the other disks of `near`; other images of a and b do count.
bool corner_covered(const std::vector<Neighbor>& near, Vec2 x, Vec2 a, Vec2 b, std::size_t i,
                    std::size_t j) {
  detail::CornerCover cover(x, a, b);
  for (std::size_t k = 0; k < near.size(); ++k) {
    if (k != i && k != j && cover.add(near[k].image, near[k].radius)) return true;
  }
  return cover.covered();
}

// True when some disk of `near` (other than index i) covers the point x.
bool covered_by_others(const std::vector<Neighbor>& near, Vec2 x, std::size_t i) {
  for (std::size_t k = 0; k < near.size(); ++k) {
    if (k != i && is_covered(squared_distance(x, near[k].image), near[k].radius)) return true;
  }
  return false;
}

bool contains(const std::vector<DiskId>& ids, DiskId id) {
  return std::find(ids.begin(), ids.end(), id) != ids.end();
}

// In a planar domain, a point of the boundary no disk covers, if any. Together with
// the corners inside the domain this decides maximality: a void that reaches no
// boundary point is bounded by circles alone, so it has a corner in the domain.
std::optional<Vec2> uncovered_boundary_point(const Packing& packing) {
  if (!packing.domain()) return std::nullopt;
  for (const BoundarySegment& s : packing.domain()->segments()) {
    const auto gaps = uncovered_on_segment(packing, s.a, s.b, false);
    if (!gaps.empty()) return s.a + (s.b - s.a) * (0.5 * (gaps[0][0] + gaps[0][1]));
  }
  return std::nullopt;
}

}  // namespace

void corners_on_circle(const Packing& packing, DiskId p, std::vector<Corner>& out) {
  const Vec2 c = packing.center(p);
  const double r = packing.radius(p);
  // Only disks within r + r_max can meet p's circle or cover a point of it.
  std::vector<Neighbor> near;
  near.reserve(24);
  packing.for_each_near(c, (r + packing.max_radius()) * (1 + 2 * kRelTol), [&](const Neighbor& n) {
    if (!(n.id == p && n.d2 == 0.0)) near.push_back(n);
  });
  const std::size_t none = near.size();  // p is not in `near`: index "none" stands for it
  bool met = false;
  for (std::size_t i = 0; i < near.size(); ++i) {
    const CircleIntersection x = intersect_circles(c, r, near[i].image, near[i].radius);
    met = met || x.count > 0;
    for (int k = 0; k < x.count; ++k) {
      if (packing.inside(x.points[k]) && !corner_covered(near, x.points[k], c, near[i].image, i, none)) {
        out.push_back({x.points[k], p, near[i].id});
      }
    }
  }
  if (!met) {  // the void surrounds p: any uncovered point of its circle in the domain
    for (const Vec2 dir : {Vec2{1, 0}, Vec2{0, 1}, Vec2{-1, 0}, Vec2{0, -1}}) {
      const Vec2 probe = c + dir * r;
      if (packing.inside(probe) && !covered_by_others(near, probe, none)) {
        out.push_back({probe, p, kNoDisk});
        break;
      }
    }
  }
}

void corners_in_region(const Packing& packing, Vec2 center, double R,
                       const std::vector<DiskId>& ignore, std::vector<Corner>& out) {
  std::vector<Neighbor> near;
  near.reserve(32);
  const double rmax = packing.max_radius();
  packing.for_each_near(center, (R + rmax) * (1 + 2 * kRelTol), [&](const Neighbor& n) {
    if (!contains(ignore, n.id)) near.push_back(n);
  });
  // Nearest first: the disks closest to the region cover most of it, so coverage tests
  // stop early.
  std::sort(near.begin(), near.end(), [](const Neighbor& a, const Neighbor& b) { return a.d2 < b.d2; });
  const double lim = R * (1 + kRelTol);
  for (std::size_t i = 0; i < near.size(); ++i) {
    for (std::size_t j = i + 1; j < near.size(); ++j) {
      // The cheap test first: it drops about half the pairs of a dense packing's region.
      if (too_far_apart_to_meet(squared_distance(near[i].image, near[j].image), near[i].radius + near[j].radius))
        continue;
      if (!intersections_may_lie_in(near[i].image, near[i].radius, near[j].image, near[j].radius,
                                    center, lim)) {
        continue;
      }
      const CircleIntersection x =
          intersect_circles(near[i].image, near[i].radius, near[j].image, near[j].radius);
      for (int k = 0; k < x.count; ++k) {
        const Vec2 pt = x.points[k];
        if (squared_distance(pt, center) <= lim * lim && packing.inside(pt) &&
            !corner_covered(near, pt, near[i].image, near[j].image, i, j)) {
          out.push_back({pt, near[i].id, near[j].id});
        }
      }
    }
  }
}

namespace detail {

namespace {

// A disk conflicting with disk `id`, or kNoDisk.
DiskId conflicting_disk(const Packing& packing, DiskId id) {
  const double r = packing.radius(id);
  DiskId other = kNoDisk;
  packing.any_near(packing.center(id), r, [&](const Neighbor& n) {
    if (n.id != id && is_conflict(n.d2, std::min(r, n.radius))) other = n.id;
    return other != kNoDisk;
  });
  return other;
}

}  // namespace

// Disk by disk on every core, the first in id order reported (the check reads only).
std::optional<std::array<DiskId, 2>> first_conflict(const Packing& packing) {
  const std::vector<DiskId> ids = packing.ids();
  const std::size_t i = first_index(ids.size(), thread_count(0), [&](std::size_t k) {
    return conflicting_disk(packing, ids[k]) != kNoDisk;
  });
  if (i == ids.size()) return std::nullopt;
  return std::array<DiskId, 2>{ids[i], conflicting_disk(packing, ids[i])};
}

std::optional<std::string> first_hole(const Packing& packing) {
  if (packing.empty()) return "the whole domain";
  if (const auto hole = uncovered_boundary_point(packing)) return "the boundary point " + point_text(*hole);
  const std::vector<DiskId> ids = packing.ids();
  const std::size_t i = first_index(ids.size(), thread_count(0), [&](std::size_t k) {
    thread_local std::vector<Corner> corners;
    corners.clear();
    corners_on_circle(packing, ids[k], corners);
    return !corners.empty();
  });
  if (i == ids.size()) return std::nullopt;
  std::vector<Corner> corners;
  corners_on_circle(packing, ids[i], corners);
  return "the point " + point_text(packing.frame().wrap(corners.front().point));
}

}  // namespace detail

bool is_maximal(const Packing& packing) { return !detail::first_hole(packing); }

}  // namespace disktune
