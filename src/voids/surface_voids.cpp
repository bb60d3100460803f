// SPDX-License-Identifier: GPL-3.0-or-later
// Surface void points: per triangle, the arrangement vertices (triangle_arrangement.h)
// of the balls meeting it that no other disk covers. Completeness: an uncovered
// component of a triangle touching the triangle's boundary has a corner or an edge
// crossing on its boundary; one inside it is bounded by circle arcs, so by
// circle-circle crossings (the outside of a single circle always reaches the edges).
#include "disktune/surface_voids.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "../domain/point_text.h"
#include "../geometry/threads.h"
#include "../geometry/triangle_arrangement.h"
#include "../geometry/triangle_regions.h"
#include "corner_cover.h"
#include "disktune/errors.h"
#include "disktune/tolerance.h"
#include "packing_checks.h"

namespace disktune {
namespace {

bool ignored(const std::vector<DiskId>& ignore, DiskId id) {
  return std::find(ignore.begin(), ignore.end(), id) != ignore.end();
}

// The disks, but the ignored ones, that can define or cover a void point within R of q:
// those centered within R + r_max. One grid query serves every triangle of a region.
void disks_near(const SurfacePacking& packing, Vec3 q, double R, const std::vector<DiskId>& ignore,
                std::vector<DiskId>& out) {
  out.clear();
  packing.for_each_near(q, R + packing.max_radius() * (1 + kRelTol), [&](DiskId j) {
    if (!ignored(ignore, j)) out.push_back(j);
  });
}

// Whether the arrangement vertex p of a triangle of `patch` (on the circles of disks a
// and b, where not kNoDisk, and on the triangle's edges it lies on) is covered by the
// disks of `near` that count on the patch: strictly inside one, or surrounded by those whose
// circles pass through it (corner_cover.h). A crossing that merely lies on a third circle can still
// open a wedge of void, and disks placed at void points make such crossings by construction.
// `inside` is the disk of `near` that last held a vertex strictly, tried first (the
// next vertex is most often near the last; the answer is the same in any order).
bool vertex_covered(const SurfacePacking& packing, const TrianglePlane& plane, PatchSet patch,
                    Vec3 p, DiskId a, DiskId b, const std::vector<DiskId>& near, double tol,
                    DiskId& inside) {
  const auto holds = [&](DiskId j) {
    return j != a && j != b && packing.share_patch(packing.patches(j), patch) &&
           is_conflict(squared_norm(packing.center(j) - p), packing.radius(j));
  };
  if (inside != kNoDisk && holds(inside)) return true;
  const Vec2 x = plane.to_plane(p);
  detail::CornerCover cover(x);
  // Toward the center of the circle a ball cuts in the plane (none for a ball that only
  // touches the plane at x: it covers nothing around x).
  const auto toward_circle = [&](DiskId j) {
    const Vec2 d = plane.to_plane(packing.center(j)) - x;
    return squared_norm(d) > tol * tol ? std::optional<Vec2>(d) : std::nullopt;
  };
  for (const DiskId j : {a, b})
    if (j != kNoDisk)
      if (const auto d = toward_circle(j)) cover.through(*d);
  for (int k = 0; k < 3; ++k) {  // edges through x: beyond them is another triangle's
    const Vec2 c = plane.corner(k), e = plane.corner((k + 1) % 3) - c;
    if (cross(e, x - c) <= tol * plane.edge_length(k)) cover.through(Vec2{e.y, -e.x});
  }
  for (const DiskId j : near) {
    if (j == a || j == b || !packing.share_patch(packing.patches(j), patch)) continue;
    const double d2 = squared_norm(packing.center(j) - p), r = packing.radius(j);
    if (is_conflict(d2, r)) return inside = j, true;  // strictly inside
    if (is_covered(d2, r))
      if (const auto d = toward_circle(j)) cover.through(*d);
  }
  return cover.covered();
}

// Whether one disk of `near` that counts on `patch` holds the ball of radius R around q
// with room to spare: then each point of a triangle within R of q lies inside it by
// more than vertex_covered's tolerance, and is no void point (is_maximal of the
// elephant's maximal sample at 10^4 disks, one core, regions of the radius: 0.081 ->
// 0.074 s).
bool holds_ball(const SurfacePacking& packing, Vec3 q, double R, const std::vector<DiskId>& near,
                PatchSet patch) {
  for (const DiskId j : near) {
    const double room = packing.radius(j) * (1 - 4 * kRelTol) - R;
    if (room > 0 && squared_norm(packing.center(j) - q) < room * room &&
        packing.share_patch(packing.patches(j), patch))
      return true;
  }
  return false;
}

// Whether the part of a triangle within `reach` of q (in its plane) lies inside the disk
// `held` (radius below 0: none). That part is convex, so its point farthest from held's
// center is a corner, a crossing of an edge with the circle around q, or the point of
// that circle farthest from held's center (along an arc the distance grows toward it).
bool part_inside(const TrianglePlane& plane, Vec2 q, double reach, const Circle& held) {
  if (held.radius < 0) return false;
  const auto outside = [&](Vec2 p) { return squared_distance(p, held.center) > held.radius * held.radius; };
  for (int k = 0; k < 3; ++k) {
    const Vec2 a = plane.corner(k), e = plane.corner((k + 1) % 3) - a, f = a - q;
    if (squared_norm(f) <= reach * reach && outside(a)) return false;
    const double A = dot(e, e), B = dot(f, e), disc = B * B - A * (dot(f, f) - reach * reach);
    if (!(disc >= 0)) continue;
    for (const double s : {(-B - std::sqrt(disc)) / A, (-B + std::sqrt(disc)) / A})
      if (s >= 0 && s <= 1 && outside(a + e * s)) return false;
  }
  const Vec2 away = q - held.center;
  const double gap = norm(away);
  const Vec2 far = q + (gap > 0 ? away * (reach / gap) : Vec2{reach, 0});
  return !(plane.contains(far, kRelTol * reach) && outside(far));
}

// Calls on_void(p, a, b) for each void point of triangle t within R of q (R infinite:
// all of them) but those `held` holds (none: all count), and stops, returning false, as
// soon as on_void does. `near` holds disks_near(q, R) (for the whole triangle: around a
// point of it, reaching all of it).
template <class OnVoid>
bool scan_triangle(const SurfacePacking& packing, std::size_t t, Vec3 q, double R, const std::vector<DiskId>& near,
                   const HoldingBall* held, OnVoid&& on_void) {
  const SurfaceIndex& index = packing.index();
  const TrianglePlane& plane = index.plane(t);
  const PatchSet patch = index.patch_of_triangle(t);
  // Within the region, only circles passing within R of q make vertices there: in the
  // plane, within R' = sqrt(R^2 - h^2) of q's projection, h its height.
  const Vec2 q2 = plane.to_plane(q);
  const double h = plane.height(q), reach2 = std::isfinite(R) ? R * R - h * h : 0;
  const double reach = std::isfinite(R) ? std::sqrt(std::max(reach2, 0.0)) + kRelTol * R : 0;
  // What lies well inside `held` (by 1e-9 of its radius, past any rounding of the
  // points made below) needs no look: the triangle's part within R of q (of a small
  // move's check, the triangles on the side the disk moves to), a circle.
  std::optional<Circle> held_circle;
  if (held && packing.share_patch(held->patches, patch)) {
    held_circle = plane.section(held->center, held->radius * (1 - 1e-9));
    if (!held_circle) held_circle = Circle{{0, 0}, -1};  // shares the patch, misses the plane
    if (std::isfinite(R) && part_inside(plane, q2, reach, *held_circle)) return true;
  } else {
    held = nullptr;
  }
  thread_local std::vector<Ball> balls;
  balls.clear();
  for (const DiskId j : near) {
    if (!packing.share_patch(packing.patches(j), patch)) continue;  // it covers nothing here
    const Vec3 c = packing.center(j);
    const double r = packing.radius(j);
    if (squared_norm(index.closest_point(t, c) - c) > r * r * (1 + 4 * kRelTol)) continue;
    const auto circle = plane.section(c, r);
    if (!circle) continue;
    if (std::isfinite(R) && std::abs(distance(circle->center, q2) - circle->radius) > reach) continue;
    if (held && distance(circle->center, held_circle->center) + circle->radius <= held_circle->radius) continue;
    balls.push_back({c, r, j});
  }
  const double R2 = std::isfinite(R) ? R * R : std::numeric_limits<double>::infinity();
  const double tol = kRelTol * packing.max_radius();
  bool going = true;
  DiskId inside = kNoDisk;
  for_each_arrangement_vertex(plane, balls, tol, [&](Vec3 p, DiskId a, DiskId b) {
    if (!going || squared_norm(p - q) > R2) return;
    if (held && is_covered(squared_norm(p - held->center), held->radius)) return;
    if (!vertex_covered(packing, plane, patch, p, a, b, near, tol, inside))
      going = on_void(p, a, b);
  });
  return going;
}

// The void points of the triangle `corners` (inside domain triangle t, in its plane),
// region by region.
void void_points_of(const SurfacePacking& packing, std::size_t t, const std::array<Vec3, 3>& corners,
                    const std::vector<DiskId>& ignore, std::vector<SurfaceVoidPoint>& out) {
  const TrianglePlane plane(corners[0], corners[1], corners[2]);
  const double tol = kRelTol * packing.max_radius();
  thread_local std::vector<DiskId> near;
  thread_local std::vector<Ball> balls;
  const PatchSet patch = packing.index().patch_of_triangle(t);
  // Regions of half the largest radius: more of them lie inside one disk (holds_ball)
  // and the rest have fewer circles. is_maximal of maximal samples at 10^4 disks, one
  // core, against regions of the whole radius: elephant 0.057 -> 0.045 s, fandisk 0.073
  // -> 0.052, sphere 0.030 -> 0.027, mesh_with_border 0.037 -> 0.031; the elephant at
  // 10^5 0.36 -> 0.32 (a third of the radius: slower again). The sample's cells, about
  // r wide, take as long either way.
  for_each_region(plane, 0.5 * packing.max_radius(), [&](Vec3 q, double R) {
    disks_near(packing, q, R, ignore, near);
    if (holds_ball(packing, q, R, near, patch)) return;  // every point there strictly inside
    // Only circles passing within R of q make vertices in the region.
    balls.clear();
    const Vec2 q2 = plane.to_plane(q);
    for (const DiskId j : near) {
      if (!packing.share_patch(packing.patches(j), patch)) continue;
      const auto circle = plane.section(packing.center(j), packing.radius(j));
      if (circle && std::abs(distance(circle->center, q2) - circle->radius) <= R * (1 + kRelTol))
        balls.push_back({packing.center(j), packing.radius(j), j});
    }
    const double R2 = R * R;
    DiskId inside = kNoDisk;
    for_each_arrangement_vertex(plane, balls, tol, [&](Vec3 p, DiskId a, DiskId b) {
      if (squared_norm(p - q) > R2) return;
      if (!vertex_covered(packing, plane, patch, p, a, b, near, tol, inside))
        out.push_back({{p, static_cast<std::uint32_t>(t)}, a, b});
    });
  });
}

}  // namespace

void void_points_in_triangle(const SurfacePacking& packing, std::size_t t, const std::vector<DiskId>& ignore,
                             std::vector<SurfaceVoidPoint>& out) {
  const auto& tri = packing.domain().triangles()[t];
  const auto& v = packing.domain().vertices();
  void_points_of(packing, t, {v[tri[0]], v[tri[1]], v[tri[2]]}, ignore, out);
}

void void_points_in_cell(const SurfacePacking& packing, std::size_t t, const std::array<Vec3, 3>& cell,
                         std::vector<SurfaceVoidPoint>& out) {
  void_points_of(packing, t, cell, {}, out);
}

namespace {

// scan_triangle over every triangle within R of q, the disks in `ignore` lifted.
template <class OnVoid>
bool scan_region(const SurfacePacking& packing, Vec3 q, double R, const std::vector<DiskId>& ignore,
                 const HoldingBall* held, OnVoid&& on_void) {
  thread_local std::vector<std::uint32_t> tris;
  thread_local std::vector<DiskId> near;
  packing.index().triangles_near(q, R, tris);
  disks_near(packing, q, R, ignore, near);
  for (const std::uint32_t t : tris) {
    if (squared_norm(packing.index().closest_point(t, q) - q) > R * R) continue;  // out of the region
    if (!scan_triangle(packing, t, q, R, near, held, [&](Vec3 p, DiskId a, DiskId b) { return on_void(t, p, a, b); }))
      return false;
  }
  return true;
}

}  // namespace

void void_points_near(const SurfacePacking& packing, Vec3 q, double R, const std::vector<DiskId>& ignore,
                      std::vector<SurfaceVoidPoint>& out) {
  scan_region(packing, q, R, ignore, nullptr, [&](std::uint32_t t, Vec3 p, DiskId a, DiskId b) {
    out.push_back({{p, t}, a, b});
    return true;
  });
}

bool void_points_near_within(const SurfacePacking& packing, Vec3 q, double R,
                             const std::vector<DiskId>& ignore, const HoldingBall& ball,
                             SurfaceVoidPoint* outside) {
  return scan_region(packing, q, R, ignore, &ball,
                     [&](std::uint32_t t, Vec3 p, DiskId a, DiskId b) {
                       if (outside) *outside = {{p, t}, a, b};
                       return false;
                     });
}

namespace {

// A void point of the whole surface, or none: the packing is maximal. Triangle by
// triangle on every core, the first triangle with one reported (the check reads only).
std::optional<SurfaceVoidPoint> first_void_point(const SurfacePacking& packing) {
  const std::size_t triangles = packing.domain().triangles().size();
  const std::size_t t = detail::first_index(triangles, detail::thread_count(0), [&](std::size_t k) {
    thread_local std::vector<SurfaceVoidPoint> found;
    found.clear();
    void_points_in_triangle(packing, k, {}, found);
    return !found.empty();
  });
  if (t == triangles) return std::nullopt;
  std::vector<SurfaceVoidPoint> found;
  void_points_in_triangle(packing, t, {}, found);
  return found.front();
}

}  // namespace

bool is_maximal(const SurfacePacking& packing) { return !detail::first_hole(packing); }

void uncovered_on_curve_edge(const SurfacePacking& packing, std::size_t c, std::size_t e, bool fixed_only,
                             std::vector<CurveGap>& out) {
  const auto& v = packing.domain().vertices();
  const auto& curve = packing.domain().fixed_curves()[c].vertices;
  const Vec3 a = v[curve[e]], b = v[curve[(e + 1) % curve.size()]], d = b - a;
  thread_local std::vector<std::array<double, 2>> covered;
  covered.clear();
  // The disks reaching the edge, piece by piece: one ball around the whole edge would
  // visit (|edge| / r)^3 grid cells. A disk found from two pieces adds its interval twice,
  // which the union below does not mind.
  const double length = norm(d), margin = packing.max_radius() * (1 + kRelTol);
  const int pieces = std::max(1, static_cast<int>(std::ceil(length / (2 * packing.max_radius()))));
  const auto add_interval = [&](DiskId j) {
    if (fixed_only && !(packing.flags(j) & kFixed)) return;
    if (const auto in = segment_in_ball(a, b, packing.center(j), packing.radius(j) * (1 + kRelTol)))
      covered.push_back(*in);
  };
  for (int k = 0; k < pieces; ++k)
    packing.for_each_near(a + d * ((k + 0.5) / pieces), 0.5 * length / pieces + margin, add_interval);
  std::sort(covered.begin(), covered.end());
  double reach = 0;
  for (const auto& in : covered) {
    if (in[0] > reach) out.push_back({c, e, reach, in[0]});
    reach = std::max(reach, in[1]);
  }
  if (reach < 1) out.push_back({c, e, reach, 1});
}

std::vector<CurveGap> uncovered_curves(const SurfacePacking& packing, bool fixed_only) {
  std::vector<CurveGap> gaps;
  const auto& curves = packing.domain().fixed_curves();
  for (std::size_t c = 0; c < curves.size(); ++c)
    for (std::size_t e = 0; e < curves[c].edge_count(); ++e) uncovered_on_curve_edge(packing, c, e, fixed_only, gaps);
  return gaps;
}

namespace {

// A disk that, with disk i, covers each other's centers, or kNoDisk. Pairwise the
// prior-disk rule allows a center in a larger disk (varying radii), not in a smaller;
// disks on different patches never conflict.
DiskId conflicting_disk(const SurfacePacking& packing, DiskId i) {
  const Vec3 c = packing.center(i);
  DiskId found = kNoDisk;
  packing.any_near(c, packing.radius(i), [&](DiskId j) {
    if (j == i || !is_conflict(squared_norm(packing.center(j) - c), std::min(packing.radius(i), packing.radius(j))) ||
        !packing.share_patch(packing.patches(i), packing.patches(j)))
      return false;
    found = j;
    return true;
  });
  return found;
}

// The live disks' ids, those of triangle 0 first, then of triangle 1, ... (a counting
// sort: id order within a triangle).
std::vector<DiskId> ids_by_triangle(const SurfacePacking& packing) {
  std::vector<std::uint32_t> start(packing.domain().triangles().size() + 1, 0);
  for (DiskId i = 0; i < packing.id_bound(); ++i)
    if (packing.alive(i)) ++start[packing.point(i).triangle + 1];
  for (std::size_t t = 1; t < start.size(); ++t) start[t] += start[t - 1];
  std::vector<DiskId> ids(packing.size());
  for (DiskId i = 0; i < packing.id_bound(); ++i)
    if (packing.alive(i)) ids[start[packing.point(i).triangle]++] = i;
  return ids;
}

}  // namespace

namespace detail {

// Disk by disk on every core, triangle by triangle (ids follow the order disks came in,
// scattered over the surface: at 10^6 disks, asked in id order, nearly every query
// missed the cache), the first in that order reported.
std::optional<std::array<DiskId, 2>> first_conflict(const SurfacePacking& packing) {
  const std::vector<DiskId> ids = ids_by_triangle(packing);
  const std::size_t i = first_index(ids.size(), thread_count(0), [&](std::size_t k) {
    return conflicting_disk(packing, ids[k]) != kNoDisk;
  });
  if (i == ids.size()) return std::nullopt;
  return std::array<DiskId, 2>{ids[i], conflicting_disk(packing, ids[i])};
}

std::optional<std::string> first_hole(const SurfacePacking& packing) {
  if (packing.empty()) return "the whole surface";
  const auto v = first_void_point(packing);
  if (!v) return std::nullopt;
  return "the point " + point_text(v->at.p) + " of triangle " + std::to_string(v->at.triangle);
}

}  // namespace detail

}  // namespace disktune
