// SPDX-License-Identifier: GPL-3.0-or-later
#include "surface_repair.h"

#include <algorithm>
#include <cmath>

#include "../geometry/triangle_arrangement.h"
#include "disktune/tolerance.h"
#include "own_voids.h"
#include "void_repair.h"

namespace disktune::detail {

std::vector<SurfaceVoidPoint> voids_near(const SurfacePacking& packing, Vec3 q, double R,
                                         const std::vector<DiskId>& ignore) {
  std::vector<SurfaceVoidPoint> out;
  void_points_near(packing, q, R, ignore, out);
  return out;
}

bool void_free_near(const SurfacePacking& packing, Vec3 c, double r) {
  return voids_near(packing, c, void_reach(r)).empty();
}

SurfacePoint void_point_choice(const SurfacePacking& packing, const std::vector<SurfaceVoidPoint>& voids, Rng& rng) {
  const std::size_t k = weighted_diameter_index(
      voids.size(), [&](std::size_t i, std::size_t j) { return squared_norm(voids[i].at.p - voids[j].at.p); },
      [&](std::size_t i) { return packing.radius_at(voids[i].at); }, 1e-12 * packing.max_radius(), rng);
  return voids[k].at;
}

HoldingBall holding_ball(const SurfacePacking& packing, const SurfacePoint& c) {
  const double r = packing.radius_at(c);
  return {c.p, packing.sizing().is_constant() ? r : r * (1 - 1e-7), packing.patches_of(c)};
}

bool covers_all(const SurfacePacking& packing, const SurfacePoint& c, const std::vector<SurfaceVoidPoint>& voids) {
  const HoldingBall ball = holding_ball(packing, c);
  for (const SurfaceVoidPoint& v : voids) {
    if (!is_covered(squared_norm(ball.center - v.at.p), ball.radius) ||
        !packing.share_patch(packing.index().patch_of_triangle(v.at.triangle), ball.patches))
      return false;
  }
  return true;
}

bool covers_lifted_voids(const SurfacePacking& packing, Vec3 c, double R, DiskId p,
                         const SurfacePoint& x, const std::vector<std::uint32_t>* near_p,
                         LiftedDisk* lifted) {
  // Where p's cell lies in its ball at x, it still covers all that only it covered
  // (surface_cell.h), and no void points are needed: with one radius (with a sizing p's
  // radius changes on the way) and on p's own patch, by a margin above the rounding.
  if (packing.sizing().is_constant() && packing.patches_of(x) == packing.patches(p)) {
    const double radius = packing.radius(p) * (1 - 1e-7);
    if (!lifted) {
      if (cell_inside(packing, p, x.p, radius, near_p)) return true;
    } else {
      if (!lifted->cell.is_of(p, c)) lifted->cell.of(packing, p, near_p);
      if (lifted->cell.inside(x.p, radius)) return true;
    }
  }
  const HoldingBall ball = holding_ball(packing, x);
  // covers_all's test of one point; the scan below holds a point by the same one.
  if (lifted && lifted->outside &&
      !(is_covered(squared_norm(ball.center - lifted->outside->at.p), ball.radius) &&
        packing.share_patch(packing.index().patch_of_triangle(lifted->outside->at.triangle),
                            ball.patches)))
    return false;
  SurfaceVoidPoint found;
  if (void_points_near_within(packing, c, R, {p}, ball, &found)) return true;
  if (lifted) lifted->outside = found;
  return false;
}

double hold_span(const SurfacePacking& packing) {
  return 2 * packing.max_radius() * (1 + 2 * kRelTol);
}

bool wider_than_one_disk(const SurfacePacking& packing, const std::vector<SurfaceVoidPoint>& a,
                         const std::vector<SurfaceVoidPoint>& b) {
  const double span = hold_span(packing);
  for (const SurfaceVoidPoint& u : a)
    for (const SurfaceVoidPoint& v : b)
      if (squared_norm(u.at.p - v.at.p) > span * span) return true;
  return false;
}

namespace {

// The void points once each (a crossing on an edge is found from both triangles).
std::vector<Vec3> distinct_points(const std::vector<SurfaceVoidPoint>& voids, double tol) {
  std::vector<Vec3> out;
  for (const SurfaceVoidPoint& v : voids) {
    bool seen = false;
    for (const Vec3& w : out) seen = seen || squared_norm(w - v.at.p) <= tol * tol;
    if (!seen) out.push_back(v.at.p);
  }
  return out;
}

// covering_positions, or with `clear_of_disks` false the positions that cover the void
// points whatever disk they meet (the other disks' spheres left out of the arrangement).
// With `nearer_than2` (and `toward`), only the first of those nearest to *toward, where
// it is nearer than that squared distance; with one radius a vertex no nearer than the
// best so far is not tested (most of them). (With a sizing the balls shrink until some
// position is found, near or not, and the nearest of those is taken.)
std::vector<SurfacePoint> positions(const SurfacePacking& packing,
                                    const std::vector<SurfaceVoidPoint>& voids, Vec3 near, double R,
                                    DiskId self, DiskId passable, const Vec3* toward,
                                    bool clear_of_disks, const double* nearer_than2 = nullptr) {
  std::vector<SurfacePoint> out;
  if (voids.empty()) return out;
  // Balls of the smallest radius near the voids; with a sizing the true radius differs
  // from place to place, so smaller balls are tried until some vertex qualifies.
  double r = packing.max_radius();
  for (const SurfaceVoidPoint& v : voids) r = std::min(r, packing.radius_at(v.at));
  const std::vector<Vec3> points = distinct_points(voids, 1e-9 * r);
  // The common case of a pair or a pulled disk that cannot cover its void, answered
  // before any arrangement.
  const double span = hold_span(packing);
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = i + 1; j < points.size(); ++j)
      if (squared_norm(points[i] - points[j]) > span * span) return out;
  // Only triangles within r of every void point can hold a position.
  std::vector<std::uint32_t> tris, kept;
  packing.index().triangles_near(points.front(), r, tris);
  for (const std::uint32_t t : tris) {
    bool reach = true;
    for (const Vec3& v : points) reach = reach && squared_norm(packing.index().closest_point(t, v) - v) <= r * r;
    if (reach) kept.push_back(t);
  }
  // The feasible set is bounded by the balls around the void points and by the other
  // disks' spheres (a position must not conflict): its vertices are among those of
  // the arrangement of both.
  // A sphere farther than a holding ball's radius from some void point has no point
  // a position could take (covers_all fails all along it): left out, it leaves the
  // same positions at a fraction of the pairs of circles.
  std::vector<Ball> conflict_balls;
  const double hold = packing.max_radius() * (1 + 4 * kRelTol);
  if (clear_of_disks)
    packing.for_each_near(points.front(), r + packing.max_radius(), [&](DiskId j) {
      if (j == self || j == passable) return;
      const Ball ball{packing.center(j), packing.radius(j) * (1 + 2 * kRelTol), j};
      for (const Vec3& v : points)
        if (squared_norm(ball.center - v) > (ball.radius + hold) * (ball.radius + hold)) return;
      conflict_balls.push_back(ball);
    });
  std::vector<Ball> balls;
  const bool nearest = nearer_than2 && toward && packing.sizing().is_constant();
  double best2 = nearest ? *nearer_than2 : 0;
  for (const double shrink : {1.0, 0.95, 0.85, 0.7}) {
    if (shrink < 1 && packing.sizing().is_constant()) break;
    balls = conflict_balls;
    for (const Vec3& v : points) balls.push_back({v, r * shrink, kNoDisk});
    for (const std::uint32_t t : kept) {
      for_each_arrangement_vertex(
          packing.index().plane(t), balls, kRelTol * r,
          [&](Vec3 p, DiskId, DiskId) {
            if (squared_norm(p - near) > R * R) return;
            const double d2 = nearest ? squared_norm(p - *toward) : 0;
            if (nearest && !(d2 < best2)) return;
            const SurfacePoint x{p, t};
            if (!covers_all(packing, x, voids) ||
                (clear_of_disks && packing.conflicts(x, self, passable)))
              return;
            if (nearest) best2 = d2, out.clear();
            out.push_back(x);
          },
          toward);
    }
    if (!out.empty()) break;
  }
  if (nearer_than2 && toward && !nearest) {
    const SurfacePoint* pick = nullptr;
    double pick2 = *nearer_than2;
    for (const SurfacePoint& x : out)
      if (squared_norm(x.p - *toward) < pick2) pick = &x, pick2 = squared_norm(x.p - *toward);
    return pick ? std::vector<SurfacePoint>{*pick} : std::vector<SurfacePoint>{};
  }
  return out;
}

}  // namespace

