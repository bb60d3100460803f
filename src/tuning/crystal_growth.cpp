// SPDX-License-Identifier: GPL-3.0-or-later
// Crystal growth (paper, 2.3 and 3.2), once for the plane and surfaces (space.h). A
// hexagonal crystal of frozen disks with spacing s grows over the domain: s = r for
// injection (the densest packing, eta 0.9069), s = sqrt(3) r for ejection (the sparsest
// covering, eta 0.3023). Attractors are the lattice sites next to the crystal: the
// points at distance s from two frozen disks at distance s (in the plane, where their
// radius-s circles cross; on a surface, where the two balls' circles meet a triangle,
// so the crystal follows the surface and bends where it curves). Sites next to farther
// frozen disks would grow a looser random packing instead (measured eta 0.79 for
// injection). A mobile disk that covers an attractor moves there and freezes; the disks
// it would conflict with are deleted and the voids left are refilled. For injection,
// an attractor no disk covers gets a new frozen disk at once (Fig. 4, "inject
// immediately"). Attractors are taken in random order from the crystal's front (the
// paper allows visiting the disks near attractors instead of all disks), so one crystal
// grows over the domain. Grain injection (beyond the paper; issue #19) seeds many
// crystals at once, far apart, at orientations spread evenly over the lattice's period,
// and grows them together from one front: they meet in grain boundaries, and the
// packing keeps no common orientation. The batch-and-commit loop is crystal_grow.h's.
#include <algorithm>
#include <cmath>

#include "disktune/errors.h"
#include "disktune/surface_tuning.h"
#include "disktune/tuning.h"
#include "attractor_rings.h"
#include "crystal_grow.h"
#include "space.h"

namespace disktune {
namespace {

template <class P>
class Crystal {
  using S = detail::Space<P>;
  using Point = typename S::Point;
  using Location = typename S::Location;
  using Near = typename S::Near;
  using Log = detail::BasicUndoLog<P>;

 public:
  // disks_per_grain 0: one crystal; else one nucleus for each that many disks.
  Crystal(P& packing, Rng& rng, bool inject, std::size_t disks_per_grain = 0)
      : p_(packing),
        rng_(rng),
        r_(packing.max_radius()),
        s_(inject ? r_ : std::sqrt(3.0) * r_),
        inject_(inject),
        disks_per_grain_(disks_per_grain),
        sites_(packing, r_) {}

  // What grow_crystal needs besides seed, taken and settle.
  P& packing() { return p_; }
  bool has_sites() const { return !sites_.empty(); }
  Point take_site() { return sites_.take_random(rng_); }

  // A site is taken when it lies strictly inside a frozen disk (injection) or closer
  // than the spacing to a frozen center (ejection: the lattice there is already built).
  bool taken(const Point& a) const {
    const double lim = s_ * (1 - kLattice);
    return S::any_near(p_, S::location(a), s_, [&](const Near& n) {
      return (p_.flags(n.id) & kFrozen) && n.d2 < lim * lim;
    });
  }

