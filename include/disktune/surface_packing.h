// SPDX-License-Identifier: GPL-3.0-or-later
// A packing on a curved surface (paper, section 7.2): each disk is the ball of radius
// r(c) around a center c on the surface, and what it covers is the part of the surface
// inside that ball. Centers carry the triangle they lie in, so every point the
// algorithms make is exactly on the surface. A 3D hash grid answers neighbour queries
// in O(1); a second grid finds the triangles near a point.
#pragma once

#include <cstdint>
#include <memory>
#include <unordered_map>
#include <utility>
#include <vector>

#include "disktune/packing.h"
#include "disktune/surface_domain.h"
#include "disktune/surface_geometry.h"
#include "disktune/surface_sizing.h"
#include "disktune/vec3.h"

namespace disktune {

/// A point on the surface: its position and the triangle it lies in.
struct SurfacePoint {
  Vec3 p;
  std::uint32_t triangle = 0;
};

/// A uniform grid over space for items given by position (disks) or by a set of cells
/// (triangles). Cells are keyed by their integer coordinates in a hash map, so empty
/// space costs nothing.
class SpaceGrid {
 public:
  explicit SpaceGrid(double cell) : cell_(cell) {}
  double cell() const { return cell_; }
  void insert(std::uint32_t id, Vec3 p) { cells_[key(p)].push_back(id); }
  void insert_in_cell(std::uint32_t id, std::uint64_t k) { cells_[k].push_back(id); }
  void remove(std::uint32_t id, Vec3 p);
  std::uint64_t key(Vec3 p) const;
  /// f(id) for every item in a cell meeting the box [q - R, q + R].
  template <class F>
  void for_each_in_box(Vec3 q, double R, F&& f) const {
    any_in_box(q, R, [&](std::uint32_t id) { return f(id), false; });
  }
  /// True, stopping at once, when pred(id) holds for an item in a cell meeting the box.
  template <class Pred>
  bool any_in_box(Vec3 q, double R, Pred&& pred) const;

 private:
  double cell_;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
  static std::uint64_t pack(std::int64_t i, std::int64_t j, std::int64_t k);
  std::int64_t coord(double v) const;
};

/// The triangles of a surface with their planes, and a grid to find those near a point.
class SurfaceIndex {
 public:
  /// `cell` is the grid's cell size; a multiple of the largest radius works well.
  SurfaceIndex(std::shared_ptr<const SurfaceDomain> domain, double cell);
  const SurfaceDomain& domain() const { return *domain_; }
  std::shared_ptr<const SurfaceDomain> domain_ptr() const { return domain_; }
  const TrianglePlane& plane(std::size_t t) const { return planes_[t]; }
  /// The triangles that may come within R of q (a superset), sorted, each once.
  void triangles_near(Vec3 q, double R, std::vector<std::uint32_t>& out) const;
  /// The closest point of triangle t to p.
  Vec3 closest_point(std::size_t t, Vec3 p) const;
  /// A point uniformly distributed over the surface by area (u1, u2, u3 uniform in [0, 1)).
  SurfacePoint point_by_area(double u1, double u2, double u3) const;
  /// The point at parameter s in [0, 1] of edge k of fixed curve c (from its vertex k to
  /// k + 1; domain().fixed_curves()), with a triangle holding that edge.
  SurfacePoint on_curve(std::size_t c, std::size_t k, double s) const;

 private:
  std::shared_ptr<const SurfaceDomain> domain_;
  std::vector<TrianglePlane> planes_;
  struct Bound {  // a ball around a triangle: a cheap first test in triangles_near
    Vec3 center;
    double radius;
  };
  std::vector<Bound> bounds_;
  std::vector<double> cumulative_area_;
  std::vector<std::vector<std::uint32_t>> curve_triangle_;  // per fixed curve, per edge
  SpaceGrid grid_;
};

class SurfacePacking {
 public:
  /// Disks on `domain` with radii from `sizing` (made for the same domain).
  SurfacePacking(std::shared_ptr<const SurfaceDomain> domain, SurfaceSizing sizing);

