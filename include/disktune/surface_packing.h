// SPDX-License-Identifier: GPL-3.0-or-later
// A packing on a curved surface (paper, section 7.2): each disk is the ball of radius
// r(c) around a center c on the surface, and what it covers is the part of the surface
// inside that ball. Centers carry the triangle they lie in, so every point the
// algorithms make is exactly on the surface. A 3D hash grid answers neighbour queries
// in O(1); a second grid finds the triangles near a point.
//
// Where sharp features cut the surface into patches (SurfaceDomain::triangle_patch),
// a disk covers, and conflicts with, only what lies on a patch it counts on: a free disk
// on its triangle's patch, a fixed disk on every patch its center lies on (both sides of
// a crease, all around a corner). So no disk covers across a feature: each patch is a
// maximal packing of its own, held at its rim by the disks on the feature curves.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <utility>
#include <vector>

#include "disktune/packing.h"
#include "disktune/surface_domain.h"
#include "disktune/surface_geometry.h"
#include "disktune/surface_sizing.h"
#include "disktune/tolerance.h"
#include "disktune/vec3.h"

namespace disktune {

/// A set of patches a disk or a point counts on, named by a number (see
/// SurfacePacking::patches): kAnyPatch is every patch.
using PatchSet = std::uint32_t;
constexpr PatchSet kAnyPatch = ~PatchSet{0};

/// A point on the surface: its position and the triangle it lies in.
struct SurfacePoint {
  Vec3 p;
  std::uint32_t triangle = 0;
};

/// A uniform grid over space for items given by position (disks). Cells are keyed by
/// their integer coordinates in an open-addressed hash table, so empty space costs
/// nothing, and each cell keeps its items' positions beside their ids: a query reads
/// the table slot and the cell's items, not a node per cell and a packing array per
/// item (those cache misses made the surface MPS grow as n^1.15 toward 10^6 disks).
class SpaceGrid {
 public:
  explicit SpaceGrid(double cell) : cell_(cell) {}
  double cell() const { return cell_; }
  void insert(std::uint32_t id, Vec3 p) {
    Cell& cell = cell_at(key(p));
    cell.items.push_back({p, id});
    ++cell.changes;
  }
  /// Counts a change in the cell holding p, as insert and remove do.
  void touch(Vec3 p) { ++cell_at(key(p)).changes; }
  /// The inserts, removals and touches so far in the cells meeting the box [q - R,
  /// q + R], summed: it grows with every one, so an unchanged sum means nothing there
  /// changed (cells never go away; cells sharing a key only make it grow more often).
  std::uint64_t changes_in_box(Vec3 q, double R) const;
  /// Unregisters `id`, known to be at `p` (nothing when it is not there).
  void remove(std::uint32_t id, Vec3 p);
  std::uint64_t key(Vec3 p) const;
  /// The index along one axis of the cell of width `cell` holding coordinate v (cells
  /// past 2^52 of them share the outermost; NaN goes there too).
  static std::int64_t cell_index(double v, double cell);
  /// Makes the cells meeting the box [q - R, q + R] exist (empty where new): inserting or
  /// removing an item there then changes only that cell's list, never the table, so
  /// threads may do so in cells no other thread reads at the time.
  void add_cells(Vec3 q, double R);
  /// Makes room for `cells` cells in all, so that adding up to that many moves no cell.
  void reserve(std::size_t cells);
  /// The number of cells made so far.
  std::size_t cell_count() const { return used_; }
  /// True when no two cells of the box [lo, hi] share a key (keys wrap after 2^21 cells
  /// per axis, which only makes queries slower, but cells sharing a key are no longer
  /// apart).
  bool keys_distinct_within(Vec3 lo, Vec3 hi) const;
  /// f(id) for every item in a cell meeting the box [q - R, q + R].
  template <class F>
  void for_each_in_box(Vec3 q, double R, F&& f) const {
    any_in_box(q, R, [&](std::uint32_t id) { return f(id), false; });
  }
  /// True, stopping at once, when pred(id) holds for an item in a cell meeting the box.
  template <class Pred>
  bool any_in_box(Vec3 q, double R, Pred&& pred) const {
    return any_item_in_box(q, R, [&](const Item& item) { return pred(item.id); });
  }
  /// The same for the items within distance R of q (by the position they were inserted
  /// at), in the same order: pred(id, squared distance to q).
  template <class Pred>
  bool any_within(Vec3 q, double R, Pred&& pred) const {
    const double R2 = R * R;
    return any_item_in_box(q, R, [&](const Item& item) {
      const double d2 = squared_norm(item.p - q);
      return d2 <= R2 && pred(item.id, d2);
    });
  }

