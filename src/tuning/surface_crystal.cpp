// SPDX-License-Identifier: GPL-3.0-or-later
// Crystal growth on a surface (paper, 2.3 and 3.2, with the surface's geometry): the
// lattice sites next to two frozen disks at spacing s are the points of the surface at
// distance s from both (two balls' circles meeting in a triangle), so the crystal
// follows the surface and bends where it curves. The growth loop is crystal_grow.h's.
#include <algorithm>
#include <cmath>

#include "../geometry/triangle_arrangement.h"
#include "crystal_grow.h"
#include "disktune/errors.h"
#include "disktune/surface_tuning.h"
#include "surface_repair.h"

namespace disktune {
namespace {

bool mobile(const SurfacePacking& p, DiskId id) { return !(p.flags(id) & (kFixed | kFrozen)); }

class SurfaceLattice {
 public:
  SurfaceLattice(SurfacePacking& packing, Rng& rng, bool inject)
      : p_(packing),
        rng_(rng),
        r_(packing.max_radius()),
        s_(inject ? r_ : std::sqrt(3.0) * r_),
        inject_(inject),
        seen_(r_) {}

  SurfacePacking& packing() { return p_; }
  bool has_sites() const { return !sites_.empty(); }
  SurfacePoint take_site() {
    const std::size_t i = uniform_index(rng_, sites_.size());
    const SurfacePoint a = sites_[i];
    sites_[i] = sites_.back();
    sites_.pop_back();
    return a;
  }

  // A site is taken when a frozen center is closer than the spacing (the lattice there
  // is built).
  bool taken(const SurfacePoint& a) const {
    const double lim = s_ * (1 - kLattice);
    bool hit = false;
    p_.for_each_near(a.p, s_, [&](DiskId j) {
      hit = hit || ((p_.flags(j) & kFrozen) && squared_norm(p_.center(j) - a.p) < lim * lim);
    });
    return hit;
  }

  bool seed(detail::SurfaceUndoLog& log, std::size_t room) {
    std::vector<DiskId> order = p_.ids();
    for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[uniform_index(rng_, i)]);
    for (const DiskId a : order) {
      if (!mobile(p_, a)) continue;
      // A partner site at distance s: where the sphere S(a, s) crosses a triangle edge.
      std::vector<SurfacePoint> ring;
      std::vector<std::uint32_t> tris;
      p_.index().triangles_near(p_.center(a), s_, tris);
      const std::vector<Ball> ball{{p_.center(a), s_, a}};
      for (const std::uint32_t t : tris) {
        for_each_arrangement_vertex(p_.index().plane(t), ball, kRelTol * r_, [&](Vec3 x, DiskId u, DiskId v) {
          if (u == a && v == kNoDisk) ring.push_back({x, t});
        });
      }
      if (ring.empty()) continue;
      freeze(log, a);
      if (settle(log, ring[uniform_index(rng_, ring.size())], room)) return true;
      log.revert();
    }
    return false;
  }

  // The nearest mobile disk covering site a moves there (the disks it would conflict
  // with go, their voids are refilled), or, when injecting and nothing mobile covers a,
  // a new disk is put there if there is room. False when nothing could be done.
  bool settle(detail::SurfaceUndoLog& log, const SurfacePoint& a, std::size_t room) {
    DiskId mover = kNoDisk;
    double mover_d2 = 0;
    bool blocked = false;
    p_.for_each_near(a.p, r_ * (1 + kRelTol), [&](DiskId j) {
      const double d2 = squared_norm(p_.center(j) - a.p);
      if ((p_.flags(j) & kFixed) && is_conflict(d2, r_)) blocked = true;
      if (mobile(p_, j) && is_covered(d2, r_) && (mover == kNoDisk || d2 < mover_d2)) mover = j, mover_d2 = d2;
    });
    if (blocked) return false;  // a boundary disk holds the site
    if (mover == kNoDisk) {
      if (!inject_ || p_.conflicts(a.p)) return false;
      freeze(log, log.insert(a, 0));
      return true;
    }
    std::vector<DiskId> doomed;
    std::vector<Vec3> holes{p_.center(mover)};
    p_.for_each_near(a.p, r_, [&](DiskId j) {
      if (j != mover && is_conflict(squared_norm(p_.center(j) - a.p), r_)) {
        doomed.push_back(j);
        holes.push_back(p_.center(j));
      }
    });
    for (const DiskId x : doomed) {
      if (p_.flags(x) & kFrozen) return false;  // never undo the crystal
    }
    for (const DiskId x : doomed) log.remove(x);
    log.move(mover, a);
    for (const Vec3& h : holes) {
      if (detail::repair_void(log, p_, h, detail::void_reach(r_), rng_, room + doomed.size()) > room + doomed.size())
        return false;
    }
    freeze(log, mover);
    return true;
  }