  // Brings a disk to site a and freezes it: the nearest mobile disk covering a moves
  // there (the disks it would conflict with go, their voids are refilled), or, when
  // injecting and nothing mobile covers a, a new disk is put there if there is room.
  // False when nothing could be done; the caller then takes back what `log` holds since
  // the call.
  bool settle(Log& log, const Point& a, std::size_t room) {
    const Location at = S::location(a);
    // A site outside the domain, or one a fixed (boundary) disk holds, stays empty.
    if (!S::inside(p_, a) || S::any_near(p_, at, r_, [&](const Near& n) {
          return (p_.flags(n.id) & kFixed) && is_conflict(n.d2, n.radius);
        })) {
      return false;
    }
    Near mover{kNoDisk, {}, 0, 0};
    S::for_each_near(p_, at, r_ * (1 + kRelTol), [&](const Near& n) {
      if (mobile(n.id) && is_covered(n.d2, n.radius) && (mover.id == kNoDisk || n.d2 < mover.d2)) mover = n;
    });
    if (mover.id == kNoDisk) {
      if (!inject_ || p_.conflicts(a)) return false;
      freeze(log, log.insert(a, r_), at);
      return true;
    }
    std::vector<DiskId> doomed;
    std::vector<Location> holes{mover.image};
    bool breaks_crystal = false;
    S::for_each_near(p_, at, r_, [&](const Near& n) {
      if (n.id != mover.id && is_conflict(n.d2, n.radius) &&
          std::find(doomed.begin(), doomed.end(), n.id) == doomed.end()) {  // one image each
        doomed.push_back(n.id);
        holes.push_back(n.image);
        breaks_crystal = breaks_crystal || (p_.flags(n.id) & kFrozen);
      }
    });
    if (breaks_crystal) return false;  // never undo the crystal (frozen by an earlier call)
    for (const DiskId x : doomed) log.remove(x);
    log.move(mover.id, a);
    for (const Location& h : holes) {
      // A void that needs more disks than the target allows is left half filled by
      // repair_void: the step fails, and the caller takes it back.
      if (S::repair_void(log, p_, h, S::void_reach(r_), rng_, room + doomed.size()) > room + doomed.size()) {
        return false;
      }
    }
    freeze(log, mover.id, at);
    return true;
  }

  // Two disks at distance s: an existing mobile pair (injected disks often sit exactly
  // r apart), or a random mobile disk and a disk brought to a random site at distance s.
  // For grains, many such nuclei (seed_grains).
  bool seed(Log& log, std::size_t room) {
    const std::vector<DiskId> order = shuffled_ids();
    if (disks_per_grain_ > 0) return seed_grains(log, order, room);
    const double lo = s_ * s_ * (1 - 4 * kRelTol), hi = s_ * s_ * (1 + 4 * kRelTol);
    for (const DiskId a : order) {
      if (!mobile(a)) continue;
      Near partner{kNoDisk, {}, 0, 0};
      S::for_each_near(p_, p_.center(a), s_ * (1 + 4 * kRelTol), [&](const Near& n) {
        if (n.id != a && mobile(n.id) && n.d2 >= lo && n.d2 <= hi) partner = n;
      });
      if (partner.id == kNoDisk) continue;
      freeze(log, a, p_.center(a));
      freeze(log, partner.id, partner.image);
      return true;
    }
    for (const DiskId a : order) {
      if (!mobile(a)) continue;
      Point site;
      if (!S::point_at(p_, a, s_, rng_, site)) continue;
      freeze(log, a, p_.center(a));
      if (settle(log, site, room)) return true;
      log.revert();
    }
    return false;
  }

  // One nucleus for each disks_per_grain disks: a random mobile disk with a disk brought
  // to a site at distance s, none nearer than half the side of a grain's area (in
  // spacings: sqrt(disks_per_grain)) to a frozen disk, so that the nuclei spread over
  // the domain and each has room to grow. Their orientations are spread evenly over the
  // lattice's period (a sixth of a turn) from a random start, not drawn independently:
  // grains of equal size then cancel in the global psi6 (independent ones leave about
  // 1/sqrt(grains) of it; the README's job, 34 grains: 0.10-0.20).
  bool seed_grains(Log& log, const std::vector<DiskId>& order, std::size_t room) {
    const std::size_t wanted = std::max<std::size_t>(1, p_.size() / disks_per_grain_);
    const double apart = 0.5 * s_ * std::sqrt(static_cast<double>(disks_per_grain_));
    const double start = uniform01(rng_);
    std::size_t seeded = 0;
    for (const DiskId a : order) {
      if (seeded == wanted) break;
      if (!p_.alive(a) || !mobile(a) || S::any_near(p_, p_.center(a), apart, [&](const Near& n) {
            return (p_.flags(n.id) & kFrozen) != 0;
          }))
        continue;
      Point site;
      const double turn = (static_cast<double>(seeded) + start) / static_cast<double>(wanted) / 6;
      if (!S::point_at_turn(p_, a, s_, turn, site)) continue;
      const std::size_t mark = log.mark();
      freeze(log, a, p_.center(a));
      if (settle(log, site, room))
        ++seeded;
      else
        log.revert_to(mark);
    }
    return seeded > 0;
  }

