// SPDX-License-Identifier: GPL-3.0-or-later
#include "own_voids.h"

#include "disktune/tolerance.h"
#include "surface_repair.h"

namespace disktune::detail {

namespace {
thread_local OwnVoidCache* active = nullptr;
}

OwnVoidCache::OwnVoidCache(const SurfacePacking& packing)
    : serial_(packing.serial()), outer_(active) {
  active = this;
}

OwnVoidCache::~OwnVoidCache() { active = outer_; }

std::vector<SurfaceVoidPoint> own_voids(const SurfacePacking& packing, DiskId p) {
  const Vec3 c = packing.center(p);
  const double reach = void_reach(packing.radius(p));
  OwnVoidCache* cache = active;
  if (!cache || cache->serial_ != packing.serial()) return voids_near(packing, c, reach, {p});
  // The scan reads the disks centered within reach + max_radius (with the tolerance) of
  // c: a change of any of them is counted in a cell meeting this box.
  const std::uint64_t changes = packing.changes_near(c, reach + packing.max_radius() * (1 + 1e-6));
  if (p >= cache->entries_.size()) cache->entries_.resize(packing.id_bound());
  OwnVoidCache::Entry& e = cache->entries_[p];
  if (!e.kept || e.changes != changes ||
      !(e.center.x == c.x && e.center.y == c.y && e.center.z == c.z)) {
    e.voids = voids_near(packing, c, reach, {p});
    e.center = c;
    e.changes = changes;
    e.kept = true;
  }
  return e.voids;
}

}  // namespace disktune::detail
