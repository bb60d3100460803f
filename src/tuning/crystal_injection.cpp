// SPDX-License-Identifier: GPL-3.0-or-later
// Crystal-growth injection (paper, 2.3). Two disks at distance r seed a crystal; the
// intersection points of frozen disks' circles are attractors, the sites of the
// hexagonal lattice around the crystal. A mobile disk that covers an attractor moves
// there and freezes (the disks it would conflict with are deleted, the voids left are
// refilled); an attractor no disk covers gets a new frozen disk at once. Attractors
// are taken in random order from the crystal's front (the paper allows visiting the
// disks near attractors instead of all disks), so one crystal grows over the box.
#include <algorithm>

#include "disktune/tuning.h"
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

bool inside_frozen(const Packing& p, Vec2 a) {
  return p.any_near(a, p.max_radius(), [&](const Neighbor& n) {
    return (p.flags(n.id) & kFrozen) && is_conflict(n.d2, n.radius);
  });
}

// Freezes disk `id` (now at `at`, in any frame) and adds the attractors its circle
// makes with the circles of its lattice neighbours: frozen disks at distance r. Their
// intersections are the sites of the hexagonal lattice the seed pair started, so the
// crystal stays that lattice (intersections with other frozen circles would grow a
// looser, random contact packing instead).
void freeze(detail::UndoLog& log, const Packing& p, DiskId id, Vec2 at, Attractors& attractors) {
  log.set_flags(id, p.flags(id) | kFrozen);
  const double r = p.radius(id);
  constexpr double kLattice = 1e-6;  // far above rounding drift, far below sqrt(3) - 1
  const double lo = r * r * (1 - kLattice), hi = r * r * (1 + kLattice);
  p.for_each_near(at, r * (1 + kLattice), [&](const Neighbor& f) {
    if (f.id == id || !(p.flags(f.id) & kFrozen) || f.d2 < lo || f.d2 > hi) return;
    const CircleIntersection x = intersect_circles(at, r, f.image, f.radius);
    for (int k = 0; k < x.count; ++k) {
      if (!inside_frozen(p, x.points[k])) attractors.add(x.points[k]);
    }
  });
}

// Two mobile disks at distance r (injected disks sit exactly r from two others), or,
// failing that, a neighbour moved onto a corner of its void that lies on p's circle.
bool seed(detail::UndoLog& log, Packing& p, Rng& rng, Attractors& attractors, std::size_t max_added) {
  const double r = p.max_radius();
  std::vector<DiskId> order = p.ids();
  for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[uniform_index(rng, i)]);
  const double lo = r * r * (1 - 4 * kRelTol), hi = r * r * (1 + 4 * kRelTol);
  for (const DiskId a : order) {
    if (!mobile(p, a)) continue;
    Neighbor partner{kNoDisk, {}, 0, 0};
    p.for_each_near(p.center(a), r * (1 + 4 * kRelTol), [&](const Neighbor& n) {
      if (n.id != a && mobile(p, n.id) && n.d2 >= lo && n.d2 <= hi) partner = n;
    });
    if (partner.id == kNoDisk) continue;
    freeze(log, p, a, p.center(a), attractors);
    freeze(log, p, partner.id, partner.image, attractors);
    return true;
  }
  std::vector<Corner> corners;
  for (std::size_t k = 0; k < std::min<std::size_t>(order.size(), 64); ++k) {
    const DiskId a = order[k];
    std::vector<Neighbor> near;
    p.for_each_near(p.center(a), 2 * r, [&](const Neighbor& n) {
      if (n.id != a && mobile(p, n.id)) near.push_back(n);
    });
    for (const Neighbor& q : near) {
      corners.clear();
      corners_in_region(p, q.image, r, {q.id}, corners);
      for (const Corner& c : corners) {
        if (c.a != a && c.b != a) continue;  // not on a's circle
        log.move(q.id, c.point);
        if (detail::repair_void(log, p, q.image, r, rng, max_added) > max_added) return false;
        freeze(log, p, a, p.center(a), attractors);
        freeze(log, p, q.id, p.frame().nearest_image(p.center(q.id), p.center(a)), attractors);
        return true;
      }
    }
  }
  return false;
}

}  // namespace

std::size_t crystal_inject(Packing& packing, Rng& rng, std::size_t max_added,
                           const std::function<void()>& after_step) {
  const double r = packing.max_radius();
  const std::size_t start = packing.size();
  Attractors attractors(packing.frame(), r);
  {
    detail::UndoLog log(packing);
    if (!seed(log, packing, rng, attractors, max_added)) {
      log.revert();
      return 0;
    }
  }
  // A step can lower the count (the disks it deletes may leave less room than they
  // took); steps are kept in a batch that is committed whenever the count is back at
  // or above where the last batch left it, so between committed batches the count
  // never falls. A batch still below at the end is taken back.
  const std::size_t limit = start + max_added;
  std::size_t committed = start;
  detail::UndoLog batch(packing);
  std::vector<DiskId> doomed;
  std::vector<Vec2> holes;
  while (!attractors.empty() && packing.size() < limit) {
    const Vec2 a = attractors.take_random(rng);
    if (inside_frozen(packing, a)) continue;
    const std::size_t step = batch.mark();
    // The mobile disk nearest to a that covers it.
    Neighbor mover{kNoDisk, {}, 0, 0};
    packing.for_each_near(a, r * (1 + kRelTol), [&](const Neighbor& n) {
      if (mobile(packing, n.id) && is_covered(n.d2, n.radius) && (mover.id == kNoDisk || n.d2 < mover.d2)) {
        mover = n;
      }
    });
    DiskId frozen = mover.id;
    if (mover.id == kNoDisk) {
      // Covered by nothing that can move (Fig. 4): a new frozen disk if there is room.
      if (packing.conflicts(a)) continue;
      frozen = batch.insert(a, r);
    } else {
      doomed.clear();
      holes.assign(1, mover.image);
      packing.for_each_near(a, r, [&](const Neighbor& n) {
        if (n.id != mover.id && is_conflict(n.d2, n.radius) &&
            std::find(doomed.begin(), doomed.end(), n.id) == doomed.end()) {
          doomed.push_back(n.id);
          holes.push_back(n.image);
        }
      });
      for (const DiskId x : doomed) batch.remove(x);
      batch.move(mover.id, a);
      const std::size_t room = limit + doomed.size() - packing.size();
      for (const Vec2& h : holes) detail::repair_void(batch, packing, h, r, rng, room);
    }
    if (packing.size() > limit) {  // never past the target
      batch.revert_to(step);
      continue;
    }
    freeze(batch, packing, frozen, a, attractors);
    if (packing.size() >= committed) {
      batch.commit();
      committed = packing.size();
      if (after_step) after_step();
    }
  }
  batch.revert();
  return packing.size() - start;
}

}  // namespace disktune
