// SPDX-License-Identifier: GPL-3.0-or-later
// Injection for angles (paper, 2.4): the circumcenter of an obtuse Delaunay triangle
// is a Voronoi vertex far from its sites, the likeliest place for a new disk; use it
// as the repeller point.
#include <algorithm>

#include "disktune/mesh.h"
#include "disktune/tuning.h"

namespace disktune {
namespace {

// True when the triangle has an angle above 90 degrees.
bool obtuse(Vec2 a, Vec2 b, Vec2 c) {
  return dot(b - a, c - a) < 0 || dot(a - b, c - b) < 0 || dot(a - c, b - c) < 0;
}

}  // namespace

std::size_t angle_inject(Packing& packing, Rng& rng, std::size_t max_added,
                         const std::function<void()>& after_step) {
  const TriangleMesh mesh = periodic_delaunay(packing);
  struct Target {
    Vec2 v;
    std::array<DiskId, 3> disks;
    std::array<Vec2, 3> at;  // where the disks were: a moved one retires the target
  };
  std::vector<Target> targets;
  for (const auto& t : mesh.triangles) {
    const Vec2 a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
    if (!obtuse(a, b, c)) continue;
    Target target{circumcenter(a, b, c), {}, {}};
    for (int k = 0; k < 3; ++k) {
      target.disks[k] = mesh.vertex_disk[t[k]];
      target.at[k] = packing.center(target.disks[k]);
    }
    targets.push_back(target);
  }
  for (std::size_t i = targets.size(); i > 1; --i) std::swap(targets[i - 1], targets[uniform_index(rng, i)]);

  std::size_t added = 0;
  for (const Target& t : targets) {
    if (added == max_added) break;
    bool stale = false;
    for (int k = 0; k < 3; ++k) {
      stale = stale || !packing.alive(t.disks[k]) || !(packing.center(t.disks[k]) == t.at[k]);
    }
    if (stale) continue;  // the triangle changed since the triangulation: next sweep
    const std::size_t n = repel_from(packing, t.v, kNoDisk, rng, max_added - added);
    added += n;
    if (after_step) after_step();
  }
  return added;
}

}  // namespace disktune