  // After a site settled in ejection: the mobile disks around it go through attractor
  // ejection (3.2: disks that cover no attractor move as in attractor ejection), which
  // removes those the lattice made redundant and pays for the voids the step refilled.
  template <class Within>
  void tidy(Log& log, const Point& a, const Within& within) {
    std::vector<DiskId> around;
    S::for_each_near(p_, S::location(a), 2 * s_, [&](const Near& n) {
      if (mobile(n.id)) around.push_back(n.id);
    });
    S::stable_order(around);
    for (const DiskId id : around) {
      if (p_.alive(id) && mobile(id) && within(p_.size() - 1)) detail::attractor_eject(log, p_, id, rng_, 1, 1);
    }
  }

 private:
  static constexpr double kLattice = 1e-6;  // far above rounding drift, far below any lattice gap

  bool mobile(DiskId id) const { return !(p_.flags(id) & (kFixed | kFrozen)); }

  std::vector<DiskId> shuffled_ids() {
    std::vector<DiskId> order = p_.ids();
    for (std::size_t i = order.size(); i > 1; --i)
      std::swap(order[i - 1], order[uniform_index(rng_, i)]);
    return order;
  }

  // Freezes disk `id` (now at `at`; on the torus, in any frame) and adds the sites its
  // lattice neighbours (frozen disks at distance s) make with it.
  void freeze(Log& log, DiskId id, Location at) {
    log.set_flags(id, p_.flags(id) | kFrozen);
    const double lo = s_ * s_ * (1 - kLattice), hi = s_ * s_ * (1 + kLattice);
    S::for_each_near(p_, at, s_ * (1 + kLattice), [&](const Near& f) {
      if (f.id == id || !(p_.flags(f.id) & kFrozen) || f.d2 < lo || f.d2 > hi) return;
      S::for_each_site(p_, at, id, f.image, f.id, s_, [&](const Point& x) {
        if (!taken(x)) sites_.add(x);
      });
    });
  }

  P& p_;
  Rng& rng_;
  double r_, s_;
  bool inject_;
  std::size_t disks_per_grain_;
  typename S::Sites sites_;
};

bool one_radius(const Packing& packing) { return packing.sizing() == nullptr; }
bool one_radius(const SurfacePacking& packing) { return packing.sizing().is_constant(); }

template <class P>
std::size_t grow(P& packing, Rng& rng, bool inject, std::size_t max_change,
                 const std::function<void()>& after_step, std::size_t disks_per_grain = 0) {
  detail::require_one_radius(one_radius(packing));
  Crystal<P> crystal(packing, rng, inject, disks_per_grain);
  return detail::grow_crystal<detail::BasicUndoLog<P>>(crystal, inject, max_change, after_step);
}

}  // namespace

std::size_t crystal_inject(Packing& packing, Rng& rng, std::size_t max_added, const std::function<void()>& after_step) {
  return grow(packing, rng, true, max_added, after_step);
}
std::size_t crystal_eject(Packing& packing, Rng& rng, std::size_t max_removed,
                          const std::function<void()>& after_step) {
  return grow(packing, rng, false, max_removed, after_step);
}
std::size_t grain_inject(Packing& packing, Rng& rng, std::size_t max_added,
                         const std::function<void()>& after_step, std::size_t disks_per_grain) {
  return grow(packing, rng, true, max_added, after_step, std::max<std::size_t>(disks_per_grain, 1));
}
std::size_t crystal_inject(SurfacePacking& packing, Rng& rng, std::size_t max_added,
                           const std::function<void()>& after_step) {
  return grow(packing, rng, true, max_added, after_step);
}
std::size_t crystal_eject(SurfacePacking& packing, Rng& rng, std::size_t max_removed,
                          const std::function<void()>& after_step) {
  return grow(packing, rng, false, max_removed, after_step);
}
std::size_t grain_inject(SurfacePacking& packing, Rng& rng, std::size_t max_added,
                         const std::function<void()>& after_step, std::size_t disks_per_grain) {
  return grow(packing, rng, true, max_added, after_step, std::max<std::size_t>(disks_per_grain, 1));
}

}  // namespace disktune
