// SPDX-License-Identifier: GPL-3.0-or-later
#include "own_voids.h"

#include <cstring>

#include "disktune/tolerance.h"
#include "surface_repair.h"

namespace disktune::detail {

namespace {
thread_local OwnVoidCache* active = nullptr;

std::uint64_t mix(std::uint64_t x) {  // splitmix64's finaliser
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// The disks but p that the scan of p's void reads (voids_near reads those centered
// within its reach and a largest radius), each with its place and triangle, in the
// order the scan meets them, hashed: where the hash is the same, so (but for a 64-bit
// collision) is what the scan reads, in the same order, and so its answer, bit for bit.
std::uint64_t read_disks(const SurfacePacking& packing, Vec3 c, double reach, DiskId p) {
  std::uint64_t hash = 0;
  packing.for_each_near(c, reach + packing.max_radius() * (1 + kRelTol), [&](DiskId j) {
    if (j == p) return;
    const SurfacePoint& at = packing.point(j);
    std::uint64_t bits[3];
    std::memcpy(bits, &at.p, sizeof bits);
    hash = mix(hash ^ (j | std::uint64_t{at.triangle} << 32));
    for (const std::uint64_t b : bits) hash = mix(hash ^ b);
  });
  return hash;
}
}  // namespace

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
  const bool same_center = e.kept && e.center.x == c.x && e.center.y == c.y && e.center.z == c.z;
  if (same_center && e.changes == changes) return e.voids;
  // Something changed in those cells, most often farther than the scan reads (they
  // span about three times its width): the disks it reads are compared first.
  const std::uint64_t read = read_disks(packing, c, reach, p);
  if (!same_center || e.read != read) {
    e.voids = voids_near(packing, c, reach, {p});
    e.center = c;
    e.read = read;
    e.kept = true;
  }
  e.changes = changes;
  return e.voids;
}

}  // namespace disktune::detail