std::vector<SurfacePoint> covering_positions(const SurfacePacking& packing,
                                             const std::vector<SurfaceVoidPoint>& voids, Vec3 near,
                                             double R, DiskId self, DiskId passable,
                                             const Vec3* toward) {
  return positions(packing, voids, near, R, self, passable, toward, true);
}

bool covering_point(const SurfacePacking& packing, const std::vector<SurfaceVoidPoint>& voids, Vec3 near, double R,
                    Rng& rng, SurfacePoint& z) {
  const auto spots = covering_positions(packing, voids, near, R, kNoDisk);
  if (spots.empty()) return false;
  z = spots[uniform_index(rng, spots.size())];
  return true;
}

bool sole_cover_point(const SurfacePacking& packing, const std::vector<SurfaceVoidPoint>& voids, DiskId p, Vec3 c,
                      double r, SurfacePoint& z) {
  const auto spots = covering_positions(packing, voids, c, 2 * r, p);
  if (spots.empty()) return false;
  std::size_t pick = 0;
  double pick_far = 1e300;
  for (std::size_t i = 0; i < spots.size(); ++i) {
    double far = 0;
    for (const SurfaceVoidPoint& v : voids) far = std::max(far, squared_norm(v.at.p - spots[i].p));
    if (far < pick_far) pick = i, pick_far = far;
  }
  z = spots[pick];
  return true;
}

