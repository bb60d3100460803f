// SPDX-License-Identifier: GPL-3.0-or-later
// The background grid of the MPS dart phase (internal). Base cells have a diagonal
// just below r, so each holds at most one center; the centers live in one flat array
// (NaN when empty: a NaN distance fails every comparison, so empty cells need no
// branch). Refinement level l splits each base cell in 2^l x 2^l cells.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "disktune/frame.h"
#include "disktune/geometry.h"
#include "disktune/huge_page_allocator.h"
#include "disktune/tolerance.h"

namespace disktune::detail {

struct Cell {
  std::uint32_t ix, iy;  // at its level's resolution
};
using CellList = std::vector<Cell, HugePageAllocator<Cell>>;  // read at random by darts

class DartGrid {
 public:
  DartGrid(const Frame& frame, double r);

  int mx() const { return mx_; }
  int my() const { return my_; }
  const std::vector<Vec2, HugePageAllocator<Vec2>>& centers() const { return centers_; }

  Vec2 size(int level) const { return size_[level]; }
  Vec2 corner(Cell c, int level) const;
  Cell base_of(Cell c, int level) const { return {c.ix >> level, c.iy >> level}; }
  bool filled(Cell base) const { return centers_[index(base)].x == centers_[index(base)].x; }
  void put(Cell base, Vec2 z) { centers_[index(base)] = z; }

  /// True when some center lies within r of z (a point of base cell b).
  bool conflicts(Vec2 z, Cell base) const;
  /// Asks the memory system for b's neighbourhood ahead of use.
  void prefetch_block(Cell base) const;

  /// Appends to `out` the children of cell c (at `level`) that no single disk covers
  /// (the cheap test, enough for most cells), or c itself when `split` is false.
  void keep_uncovered(Cell c, int level, bool split, std::vector<Cell>& out) const;
  /// Exact test: false when some point of the cell is uncovered, in which case
  /// `witness` is set to one such point, drawn uniformly from the uncovered part of the
  /// cell when a few darts find it (a corner of the uncovered part otherwise).
  template <class Rng>
  bool covered_exactly(Cell c, int level, Rng& uniform01, Vec2& witness) const;

 private:
  std::size_t index(Cell b) const { return static_cast<std::size_t>(b.iy) * mx_ + b.ix; }
  template <class Pred>
  bool any_in_block(Cell base, Pred&& pred) const;
  /// Images of the centers within `reach` of point q of base cell b; returns the count.
  int gather(Cell base, Vec2 q, double reach, Vec2 (&out)[32]) const;
  /// Uncovered vertices of the uncovered part of cell [lo, hi]; returns the count.
  int uncovered_vertices(Vec2 lo, Vec2 hi, const Vec2* disks, int n, Vec2 (&out)[64]) const;

  const Frame& frame_;
  double r_;
  int mx_, my_;     // base cells per axis: an integer number per period
  Vec2 size_[32];   // cell size at each level
  std::vector<Vec2, HugePageAllocator<Vec2>> centers_;
};

template <class Rng>
bool DartGrid::covered_exactly(Cell c, int level, Rng& uniform01, Vec2& witness) const {
  const Vec2 lo = corner(c, level), hi = lo + size(level);
  Vec2 disks[32];
  const Vec2 mid = (lo + hi) * 0.5;
  const int n = gather(base_of(c, level), mid, r_ + norm(hi - mid), disks);
  Vec2 vertices[64];
  const int nv = uncovered_vertices(lo, hi, disks, n, vertices);
  if (nv == 0) return true;
  // The uncovered part lies in the convex hull of its vertices (its arcs bulge into
  // it), so darts go into their bounding box.
  Vec2 blo = vertices[0], bhi = vertices[0];
  for (int k = 1; k < nv; ++k) {
    blo = {std::min(blo.x, vertices[k].x), std::min(blo.y, vertices[k].y)};
    bhi = {std::max(bhi.x, vertices[k].x), std::max(bhi.y, vertices[k].y)};
  }
  for (int t = 0; t < 64; ++t) {
    const Vec2 z{blo.x + uniform01() * (bhi.x - blo.x), blo.y + uniform01() * (bhi.y - blo.y)};
    bool free = true;
    for (int k = 0; k < n && free; ++k) free = !is_covered(squared_distance(z, disks[k]), r_);
    if (free) {
      witness = z;
      return false;
    }
  }
  witness = vertices[0];  // a vertex is a valid center: on at most two circles, in no disk
  return false;
}

}  // namespace disktune::detail
