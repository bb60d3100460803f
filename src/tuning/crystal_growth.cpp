// SPDX-License-Identifier: GPL-3.0-or-later
// Crystal growth (paper, 2.3 and 3.2). A hexagonal crystal of frozen disks with
// spacing s grows over the domain: s = r for injection (the densest packing, eta
// 0.9069), s = sqrt(3) r for ejection (the sparsest covering, eta 0.3023). Attractors
// are the lattice sites next to the crystal: the intersections of the radius-s circles
// around frozen disks at distance s (intersections with farther frozen disks would grow
// a looser random packing instead; measured eta 0.79 for injection). A mobile disk that
// covers an attractor moves there and freezes; the disks it would conflict with are
// deleted and the voids left are refilled. For injection, an attractor no disk covers
// gets a new frozen disk at once (Fig. 4, "inject immediately"). Attractors are taken in
// random order from the crystal's front (the paper allows visiting the disks near
// attractors instead of all disks), so one crystal grows over the box.
#include <algorithm>
#include <cmath>

#include "disktune/errors.h"
#include "disktune/tuning.h"
#include "crystal_grow.h"
#include "void_repair.h"

namespace disktune {
namespace {

// Attractor points with a grid for "is there one here already".
class Attractors {
 public:
  Attractors(const Frame& frame, double r) : grid_(frame, r), r_(r) {}
  bool empty() const { return live_.empty(); }
  void add(Vec2 a) {
    a = grid_.frame().wrap(a);
    if (grid_.any_near(a, 1e-7 * r_, [](const Neighbor&) { return true; })) return;
    const auto id = static_cast<DiskId>(points_.size());
    points_.push_back(a);
    grid_.insert(id, a, 0.0);
    live_.push_back(id);
  }
  Vec2 take_random(Rng& rng) {
    const std::size_t i = uniform_index(rng, live_.size());
    const DiskId id = live_[i];
    live_[i] = live_.back();
    live_.pop_back();
    grid_.remove(id, points_[id]);
    return points_[id];
  }

 private:
  SpatialGrid grid_;
  double r_;
  std::vector<Vec2> points_;
  std::vector<DiskId> live_;
};

bool mobile(const Packing& p, DiskId id) { return !(p.flags(id) & (kFixed | kFrozen)); }

class Crystal {
 public:
  Crystal(Packing& packing, Rng& rng, bool inject)
      : p_(packing),
        rng_(rng),
        r_(packing.max_radius()),
        s_(inject ? r_ : std::sqrt(3.0) * r_),
        inject_(inject),
        attractors_(packing.frame(), r_) {}

  // A site is taken when it lies strictly inside a frozen disk (injection) or closer
  // than the spacing to a frozen center (ejection: the lattice there is already built).
  bool taken(Vec2 a) const {
    const double lim = s_ * (1 - kLattice);
    return p_.any_near(a, s_, [&](const Neighbor& n) {
      return (p_.flags(n.id) & kFrozen) && n.d2 < lim * lim;
    });
  }

  // Freezes disk `id` (now at `at`, in any frame) and adds the sites its lattice
  // neighbours (frozen disks at distance s) make with it.
  void freeze(detail::UndoLog& log, DiskId id, Vec2 at) {
    log.set_flags(id, p_.flags(id) | kFrozen);
    const double lo = s_ * s_ * (1 - kLattice), hi = s_ * s_ * (1 + kLattice);
    p_.for_each_near(at, s_ * (1 + kLattice), [&](const Neighbor& f) {
      if (f.id == id || !(p_.flags(f.id) & kFrozen) || f.d2 < lo || f.d2 > hi) return;
      const CircleIntersection x = intersect_circles(at, s_, f.image, s_);
      for (int k = 0; k < x.count; ++k) {
        if (!taken(x.points[k])) attractors_.add(x.points[k]);
      }
    });
  }

