// SPDX-License-Identifier: GPL-3.0-or-later
// Void injection (paper, 2.1) and the void repair it shares with the other operations.
#include "disktune/tuning.h"
#include "void_repair.h"

namespace disktune {
namespace detail {

std::pair<std::size_t, std::size_t> diameter_pair(const std::vector<Corner>& corners) {
  std::pair<std::size_t, std::size_t> best{0, 0};
  double best_d2 = -1;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    for (std::size_t j = i + 1; j < corners.size(); ++j) {
      const double d2 = squared_distance(corners[i].point, corners[j].point);
      if (d2 > best_d2) best_d2 = d2, best = {i, j};
    }
  }
  return best;
}

bool covers_all(Vec2 c, double r, const std::vector<Corner>& corners) {
  for (const Corner& k : corners) {
    if (!is_covered(squared_distance(c, k.point), r)) return false;
  }
  return true;
}

std::vector<Neighbor> mobile_neighbors(const Packing& packing, Vec2 point, DiskId self, Rng& rng) {
  std::vector<Neighbor> near;
  packing.for_each_near(point, 2 * packing.max_radius(), [&](const Neighbor& n) {
    if (n.id == self || (packing.flags(n.id) & (kFixed | kFrozen))) return;
    for (const Neighbor& m : near) {
      if (m.id == n.id) return;
    }
    near.push_back(n);
  });
  for (std::size_t i = near.size(); i > 1; --i) std::swap(near[i - 1], near[uniform_index(rng, i)]);
  return near;
}

bool void_free_near(const Packing& packing, Vec2 center, double r) {
  std::vector<Corner> corners;
  return !packing.any_near(center, 2 * r * (1 + kRelTol), [&](const Neighbor& n) {
    corners_on_circle(packing, n.id, corners);
    return !corners.empty();
  });
}

// One end of the diameter pair, chosen at random: a fixed choice would add a
// direction bias to every injected disk.
static Vec2 diameter_corner(const std::vector<Corner>& corners, Rng& rng) {
  const auto [i, j] = diameter_pair(corners);
  return corners[(rng() & 1) ? i : j].point;
}

std::size_t repair_void(UndoLog& log, const Packing& packing, Vec2 center, double r, Rng& rng,
                        std::size_t max_added) {
  std::vector<Corner> corners;
  for (std::size_t added = 0;; ++added) {
    corners.clear();
    corners_in_region(packing, center, r, {}, corners);
    if (corners.empty()) return added;
    if (added == max_added) return max_added + 1;
    log.insert(diameter_corner(corners, rng), r);
  }
}

}  // namespace detail

std::size_t void_inject(Packing& packing, DiskId p, Rng& rng, std::size_t max_added) {
  if (packing.flags(p) & (kFixed | kFrozen)) return 0;
  const Vec2 c = packing.center(p);
  const double r = packing.radius(p);
  std::vector<Corner> corners;
  corners_in_region(packing, c, r, {p}, corners);
  if (corners.empty()) return 0;  // no room: p's void is a point
  detail::UndoLog log(packing);
  const Vec2 to = detail::diameter_corner(corners, rng);
  log.move(p, to);
  if (detail::covers_all(to, r, corners)) return 0;  // diameter below r: the void is covered
  const std::size_t added = detail::repair_void(log, packing, c, r, rng, max_added);
  if (added > max_added) {
    log.revert();
    return 0;
  }
  return added;
}

}  // namespace disktune
