// SPDX-License-Identifier: GPL-3.0-or-later
#include "disktune/spatial_grid.h"

#include <algorithm>
#include <cassert>

#include "disktune/errors.h"

namespace disktune {

SpatialGrid::SpatialGrid(const Frame& frame, double max_cell_size) : frame_(frame) {
  // An integer number of cells per period, so the periodic wrap of cell indices is
  // exact; capped so that absurd inputs cannot ask for terabytes.
  auto cells = [&](double len) {
    const double n = std::ceil(len / max_cell_size);
    return static_cast<int>(std::clamp(n, 1.0, 32768.0));
  };
  nx_ = cells(frame.extent.x);
  ny_ = cells(frame.extent.y);
  hx_ = frame.extent.x / nx_;
  hy_ = frame.extent.y / ny_;
  inv_hx_ = 1 / hx_;
  inv_hy_ = 1 / hy_;
  capacity_ = 1;
  count_.assign(static_cast<std::size_t>(nx_) * ny_, 0);
  slots_.resize(count_.size() * capacity_);
}

std::size_t SpatialGrid::cell_index(Vec2 p) const {
  const int cx = std::clamp(static_cast<int>((p.x - frame_.origin.x) / hx_), 0, nx_ - 1);
  const int cy = std::clamp(static_cast<int>((p.y - frame_.origin.y) / hy_), 0, ny_ - 1);
  return static_cast<std::size_t>(cy) * nx_ + cx;
}

void SpatialGrid::insert(DiskId id, Vec2 p, double r) {
  const std::size_t c = cell_index(p);
  if (count_[c] == capacity_) grow();
  slots_[c * capacity_ + count_[c]++] = Slot{p, r, id};
}

void SpatialGrid::remove(DiskId id, Vec2 p) {
  const std::size_t c = cell_index(p);
  Slot* s = &slots_[c * capacity_];
  const int n = count_[c];
  for (int k = 0; k < n; ++k) {
    if (s[k].id == id) {
      s[k] = s[n - 1];
      s[n - 1] = Slot{};
      --count_[c];
      return;
    }
  }
  assert(false && "SpatialGrid::remove: id not found in its cell");
}

void SpatialGrid::grow() {
  const int old_cap = capacity_;
  // The counts are 16-bit: a cell takes 32768 disks at most. More means radii that vary
  // by a factor of some 300 within the grid (its cells are as wide as the largest
  // radius); check_resources refuses that before sampling, this stops anything else.
  if (old_cap >= 32768) {
    throw InvalidInput("more than 32768 disks in one cell of the neighbour grid, whose cells are as wide as the "
                       "largest radius: the radii vary too much; make the smallest radius larger or the largest "
                       "smaller");
  }
  const int new_cap = old_cap * 2;
  std::vector<Slot, detail::HugePageAllocator<Slot>> slots(count_.size() * new_cap);
  for (std::size_t c = 0; c < count_.size(); ++c) {
    std::copy_n(&slots_[c * old_cap], count_[c], &slots[c * new_cap]);
  }
  slots_.swap(slots);
  capacity_ = new_cap;
}

}  // namespace disktune
