// SPDX-License-Identifier: GPL-3.0-or-later
// Each disk's neighbours within a fixed reach, read from a list made with a margin (Verlet's
// neighbour lists, as molecular dynamics keeps them) (internal). Relaxation asks for the
// same neighbours of every disk thirty times, and most disks move a little each sweep:
// a list read is a few loads where the grid's cells are a dozen hash lookups.
//
// Why the lists stay complete: each disk is listed from an anchor, where it was when
// its own list was last made, and once it lies more than `slack` from it, its list is
// made again from where it is, within reach + 3 slack, and it is added to the list of
// every disk found. Take two disks within reach of each other now, and the one, q,
// listed last, at time T. Since then neither has been relisted, so each lies within
// slack of its anchor, then and now; at T, p was within slack + reach + slack + slack
// of q: in q's new list, and q added to p's.
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <vector>

#include "../geometry/threads.h"
#include "disktune/surface_packing.h"
#include "disktune/tolerance.h"

namespace disktune::detail {

class NeighbourLists {
 public:
  /// Lists for the disks of ids below `id_bound`, of the disks within `reach`, a disk
  /// relisted once it moved `slack` from where it was listed.
  NeighbourLists(DiskId id_bound, double reach, double slack)
      : reach_(reach), slack_(slack), lists_(id_bound), anchor_(id_bound) {}

  /// How far from a disk the lists look, and so what relisting it reads and writes.
  double listed_reach() const { return reach_ + 3 * slack_; }

  /// Makes the lists where none are made (at first, or after `forget`), on up to
  /// `threads` threads: of the disks `ids` names, where given, else of every disk. A disk
  /// without a list must then stay where it is: the lists of those that move stay
  /// complete (a disk that stays needs no relisting, and one that moves lists itself).
  void make(const SurfacePacking& packing, unsigned threads,
            const std::vector<DiskId>* ids = nullptr) {
    if (made_) return;
    const std::vector<DiskId> all = ids ? std::vector<DiskId>{} : packing.ids();
    const std::vector<DiskId>& which = ids ? *ids : all;
    parallel_for(which.size(), threads, [&](std::size_t k, unsigned) { list(packing, which[k]); });
    made_ = true;
  }

  /// Drops the lists (disks moved by other means): `make` makes them anew.
  void forget() { made_ = false; }

  /// Records that disk p moved (to its center now). Writes the lists of the disks within
  /// listed_reach() of p.
  void moved(const SurfacePacking& packing, DiskId p) {
    if (squared_norm(packing.center(p) - anchor_[p]) <= slack_ * slack_) return;
    list(packing, p);
    for (const DiskId q : lists_[p]) {
      std::vector<DiskId>& theirs = lists_[q];
      const auto at = std::lower_bound(theirs.begin(), theirs.end(), p);
      if (at == theirs.end() || *at != p) theirs.insert(at, p);
    }
  }

  /// Whether a disk at x (p's place after a move) would meet a disk but p, as
  /// SurfacePacking::conflicts says, read from p's list where x lies close enough to p's
  /// center for it to hold every disk that x can meet; none where it does not.
  std::optional<bool> conflicts(const SurfacePacking& packing, DiskId p,
                                const SurfacePoint& x) const {
    if (norm(x.p - packing.center(p)) + packing.max_radius() > reach_) return std::nullopt;
    const PatchSet on = packing.patches_of(x);
    for (const DiskId q : lists_[p]) {
      if (is_conflict(squared_norm(packing.center(q) - x.p), packing.radius(q)) &&
          packing.share_patch(packing.patches(q), on))
        return true;
    }
    return false;
  }

  /// f(q, d2) for every disk q but p whose center lies within reach of c, p's center (at
  /// squared distance d2), in the order of their ids.
  template <class F>
  void for_each(const SurfacePacking& packing, DiskId p, Vec3 c, F&& f) const {
    const double R2 = reach_ * reach_;
    for (const DiskId q : lists_[p]) {
      const double d2 = squared_norm(packing.center(q) - c);
      if (d2 <= R2) f(q, d2);
    }
  }

 private:
  double reach_, slack_;
  std::vector<std::vector<DiskId>> lists_;  // each sorted by id
  std::vector<Vec3> anchor_;
  bool made_ = false;

  void list(const SurfacePacking& packing, DiskId p) {
    const Vec3 c = packing.center(p);
    std::vector<DiskId>& mine = lists_[p];
    mine.clear();
    packing.for_each_near(c, listed_reach(), [&](DiskId q) {
      if (q != p) mine.push_back(q);
    });
    std::sort(mine.begin(), mine.end());
    anchor_[p] = c;
  }
};

}  // namespace disktune::detail
