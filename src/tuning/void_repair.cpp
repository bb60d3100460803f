// SPDX-License-Identifier: GPL-3.0-or-later
// The planar steps the tuning operations share (void_repair.h).
#include "void_repair.h"

#include <algorithm>
#include <cmath>

namespace disktune {
namespace detail {

Vec2 void_corner(const Packing& packing, const std::vector<Corner>& corners, Rng& rng) {
  // Equal up to rounding: the two ends of a diameter pair under one radius.
  const std::size_t k = weighted_diameter_index(
      corners.size(), [&](std::size_t i, std::size_t j) { return squared_distance(corners[i].point, corners[j].point); },
      [&](std::size_t i) { return packing.radius_at(corners[i].point); }, 1e-12 * packing.max_radius(), rng);
  return corners[k].point;
}

bool covers_all(const Packing& packing, Vec2 c, const std::vector<Corner>& corners) {
  const double r = packing.radius_at(c);
  const double inside = packing.sizing() ? r * (1 - 1e-7) : r;
  for (const Corner& k : corners) {
    if (!is_covered(squared_distance(c, k.point), inside)) return false;
  }
  return true;
}

std::vector<Neighbor> mobile_neighbors(const Packing& packing, Vec2 point, DiskId self, Rng& rng) {
  std::vector<Neighbor> near;
  const double r = packing.radius_at(point);
  packing.for_each_near(point, r + packing.max_radius(), [&](const Neighbor& n) {
    if (n.id == self || (packing.flags(n.id) & (kFixed | kFrozen))) return;
    if (n.d2 > (r + n.radius) * (r + n.radius)) return;  // does not overlap a disk at point
    for (const Neighbor& m : near) {
      if (m.id == n.id) return;
    }
    near.push_back(n);
  });
  for (std::size_t i = near.size(); i > 1; --i) std::swap(near[i - 1], near[uniform_index(rng, i)]);
  return near;
}

bool void_free_near(const Packing& packing, Vec2 center, double r) {
  std::vector<Corner> corners;
  return !packing.any_near(center, (r + packing.max_radius()) * (1 + kRelTol), [&](const Neighbor& n) {
    corners_on_circle(packing, n.id, corners);
    return !corners.empty();
  });
}

std::size_t repair_void(UndoLog& log, const Packing& packing, Vec2 center, double r, Rng& rng,
                        std::size_t max_added) {
  std::vector<Corner> corners;
  for (std::size_t added = 0;; ++added) {
    corners.clear();
    corners_in_region(packing, center, r, {}, corners);
    if (corners.empty()) return added;
    if (added == max_added) return max_added + 1;
    const Vec2 at = void_corner(packing, corners, rng);
    log.insert(at, packing.radius_at(at));
  }
}

bool covering_point(const Packing& packing, const std::vector<Corner>& corners, Rng& rng, Vec2& z) {
  const double r = packing.max_radius();  // the box below holds every candidate
  Vec2 lo{-1e300, -1e300}, hi{1e300, 1e300};
  for (const Corner& c : corners) {
    lo = {std::max(lo.x, c.point.x - r), std::max(lo.y, c.point.y - r)};
    hi = {std::min(hi.x, c.point.x + r), std::min(hi.y, c.point.y + r)};
  }
  if (lo.x > hi.x || lo.y > hi.y) return false;
  auto fits = [&](Vec2 x) {
    return !packing.conflicts(x) && covers_all(packing, x, corners);
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

bool sole_cover_point(const Packing& packing, const std::vector<Corner>& corners, DiskId p, Vec2& z) {
  std::vector<Vec2> points;
  for (const Corner& c : corners) points.push_back(c.point);
  z = min_enclosing_circle(points).center;
  packing.for_each_near(z, packing.max_radius(), [&](const Neighbor& k) {
    if (k.id != p && is_conflict(k.d2, k.radius) && k.d2 > 0) {
      z = k.image + (z - k.image) * (k.radius / std::sqrt(k.d2));
    }
  });
  return !packing.conflicts(z, p) && covers_all(packing, z, corners);
}

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

void pull_toward(UndoLog& log, Packing& packing, const Neighbor& q, Vec2 to, DiskId passable) {
  std::vector<Corner> corners;
  corners_in_region(packing, q.image, q.radius, {q.id}, corners);
  const Vec2 v = to - q.image;
  double t = reach_toward(packing, passable, q, v, corners);
  // With varying radii q's radius changes on the way: where it no longer covers its
  // void, try 0.9 of the step, three times at most (6.2). Any shorter step still
  // keeps q out of the other disks. (A non-convex domain may not hold the target.)
  for (int tries = 0; tries < 3 && t > 0; ++tries, t *= 0.9) {
    const Vec2 at = q.image + v * t;
    if (packing.inside(at) && covers_all(packing, at, corners)) {
      log.move(q.id, at);  // still covers its void: no repair
      break;
    }
    if (!packing.sizing()) break;
  }
}

}  // namespace detail

}  // namespace disktune