  const SurfaceDomain& domain() const { return index_->domain(); }
  const SurfaceIndex& index() const { return *index_; }
  const SurfaceSizing& sizing() const { return *sizing_; }
  double max_radius() const { return sizing_->max_radius(); }
  /// The radius a disk centered at q gets.
  double radius_at(const SurfacePoint& q) const;

  DiskId insert(const SurfacePoint& q, std::uint8_t flags = 0);
  void remove(DiskId id);
  /// Moves a disk; its radius becomes radius_at(q).
  void move(DiskId id, const SurfacePoint& q);

  bool alive(DiskId id) const { return id < radius_.size() && radius_[id] > 0; }
  const SurfacePoint& point(DiskId id) const { return point_[id]; }
  Vec3 center(DiskId id) const { return point_[id].p; }
  double radius(DiskId id) const { return radius_[id]; }
  std::uint8_t flags(DiskId id) const { return flags_[id]; }
  void set_flags(DiskId id, std::uint8_t f) { flags_[id] = f; }
  std::size_t size() const { return live_; }
  bool empty() const { return live_ == 0; }
  DiskId id_bound() const { return static_cast<DiskId>(radius_.size()); }
  std::vector<DiskId> ids() const;

  /// f(id) for every live disk whose center is within R of q.
  template <class F>
  void for_each_near(Vec3 q, double R, F&& f) const;
  /// True, stopping at once, when pred(id) holds for a live disk centered within R of q.
  template <class Pred>
  bool any_near(Vec3 q, double R, Pred&& pred) const {
    const double R2 = R * R;
    return grid_.any_in_box(q, R, [&](std::uint32_t id) { return squared_norm(point_[id].p - q) <= R2 && pred(DiskId{id}); });
  }
  /// True when q lies strictly inside a disk other than `ignore1` and `ignore2` (beyond
  /// the tolerance): a center there would be a conflict.
  bool conflicts(Vec3 q, DiskId ignore1 = kNoDisk, DiskId ignore2 = kNoDisk) const;
  /// True when q lies in a closed disk other than `ignore1` and `ignore2`.
  bool covered(Vec3 q, DiskId ignore1 = kNoDisk, DiskId ignore2 = kNoDisk) const;

 private:
  std::shared_ptr<const SurfaceIndex> index_;
  std::shared_ptr<const SurfaceSizing> sizing_;
  SpaceGrid grid_;
  std::vector<SurfacePoint> point_;
  std::vector<double> radius_;  // 0 marks a free id
  std::vector<std::uint8_t> flags_;
  std::vector<DiskId> free_ids_;
  std::size_t live_ = 0;
};

// ---- templates ----

template <class Pred>
bool SpaceGrid::any_in_box(Vec3 q, double R, Pred&& pred) const {
  const std::int64_t i0 = coord(q.x - R), i1 = coord(q.x + R);
  const std::int64_t j0 = coord(q.y - R), j1 = coord(q.y + R);
  const std::int64_t k0 = coord(q.z - R), k1 = coord(q.z + R);
  for (std::int64_t i = i0; i <= i1; ++i)
    for (std::int64_t j = j0; j <= j1; ++j)
      for (std::int64_t k = k0; k <= k1; ++k) {
        const auto it = cells_.find(pack(i, j, k));
        if (it == cells_.end()) continue;
        for (const std::uint32_t id : it->second)
          if (pred(id)) return true;
      }
  return false;
}

/// The count at area fraction 1 on the surface: the integral of 4 / (pi r(x)^2), by the
/// edge-midpoint rule on every triangle (A / (pi r^2 / 4) for one radius).
double density_unit(const SurfacePacking& packing);

template <class F>
void SurfacePacking::for_each_near(Vec3 q, double R, F&& f) const {
  const double R2 = R * R;
  grid_.for_each_in_box(q, R, [&](std::uint32_t id) {
    if (squared_norm(point_[id].p - q) <= R2) f(static_cast<DiskId>(id));
  });
}

}  // namespace disktune