void pull_toward(SurfaceUndoLog& log, SurfacePacking& packing, DiskId q, Vec3 to, DiskId passable) {
  const Vec3 cq = packing.center(q);
  const double rq = packing.radius(q);
  const auto voids = own_voids(packing, q);
  if (voids.empty()) return;
  // The first of the positions nearest `to`, where one is nearer than q is now.
  const double nearer_than2 = squared_norm(cq - to) * (1 - 1e-9);
  // First the positions that cover the void, the other disks left out: on a triangle
  // they make a convex set holding every position, and the candidates hold its point
  // nearest `to`. So when none is nearer than q is now, no position is; and when the
  // nearest meets no disk, it is the answer. The other disks' spheres (many more
  // circles) only where it meets one. (With a sizing the covering balls shrink until
  // some position is found, which the disks change: the full search at once.)
  std::vector<SurfacePoint> best;
  if (packing.sizing().is_constant()) {
    best = positions(packing, voids, cq, 2 * rq, q, passable, &to, false, &nearer_than2);
    if (best.empty()) return;
  }
  if (best.empty() || packing.conflicts(best[0], q, passable))
    best = positions(packing, voids, cq, 2 * rq, q, passable, &to, true, &nearer_than2);
  if (best.empty()) return;
  const std::size_t before = log.mark();
  const Vec3 to_p = best[0].p;
  log.move(q, best[0]);
  // The packing is maximal before the pull, so what lifting q leaves lies in q's old
  // ball, inside the convex hull of its void points on each triangle; the new place
  // covers them all (positions keeps only such), so only a crossing on q's new rim can
  // be open (placed_void_free, space.h): the exact check around the new center alone.
  if (!void_free_near(packing, to_p, rq)) log.revert_to(before);
}

std::vector<DiskId> mobile_neighbors(const SurfacePacking& packing, Vec3 point, double r, DiskId self, Rng& rng) {
  std::vector<DiskId> near;
  packing.for_each_near(point, r + packing.max_radius(), [&](DiskId j) {
    if (j == self || (packing.flags(j) & (kFixed | kFrozen))) return;
    if (self != kNoDisk && !packing.share_patch(packing.patches(j), packing.patches(self))) return;
    const double reach = r + packing.radius(j);
    if (squared_norm(packing.center(j) - point) < reach * reach) near.push_back(j);
  });
  std::sort(near.begin(), near.end());  // grid order is not deterministic across rehashes
  for (std::size_t i = near.size(); i > 1; --i) std::swap(near[i - 1], near[uniform_index(rng, i)]);
  return near;
}

std::size_t repair_void(SurfaceUndoLog& log, const SurfacePacking& packing, Vec3 q, double R, Rng& rng,
                        std::size_t max_added) {
  for (std::size_t added = 0;; ++added) {
    const std::vector<SurfaceVoidPoint> voids = voids_near(packing, q, R);
    if (voids.empty()) return added;
    if (added == max_added) return max_added + 1;
    const SurfacePoint at = void_point_choice(packing, voids, rng);
    log.insert(at, 0);
  }
}

}  // namespace disktune::detail
