// SPDX-License-Identifier: GPL-3.0-or-later
// A uniform bucket grid over a Frame: O(1) insert, remove and move, and neighbour
// queries that return every periodic image in range (so boxes only a few radii wide
// are handled exactly). Cells have fixed-capacity slots in one flat array; a full
// cell doubles the capacity of all cells (amortised O(1); never, when the cells are
// small enough for the packing's separation).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
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
  int capacity_ = 0;
  std::vector<std::uint16_t> count_;
  struct Slot {
    Vec2 pos;
    double radius;
    DiskId id;
  };
  // Centers and radii beside the ids: queries read no other array. Huge pages: 92 MB at
  // 10^6 disks, read at random.
  std::vector<Slot, detail::HugePageAllocator<Slot>> slots_;
};

namespace detail {
inline int floor_div(int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
}  // namespace detail

template <class Pred>
bool SpatialGrid::any_near(Vec2 q, double R, Pred&& pred) const {
  const Vec2 o = frame_.origin;
  int ix0 = static_cast<int>(std::floor((q.x - R - o.x) / hx_));
  int ix1 = static_cast<int>(std::floor((q.x + R - o.x) / hx_));
  int iy0 = static_cast<int>(std::floor((q.y - R - o.y) / hy_));
  int iy1 = static_cast<int>(std::floor((q.y + R - o.y) / hy_));
  if (!frame_.periodic) {
    ix0 = std::max(ix0, 0), iy0 = std::max(iy0, 0);
    ix1 = std::min(ix1, nx_ - 1), iy1 = std::min(iy1, ny_ - 1);
  }
  const double R2 = R * R;
  for (int iy = iy0; iy <= iy1; ++iy) {
    const int wy = detail::floor_div(iy, ny_);
    const int cy = iy - wy * ny_;
    const double offy = wy * frame_.extent.y;
    for (int ix = ix0; ix <= ix1; ++ix) {
      const int wx = detail::floor_div(ix, nx_);
      const int cx = ix - wx * nx_;
      const Vec2 off{wx * frame_.extent.x, offy};
      const std::size_t cell = static_cast<std::size_t>(cy) * nx_ + cx;
      const std::size_t first = cell * capacity_;
      for (std::size_t k = first, end = first + count_[cell]; k < end; ++k) {
        const Slot& slot = slots_[k];
        const Vec2 image = slot.pos + off;
        const double d2 = squared_distance(image, q);
        if (d2 <= R2 && pred(Neighbor{slot.id, image, d2, slot.radius})) return true;
      }
    }
  }
  return false;
}

}  // namespace disktune
