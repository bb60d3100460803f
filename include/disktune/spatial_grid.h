// SPDX-License-Identifier: GPL-3.0-or-later
// A uniform bucket grid over a Frame: O(1) insert, remove and move, and neighbour
// queries that return every periodic image in range (so boxes only a few radii wide
// are handled exactly). Cells have fixed-capacity slots in one flat array; a full
// cell doubles the capacity of all cells (amortised O(1); never, when the cells are
// small enough for the packing's separation).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "disktune/frame.h"
#include "disktune/geometry.h"
#include "disktune/huge_page_allocator.h"

namespace disktune {

using DiskId = std::uint32_t;

/// What a neighbour query reports for one periodic image of one disk.
struct Neighbor {
  DiskId id;
  Vec2 image;     // the image's center, in the query point's unwrapped frame
  double d2;      // its squared distance to the query point
  double radius;  // the disk's radius
};

class SpatialGrid {
 public:
  SpatialGrid() = default;
  /// Cells are at most `max_cell_size` wide, with an integer number per period. Cells
  /// of a diagonal below the smallest center distance hold one disk each, which keeps
  /// the grid small (one slot per cell) and queries cache-friendly.
  SpatialGrid(const Frame& frame, double max_cell_size);

  /// Registers disk `id` with center `p` (wrapped into the frame) and radius `r`.
  void insert(DiskId id, Vec2 p, double r);
  /// Unregisters `id`, known to be at position `p`.
  void remove(DiskId id, Vec2 p);

  /// Calls f(const Neighbor&) for every image of a registered disk whose center lies
  /// within distance R of q.
  template <class F>
  void for_each_near(Vec2 q, double R, F&& f) const {
    any_near(q, R, [&](const Neighbor& n) { return f(n), false; });
  }

  /// Like for_each_near, but stops at, and returns true on, the first neighbour for
  /// which `pred` returns true.
  template <class Pred>
  bool any_near(Vec2 q, double R, Pred&& pred) const;

  const Frame& frame() const { return frame_; }

 private:
  std::size_t cell_index(Vec2 p) const;
  void grow();

  Frame frame_;
  int nx_ = 0, ny_ = 0;
  double hx_ = 1, hy_ = 1;
  double inv_hx_ = 1, inv_hy_ = 1;  // cells per unit length, for the queries
  int capacity_ = 0;
  std::vector<std::uint16_t> count_;
  // An empty slot lies at infinity: no query reaches it.
  struct Slot {
    Vec2 pos{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    double radius = 0;
    DiskId id = 0;
  };
  // Centers and radii beside the ids: queries read no other array. Huge pages: 92 MB at
  // 10^6 disks, read at random.
  std::vector<Slot, detail::HugePageAllocator<Slot>> slots_;
};

namespace detail {
inline int floor_div(int a, int b) {
  if (a >= 0 && a < b) return 0;  // most queries, without a division
  return a >= 0 ? a / b : -((-a + b - 1) / b);
}
// floor(v) for |v| < 2^31, without a call to libm's floor.
inline int floor_int(double v) {
  const int i = static_cast<int>(v);
  return i - (v < i);
}
}  // namespace detail

template <class Pred>
bool SpatialGrid::any_near(Vec2 q, double R, Pred&& pred) const {
  const double x = q.x - frame_.origin.x, y = q.y - frame_.origin.y;
  const double R2 = R * R;
  // Each row visits only the columns its part of the disk of radius R can reach (for
  // large R a fifth fewer cells than the bounding square); `slack` widens the reach
  // against rounding. A bounded frame's border cells reach out to infinity, since
  // centers outside it are clamped into them: queries outside visit them too.
  const double slack = 1e-9 * (hx_ + hy_) + 1e-12 * (std::abs(x) + std::abs(y) + R);
  int iy0 = detail::floor_int((y - R - slack) * inv_hy_);
  int iy1 = detail::floor_int((y + R + slack) * inv_hy_);
  if (!frame_.periodic) iy0 = std::clamp(iy0, 0, ny_ - 1), iy1 = std::clamp(iy1, 0, ny_ - 1);
  int wy = detail::floor_div(iy0, ny_);
  int cy = iy0 - wy * ny_;
  for (int iy = iy0; iy <= iy1; ++iy, ++cy) {
    if (cy == ny_) cy = 0, ++wy;
    const bool open_below = !frame_.periodic && iy == 0,
               open_above = !frame_.periodic && iy == ny_ - 1;
    const double lo = iy * hy_, hi = lo + hy_;
    double dy = y < lo && !open_below ? lo - y : y > hi && !open_above ? y - hi : 0.0;
    dy = std::max(dy - slack, 0.0);
    const double half = std::sqrt(std::max(R2 - dy * dy, 0.0)) + slack;
    int jx0 = detail::floor_int((x - half) * inv_hx_);
    int jx1 = detail::floor_int((x + half) * inv_hx_);
    if (!frame_.periodic) jx0 = std::clamp(jx0, 0, nx_ - 1), jx1 = std::clamp(jx1, 0, nx_ - 1);
    const double offy = wy * frame_.extent.y;
    const std::size_t row = static_cast<std::size_t>(cy) * nx_;
    int wx = detail::floor_div(jx0, nx_);
    int cx = jx0 - wx * nx_;
    // Runs of columns within one period share the image offset, and their slots are
    // contiguous. Empty slots lie at infinity, so the slots are scanned without their
    // counts, the hits gathered without branches and handed to `pred` in slot order.
    for (int jx = jx0; jx <= jx1; cx = 0, ++wx) {
      const int run = std::min(jx1 - jx, nx_ - 1 - cx) + 1;
      jx += run;
      const Vec2 off{wx * frame_.extent.x, offy};
      const Slot* slot = slots_.data() + (row + cx) * capacity_;
      const Slot* const end = slot + static_cast<std::size_t>(run) * capacity_;
      constexpr int kChunk = 64;
      std::uint8_t hit[kChunk];
      for (; slot < end; slot += kChunk) {
        const int n = static_cast<int>(std::min<std::ptrdiff_t>(end - slot, kChunk));
        int hits = 0;
        for (int k = 0; k < n; ++k) {
          hit[hits] = static_cast<std::uint8_t>(k);
          hits += squared_distance(slot[k].pos + off, q) <= R2;
        }
        for (int h = 0; h < hits; ++h) {
          const Slot& s = slot[hit[h]];
          const Vec2 image = s.pos + off;
          if (pred(Neighbor{s.id, image, squared_distance(image, q), s.radius})) return true;
        }
      }
    }
  }
  return false;
}

}  // namespace disktune