 private:
  struct Item {
    Vec3 p;
    std::uint32_t id;
  };
  struct Cell {
    std::uint64_t key = kEmpty;
    std::vector<Item> items;  // kept when emptied: a cell once used is likely used again
    std::uint64_t changes = 0;
  };
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};  // pack never makes it

  template <class Pred>
  bool any_item_in_box(Vec3 q, double R, Pred&& pred) const;
  const std::vector<Item>* items_of(std::uint64_t key) const;
  Cell& cell_at(std::uint64_t key);                // adds the cell when missing
  void rehash(std::size_t slots);                  // moves every cell to a table of `slots`
  std::size_t slot_of(std::uint64_t key) const;    // its slot, or the empty one it would take
  static std::uint64_t pack(std::int64_t i, std::int64_t j, std::int64_t k);
  std::int64_t coord(double v) const;

  double cell_;
  std::vector<Cell> table_;  // linear probing; the size a power of two, at most half full
  std::size_t used_ = 0;
};

namespace detail {
class BoxTree;
}

/// The triangles of a surface with their planes, and a bounding-box tree to find those
/// near a point.
class SurfaceIndex {
 public:
  explicit SurfaceIndex(std::shared_ptr<const SurfaceDomain> domain);
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

  /// The patch of triangle t (0 on a surface without features), which its points lie on.
  PatchSet patch_of_triangle(std::size_t t) const { return by_patch_ ? domain_->triangle_patch()[t] : 0; }
  /// The patches point q lies on: its triangle's, and within `tol` of a feature edge or
  /// vertex of that triangle, every patch there.
  PatchSet patches_at(const SurfacePoint& q, double tol) const;
  /// True when the two sets have a patch in common.
  bool share_patch(PatchSet a, PatchSet b) const {
    if (a == b || a == kAnyPatch || b == kAnyPatch) return true;
    if (a < patch_count_ && b < patch_count_) return false;
    return shared_by_sets(a, b);
  }

 private:
  std::shared_ptr<const SurfaceDomain> domain_;
  std::vector<TrianglePlane> planes_;
  std::vector<double> cumulative_area_;
  std::vector<std::vector<std::uint32_t>> curve_triangle_;  // per fixed curve, per edge
  // A tree, not a grid: a ball query visits the few boxes near it, where a grid of cells
  // some radii wide hashed 8-27 cells and sorted out repeats (the elephant's triangles
  // within r = 0.0093 of each disk: 1.3 us a query with the grid, 0.8 with the tree,
  // 0.72 since its leaves read their boxes in a row).
  std::shared_ptr<const detail::BoxTree> tree_;
  // Patches, where features cut the surface. Sets of two or more patches (those of a
  // feature edge's sides and around a feature vertex) are numbered from patch_count_ on:
  // patch_sets_[set - patch_count_], sorted. Per triangle touching a feature, the set of
  // each of its vertices and edges (the triangle's own patch where none is special).
  bool by_patch_ = false;
  PatchSet patch_count_ = 1;
  std::vector<std::vector<std::uint32_t>> patch_sets_;
  std::unordered_map<std::uint32_t, std::array<PatchSet, 6>> near_feature_;  // vertices 0-2, edges 3-5
  bool shared_by_sets(PatchSet a, PatchSet b) const;
  PatchSet set_of(std::vector<std::uint32_t> patches);
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

  /// The patches disk `id` counts on, and those a free disk at q would (its triangle's).
  PatchSet patches(DiskId id) const { return patches_[id]; }
  PatchSet patches_of(const SurfacePoint& q) const { return index_->patch_of_triangle(q.triangle); }
  /// True when the two sets have a patch in common.
  bool share_patch(PatchSet a, PatchSet b) const { return index_->share_patch(a, b); }

