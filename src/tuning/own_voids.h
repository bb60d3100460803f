// SPDX-License-Identifier: GPL-3.0-or-later
// The void a disk of a surface packing leaves when lifted alone, kept from one ask to
// the next while no disk near it changes (internal). Sifting asks it of p and of each
// neighbour, the attractor's ranking and pulls of the same disks again and again; most
// of the time nothing near them has moved since.
#pragma once

#include <cstdint>
#include <vector>

#include "disktune/surface_packing.h"
#include "disktune/surface_voids.h"

namespace disktune::detail {

/// While one lives, own_voids on this thread keeps its answers for `packing` (the
/// object: a copy has its own serial and is not served). Nested ones: the inner serves.
class OwnVoidCache {
 public:
  explicit OwnVoidCache(const SurfacePacking& packing);
  ~OwnVoidCache();
  OwnVoidCache(const OwnVoidCache&) = delete;
  OwnVoidCache& operator=(const OwnVoidCache&) = delete;

 private:
  struct Entry {
    Vec3 center;
    std::uint64_t changes = 0;  // SurfacePacking::changes_near when it was last asked
    std::uint64_t read = 0;     // the disks the scan read (read_disks), when it was found
    bool kept = false;
    std::vector<SurfaceVoidPoint> voids;
  };
  std::uint64_t serial_;
  std::vector<Entry> entries_;
  OwnVoidCache* outer_;
  friend std::vector<SurfaceVoidPoint> own_voids(const SurfacePacking& packing, DiskId p);
};

/// The void points within void_reach of disk p's center with p lifted: voids_near's
/// answer, from the cache when one serves this packing, p has not moved, and the disks
/// the scan reads are where they were when it was found: nothing changed in the grid
/// cells around p, or the disks centered within the scan's reach are the same ones at
/// the same places, met in the same order (a 64-bit hash of their ids and places).
std::vector<SurfaceVoidPoint> own_voids(const SurfacePacking& packing, DiskId p);

}  // namespace disktune::detail