  template <class Within>
  void tidy(detail::SurfaceUndoLog& log, const SurfacePoint& a, const Within& within) {
    std::vector<DiskId> around;
    p_.for_each_near(a.p, 2 * s_, [&](DiskId j) {
      if (mobile(p_, j)) around.push_back(j);
    });
    std::sort(around.begin(), around.end());
    for (const DiskId id : around) {
      if (p_.alive(id) && mobile(p_, id) && within(p_.size() - 1)) detail::attractor_eject(log, p_, id, rng_, 1, 1);
    }
  }

 private:
  static constexpr double kLattice = 1e-6;

  // Freezes disk `id` and adds the sites it makes with its lattice neighbours (frozen
  // disks at distance s).
  void freeze(detail::SurfaceUndoLog& log, DiskId id) {
    log.set_flags(id, p_.flags(id) | kFrozen);
    const Vec3 at = p_.center(id);
    const double lo = s_ * s_ * (1 - kLattice), hi = s_ * s_ * (1 + kLattice);
    std::vector<std::uint32_t> tris;
    p_.for_each_near(at, s_ * (1 + kLattice), [&](DiskId f) {
      const double d2 = squared_norm(p_.center(f) - at);
      if (f == id || !(p_.flags(f) & kFrozen) || d2 < lo || d2 > hi) return;
      const std::vector<Ball> pair{{at, s_, id}, {p_.center(f), s_, f}};
      p_.index().triangles_near(at, s_, tris);
      for (const std::uint32_t t : tris) {
        for_each_arrangement_vertex(p_.index().plane(t), pair, kRelTol * r_, [&](Vec3 x, DiskId u, DiskId v) {
          if (u != kNoDisk && v != kNoDisk) add_site({x, t});
        });
      }
    });
  }

  void add_site(const SurfacePoint& a) {
    if (taken(a)) return;
    bool dup = false;
    seen_.for_each_in_box(a.p, 1e-7 * r_, [&](std::uint32_t k) {
      dup = dup || squared_norm(all_[k].p - a.p) <= 1e-14 * r_ * r_;
    });
    if (dup) return;
    seen_.insert(static_cast<std::uint32_t>(all_.size()), a.p);
    all_.push_back(a);
    sites_.push_back(a);
  }

  SurfacePacking& p_;
  Rng& rng_;
  double r_, s_;
  bool inject_;
  SpaceGrid seen_;                 // every site ever added, to add each once
  std::vector<SurfacePoint> all_;  // indexed by seen_
  std::vector<SurfacePoint> sites_;
};

}  // namespace

std::size_t crystal_inject(SurfacePacking& packing, Rng& rng, std::size_t max_added,
                           const std::function<void()>& after_step) {
  detail::require_one_radius(packing.sizing().is_constant());
  SurfaceLattice lattice(packing, rng, true);
  return detail::grow_crystal<detail::SurfaceUndoLog>(lattice, true, max_added, after_step);
}

std::size_t crystal_eject(SurfacePacking& packing, Rng& rng, std::size_t max_removed,
                          const std::function<void()>& after_step) {
  detail::require_one_radius(packing.sizing().is_constant());
  SurfaceLattice lattice(packing, rng, false);
  return detail::grow_crystal<detail::SurfaceUndoLog>(lattice, false, max_removed, after_step);
}

}  // namespace disktune