  // Brings a disk to site a and freezes it: the nearest mobile disk covering a moves
  // there (the disks it would conflict with go, their voids are refilled), or, when
  // injecting and nothing mobile covers a, a new disk is put there if there is room.
  // False when nothing could be done; the caller then takes back what `log` holds since
  // the call.
  bool settle(detail::UndoLog& log, Vec2 a, std::size_t room) {
    // A site outside the domain, or one a fixed (boundary) disk holds, stays empty.
    if (!p_.inside(a) || p_.any_near(a, r_, [&](const Neighbor& n) {
          return (p_.flags(n.id) & kFixed) && is_conflict(n.d2, n.radius);
        })) {
      return false;
    }
    Neighbor mover{kNoDisk, {}, 0, 0};
    p_.for_each_near(a, r_ * (1 + kRelTol), [&](const Neighbor& n) {
      if (mobile(p_, n.id) && is_covered(n.d2, n.radius) && (mover.id == kNoDisk || n.d2 < mover.d2)) {
        mover = n;
      }
    });
    if (mover.id == kNoDisk) {
      if (!inject_ || p_.conflicts(a)) return false;
      freeze(log, log.insert(a, r_), a);
      return true;
    }
    std::vector<DiskId> doomed;
    std::vector<Vec2> holes{mover.image};
    p_.for_each_near(a, r_, [&](const Neighbor& n) {
      if (n.id != mover.id && is_conflict(n.d2, n.radius) &&
          std::find(doomed.begin(), doomed.end(), n.id) == doomed.end()) {
        doomed.push_back(n.id);
        holes.push_back(n.image);
      }
    });
    for (const DiskId x : doomed) log.remove(x);
    log.move(mover.id, a);
    for (const Vec2& h : holes) {
      // A void that needs more disks than the target allows is left half filled by
      // repair_void: the step fails, and the caller takes it back.
      if (detail::repair_void(log, p_, h, r_, rng_, room + doomed.size()) > room + doomed.size()) {
        return false;
      }
    }
    freeze(log, mover.id, a);
    return true;
  }

  // Two disks at distance s: an existing mobile pair (injected disks often sit exactly
  // r apart), or a random mobile disk and a disk brought to a random site at distance s.
  bool seed(detail::UndoLog& log, std::size_t room) {
    std::vector<DiskId> order = p_.ids();
    for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[uniform_index(rng_, i)]);
    const double lo = s_ * s_ * (1 - 4 * kRelTol), hi = s_ * s_ * (1 + 4 * kRelTol);
    for (const DiskId a : order) {
      if (!mobile(p_, a)) continue;
      Neighbor partner{kNoDisk, {}, 0, 0};
      p_.for_each_near(p_.center(a), s_ * (1 + 4 * kRelTol), [&](const Neighbor& n) {
        if (n.id != a && mobile(p_, n.id) && n.d2 >= lo && n.d2 <= hi) partner = n;
      });
      if (partner.id == kNoDisk) continue;
      freeze(log, a, p_.center(a));
      freeze(log, partner.id, partner.image);
      return true;
    }
    for (const DiskId a : order) {
      if (!mobile(p_, a)) continue;
      const double angle = 2 * 3.14159265358979323846 * uniform01(rng_);
      freeze(log, a, p_.center(a));
      if (settle(log, p_.center(a) + Vec2{std::cos(angle), std::sin(angle)} * s_, room)) return true;
      log.revert();
    }
    return false;
  }

  // What grow_crystal needs besides seed, taken and settle.
  Packing& packing() { return p_; }
  bool has_sites() const { return !attractors_.empty(); }
  Vec2 take_site() { return attractors_.take_random(rng_); }

  // After a site settled in ejection: the mobile disks around it go through attractor
  // ejection (3.2: disks that cover no attractor move as in attractor ejection), which
  // removes those the lattice made redundant and pays for the voids the step refilled.
  template <class Within>
  void tidy(detail::UndoLog& log, Vec2 a, const Within& within) {
    std::vector<DiskId> around;
    p_.for_each_near(a, 2 * s_, [&](const Neighbor& n) {
      if (mobile(p_, n.id)) around.push_back(n.id);
    });
    for (const DiskId id : around) {
      if (p_.alive(id) && mobile(p_, id) && within(p_.size() - 1)) detail::attractor_eject(log, p_, id, rng_, 1, 1);
    }
  }

 private:
  static constexpr double kLattice = 1e-6;  // far above rounding drift, far below any lattice gap

  Packing& p_;
  Rng& rng_;
  double r_, s_;
  bool inject_;
  Attractors attractors_;
};

}  // namespace

std::size_t crystal_inject(Packing& packing, Rng& rng, std::size_t max_added,
                           const std::function<void()>& after_step) {
  detail::require_one_radius(packing.sizing() == nullptr);
  Crystal crystal(packing, rng, true);
  return detail::grow_crystal<detail::UndoLog>(crystal, true, max_added, after_step);
}

std::size_t crystal_eject(Packing& packing, Rng& rng, std::size_t max_removed,
                          const std::function<void()>& after_step) {
  detail::require_one_radius(packing.sizing() == nullptr);
  Crystal crystal(packing, rng, false);
  return detail::grow_crystal<detail::UndoLog>(crystal, false, max_removed, after_step);
}

}  // namespace disktune