  bool alive(DiskId id) const { return id < radius_.size() && radius_[id] > 0; }
  const SurfacePoint& point(DiskId id) const { return point_[id]; }
  Vec3 center(DiskId id) const { return point_[id].p; }
  double radius(DiskId id) const { return radius_[id]; }
  std::uint8_t flags(DiskId id) const { return flags_[id]; }
  /// Sets the flags; a disk made fixed or free counts on its patches anew.
  void set_flags(DiskId id, std::uint8_t f);
  std::size_t size() const { return live_; }
  bool empty() const { return live_ == 0; }
  DiskId id_bound() const { return static_cast<DiskId>(radius_.size()); }
  std::vector<DiskId> ids() const;
  /// Renumbers the live disks 0, 1, ... in the order of a Z-order curve through the
  /// neighbour grid's cells (free ids dropped), and returns their old ids in that order.
  /// Disks near one another then sit near one another in memory: relaxation (10
  /// sweeps) of the elephant's sample at 10^5 disks, darts' order against this one,
  /// 2.1-2.4 -> 1.8-1.9 s on one core, 1.4-1.6 -> 1.24 s on two.
  /// Ids taken before name other disks afterwards.
  std::vector<DiskId> order_by_place();

  /// f(id) for every live disk whose center is within R of q.
  template <class F>
  void for_each_near(Vec3 q, double R, F&& f) const;
  /// True, stopping at once, when pred(id) holds for a live disk centered within R of q.
  template <class Pred>
  bool any_near(Vec3 q, double R, Pred&& pred) const {
    return grid_.any_within(q, R, [&](std::uint32_t id, double) { return pred(DiskId{id}); });
  }
  /// True when q lies strictly inside a disk other than `ignore1` and `ignore2` (beyond
  /// the tolerance) that shares a patch with q: a free center there would be a conflict.
  bool conflicts(const SurfacePoint& q, DiskId ignore1 = kNoDisk, DiskId ignore2 = kNoDisk) const {
    return conflicts(q.p, patches_of(q), ignore1, ignore2);
  }
  /// The same for a point counting on the patches `on` (kAnyPatch: every disk counts).
  bool conflicts(Vec3 q, PatchSet on, DiskId ignore1 = kNoDisk, DiskId ignore2 = kNoDisk) const;
  /// True when q lies in a closed disk other than `ignore1` and `ignore2` that shares a
  /// patch with q.
  bool covered(const SurfacePoint& q, DiskId ignore1 = kNoDisk, DiskId ignore2 = kNoDisk) const {
    return covered(q.p, patches_of(q), ignore1, ignore2);
  }
  bool covered(Vec3 q, PatchSet on, DiskId ignore1 = kNoDisk, DiskId ignore2 = kNoDisk) const;

  /// Grows with every insert, removal, move or flag change of a disk centered in the
  /// neighbour grid's cells meeting the box [q - R, q + R] (SpaceGrid::changes_in_box):
  /// while it stays the same, nothing near q changed, and what was found there holds.
  std::uint64_t changes_near(Vec3 q, double R) const { return grid_.changes_in_box(q, R); }
  /// A number no other packing object of the process has, taken anew by a copy: what
  /// is kept about one packing (changes_near) is never taken for another's.
  std::uint64_t serial() const { return serial_.value; }

  /// The width of the neighbour grid's cells (a query within R of q reads the cells
  /// meeting the box [q - R, q + R]; an item lies in the cell holding its center).
  double grid_cell() const { return grid_.cell(); }
  /// Makes the neighbour grid's cells within R of q exist (SpaceGrid::add_cells): until
  /// then moves of a disk to within R of q change only the cells they leave and enter,
  /// and the disk's own entries, so moves far enough apart can run on separate threads
  /// (relax).
  void add_grid_cells(Vec3 q, double R) { grid_.add_cells(q, R); }
  /// False where the domain, grown by `reach`, spans so many cells that cells far apart
  /// share a grid key (SpaceGrid::keys_distinct_within), and moves far apart may still
  /// touch one cell.
  bool grid_cells_distinct(double reach) const;

