// SPDX-License-Identifier: GPL-3.0-or-later
// Attractor ejection over an undo log, and the disks around p, ring by ring, that it
// pulls (internal; planar and surface packings both use it).
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "disktune/packing.h"
#include "disktune/random.h"
#include "undo_log.h"

namespace disktune::detail {

/// Rings of neighbours the wide attractor phase pulls (the automatic schedule's last
/// ejection phase). One ring stalls near 0.63 times an MPS's count on a curved or
/// bounded domain; three rings reach about 0.60 (docs/tuning.md), at about four times
/// the cost of an operation.
inline constexpr int kWideAttractorRings = 3;

/// Attractor ejection of p over `rings` rings of neighbours (tuning.h), its edits
/// recorded in `log` (taken back to where they started when it fails), so that a caller
/// such as crystal ejection can take it back too. Defined in attractor_ejection.cpp for
/// Packing and SurfacePacking.
template <class P>
std::size_t attractor_eject(BasicUndoLog<P>& log, P& packing, DiskId p, Rng& rng, std::size_t max_removed, int rings);

/// One disk to pull: the item (a disk, or a disk with its image) and the index, in the
/// same list, of the disk nearer p it is pulled toward (entry 0 is p itself).
template <class Item>
struct RingPull {
  Item item;
  std::size_t toward;
};

/// p and the disks within `rings` neighbour steps of it, each once, ring by ring;
/// neighbors_of(item) lists an item's neighbours, id_of(item) names its disk.
template <class Item, class NeighborsOf, class IdOf>
std::vector<RingPull<Item>> rings_around(const Item& p, int rings, NeighborsOf&& neighbors_of, IdOf&& id_of) {
  std::vector<RingPull<Item>> out{{p, 0}};
  std::vector<DiskId> seen{id_of(p)};
  std::size_t ring_begin = 0;
  for (int ring = 0; ring < rings; ++ring) {
    const std::size_t ring_end = out.size();
    for (std::size_t i = ring_begin; i < ring_end; ++i) {
      for (const Item& next : neighbors_of(out[i].item)) {
        const DiskId id = id_of(next);
        if (std::find(seen.begin(), seen.end(), id) != seen.end()) continue;
        seen.push_back(id);
        out.push_back({next, i});
      }
    }
    ring_begin = ring_end;
  }
  return out;
}

}  // namespace disktune::detail
