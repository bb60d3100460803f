// SPDX-License-Identifier: GPL-3.0-or-later
// A packing: disks (center, radius, flags) in a Frame, with a spatial grid for O(1)
// insert, remove, move and neighbour queries. The packing owns the conflict and
// coverage rules; it does not enforce them on every edit (algorithms move through
// states they have already checked), but offers the checks.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

#include "disktune/frame.h"
#include "disktune/geometry.h"
#include "disktune/planar_domain.h"
#include "disktune/sizing.h"
#include "disktune/spatial_grid.h"
#include "disktune/tolerance.h"

namespace disktune {

inline constexpr DiskId kNoDisk = std::numeric_limits<DiskId>::max();

/// Per-disk flags: fixed disks (boundary samples) never move; frozen disks belong to
/// a growing crystal.
enum DiskFlags : std::uint8_t { kFixed = 1, kFrozen = 2 };

class Packing {
 public:
  /// `max_radius` bounds every radius ever inserted; it sizes the grid cells.
  Packing(const Frame& frame, double max_radius);

  /// Adds a disk and returns its id. Ids are stable until the disk is removed, and a
  /// removed id may be reused by a later insert. With a sizing, pass radius_at(center).
  DiskId insert(Vec2 center, double radius, std::uint8_t flags = 0);
  void remove(DiskId id);
  /// Moves a disk; with a sizing its radius becomes radius_at(center).
  void move(DiskId id, Vec2 center);

  bool alive(DiskId id) const { return id < radius_.size() && radius_[id] > 0; }
  Vec2 center(DiskId id) const { return center_[id]; }
  double radius(DiskId id) const { return radius_[id]; }
  std::uint8_t flags(DiskId id) const { return flags_[id]; }
  void set_flags(DiskId id, std::uint8_t f) { flags_[id] = f; }

  /// Number of live disks.
  std::size_t size() const { return live_; }
  bool empty() const { return live_ == 0; }
  /// Every live id is below this bound.
  DiskId id_bound() const { return static_cast<DiskId>(radius_.size()); }
  /// Live ids in increasing order.
  std::vector<DiskId> ids() const;

  const Frame& frame() const { return grid_.frame(); }
  double max_radius() const { return max_radius_; }

  /// f(const Neighbor&) for every image of every disk whose center is within R of q.
  template <class F>
  void for_each_near(Vec2 q, double R, F&& f) const {
    grid_.for_each_near(q, R, std::forward<F>(f));
  }
  /// True, stopping early, when pred(const Neighbor&) holds for some image within R of q.
  template <class Pred>
  bool any_near(Vec2 q, double R, Pred&& pred) const {
    return grid_.any_near(q, R, std::forward<Pred>(pred));
  }

  /// Spatially varying radii (paper, section 6): a disk inserted or moved to x takes the
  /// radius r(x) (radius_at), and the conflict rule stays "a new center must lie outside
  /// every disk" (the moved or injected disk is the latest arrival). The `max_radius`
  /// given at construction must bound r; copies share the sizing.
  void set_sizing(std::shared_ptr<const Sizing> sizing) { sizing_ = std::move(sizing); }
  const Sizing* sizing() const { return sizing_.get(); }
  /// The radius a disk centered at q gets: r(q) with a sizing, max_radius() without.
  /// Throws InvalidInput when r(q) is not in (0, max_radius()].
  double radius_at(Vec2 q) const { return sizing_ ? sized_radius(q) : max_radius_; }

  /// Restricts the packing to a planar domain inside its frame: void corners outside
  /// the domain are no voids (voids.h), and a center outside it is a conflict. Copies
  /// of the packing share the domain.
  void set_domain(std::shared_ptr<const PlanarDomain> domain) { domain_ = std::move(domain); }
  const PlanarDomain* domain() const { return domain_.get(); }
  /// True when q lies in the domain (always, without one).
  bool inside(Vec2 q) const { return !domain_ || domain_->contains(q); }

  /// True when a new center at `q` would lie outside the domain or strictly inside an
  /// existing disk (other than `ignore`): the prior-disk conflict rule, which for a
  /// uniform radius is "closer than r to another center".
  bool conflicts(Vec2 q, DiskId ignore = kNoDisk) const;
  /// True when `q` lies in some disk other than `ignore` (closed disks, tolerance).
  bool covered(Vec2 q, DiskId ignore = kNoDisk) const;

 private:
  SpatialGrid grid_;
  double max_radius_;
  std::vector<Vec2> center_;
  std::vector<double> radius_;  // 0 marks a free id
  std::vector<std::uint8_t> flags_;
  std::vector<DiskId> free_ids_;
  std::size_t live_ = 0;
  std::shared_ptr<const PlanarDomain> domain_;
  std::shared_ptr<const Sizing> sizing_;
  double sized_radius(Vec2 q) const;
};

/// The count at area fraction 1 for a packing in a domain of the given area: A / (pi r^2
/// / 4) for one radius, the integral of 4 / (pi r(x)^2) with a sizing (then "area
/// fraction" is this relative density: docs/sizing.md). Targets (tuning.h) and the
/// quality report's eta are counts over it.
double density_unit(const Packing& packing, double area);

/// How many disks fit one after another along a planar domain's boundary: its length
/// over r, or the integral of 1 / r(s) along it with a sizing (by steps of a quarter of
/// r). Centers on the boundary have half their disk outside, so a thin domain holds more
/// than the hexagonal density of its area alone; targets allow this many more (for a
/// convex domain Oler's inequality needs half of it, plus one).
double boundary_unit(const PlanarDomain& domain, const Sizing* sizing, double r);
/// The same for a packing's domain and radius or sizing; 0 in the periodic box.
double boundary_unit(const Packing& packing);

}  // namespace disktune