 private:
  // A fresh number for every object, also for copies and moves.
  struct Serial {
    std::uint64_t value = next();
    Serial() = default;
    Serial(const Serial&) : value(next()) {}
    Serial& operator=(const Serial&) { return value = next(), *this; }
    static std::uint64_t next();
  };
  std::shared_ptr<const SurfaceIndex> index_;
  std::shared_ptr<const SurfaceSizing> sizing_;
  Serial serial_;
  SpaceGrid grid_;
  std::vector<SurfacePoint> point_;
  std::vector<double> radius_;  // 0 marks a free id
  std::vector<std::uint8_t> flags_;
  std::vector<PatchSet> patches_;
  std::vector<DiskId> free_ids_;
  std::size_t live_ = 0;
  PatchSet patches_for(const SurfacePoint& q, std::uint8_t flags) const {
    return flags & kFixed ? index_->patches_at(q, kRelTol * max_radius()) : patches_of(q);
  }
};

// ---- inline and templates ----

// The grid's lookups, inline: a ball query makes 8-27 of them (a third of relaxation's
// grid time on fandisk was the calls).
inline std::int64_t SpaceGrid::cell_index(double v, double cell) {
  // Points beyond 2^52 cells share the outermost cells (see pack: only slower): casting
  // a larger value to int64 is undefined, which a surface CSV point at x = 1e300 reached
  // (found by fuzzing, #17). Still monotone, so a box's cells hold all its items.
  constexpr double kFar = 4503599627370496.0;  // 2^52
  const double c = std::floor(v / cell);
  return static_cast<std::int64_t>(c >= -kFar ? std::min(c, kFar) : -kFar);  // NaN: -kFar
}

inline std::int64_t SpaceGrid::coord(double v) const { return cell_index(v, cell_); }

inline std::uint64_t SpaceGrid::pack(std::int64_t i, std::int64_t j, std::int64_t k) {
  // 21 bits per axis around the origin: two million cells each way is plenty, and
  // coordinates past it only share cells (slower, never wrong).
  const auto b = [](std::int64_t v) {
    return static_cast<std::uint64_t>(v + (1 << 20)) & 0x1fffff;
  };
  return b(i) | b(j) << 21 | b(k) << 42;
}

inline std::uint64_t SpaceGrid::key(Vec3 p) const {
  return pack(coord(p.x), coord(p.y), coord(p.z));
}

inline std::size_t SpaceGrid::slot_of(std::uint64_t key) const {
  // A 64-bit mix (splitmix64's finaliser): neighbouring cells land far apart.
  std::uint64_t h = key;
  h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ULL;
  h = (h ^ (h >> 27)) * 0x94d049bb133111ebULL;
  h ^= h >> 31;
  const std::size_t mask = table_.size() - 1;
  std::size_t at = static_cast<std::size_t>(h) & mask;
  while (table_[at].key != key && table_[at].key != kEmpty) at = (at + 1) & mask;
  return at;
}

inline const std::vector<SpaceGrid::Item>* SpaceGrid::items_of(std::uint64_t key) const {
  const Cell& cell = table_[slot_of(key)];
  return cell.key == key ? &cell.items : nullptr;
}

template <class Pred>
bool SpaceGrid::any_item_in_box(Vec3 q, double R, Pred&& pred) const {
  if (used_ == 0) return false;
  const std::int64_t i0 = coord(q.x - R), i1 = coord(q.x + R);
  const std::int64_t j0 = coord(q.y - R), j1 = coord(q.y + R);
  const std::int64_t k0 = coord(q.z - R), k1 = coord(q.z + R);
  for (std::int64_t i = i0; i <= i1; ++i)
    for (std::int64_t j = j0; j <= j1; ++j)
      for (std::int64_t k = k0; k <= k1; ++k) {
        const std::vector<Item>* items = items_of(pack(i, j, k));
        if (!items) continue;
        for (const Item& item : *items)
          if (pred(item)) return true;
      }
  return false;
}

/// The count at area fraction 1 on the surface: the integral of 4 / (pi r(x)^2), by the
/// edge-midpoint rule on every triangle (A / (pi r^2 / 4) for one radius).
double density_unit(const SurfacePacking& packing);

template <class F>
void SurfacePacking::for_each_near(Vec3 q, double R, F&& f) const {
  grid_.any_within(q, R,
                   [&](std::uint32_t id, double) { return f(static_cast<DiskId>(id)), false; });
}

}  // namespace disktune
