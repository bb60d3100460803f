// SPDX-License-Identifier: GPL-3.0-or-later
#include "dart_grid.h"

#include <cmath>
#include <limits>

#include "../voids/corner_cover.h"
#include "disktune/spatial_grid.h"  // detail::floor_div

namespace disktune::detail {
namespace {

// The 5 x 5 block around a base cell, nearest cells first, so that tests which stop
// at the first hit (a conflict, a covering disk) usually stop early. A disk of radius
// r spans under 1.5 base cells, so the block holds every disk that can reach the cell.
constexpr int kBlock[25][2] = {{0, 0},   {1, 0},   {-1, 0},  {0, 1},  {0, -1}, {1, 1},   {-1, 1},
                               {1, -1},  {-1, -1}, {2, 0},   {-2, 0}, {0, 2},  {0, -2},  {2, 1},
                               {2, -1},  {-2, 1},  {-2, -1}, {1, 2},  {-1, 2}, {1, -2},  {-1, -2},
                               {2, 2},   {-2, 2},  {2, -2},  {-2, -2}};

}  // namespace

// Calls pred(center image) for the centers of the block around b, nearest first, and
// stops at the first true. Away from the frame's edges the block is 25 fixed offsets
// into the flat array; near them, indices wrap with periodic image offsets (a box only
// a few cells wide visits one cell at several offsets) or are skipped (no periodicity).
template <class Pred>
bool DartGrid::any_in_block(Cell b, Pred&& pred) const {
  const int bx = static_cast<int>(b.ix), by = static_cast<int>(b.iy);
  if (bx >= 2 && bx < mx_ - 2 && by >= 2 && by < my_ - 2) {
    const Vec2* base = &centers_[index(b)];
    for (const auto& o : kBlock) {
      if (pred(base[o[1] * mx_ + o[0]])) return true;
    }
    return false;
  }
  for (const auto& o : kBlock) {
    int ix = bx + o[0], iy = by + o[1];
    Vec2 off{0, 0};
    if (ix < 0 || ix >= mx_ || iy < 0 || iy >= my_) {
      if (!frame_.periodic) continue;
      const int wx = floor_div(ix, mx_), wy = floor_div(iy, my_);
      ix -= wx * mx_, iy -= wy * my_;
      off = {wx * frame_.extent.x, wy * frame_.extent.y};
    }
    if (pred(centers_[static_cast<std::size_t>(iy) * mx_ + ix] + off)) return true;
  }
  return false;
}

namespace {
}  // namespace

DartGrid::DartGrid(const Frame& frame, double r) : frame_(frame), r_(r) {
  const double side = r * 0.70710678118654752 * (1 - 1e-6);
  mx_ = static_cast<int>(std::ceil(frame.extent.x / side));
  my_ = static_cast<int>(std::ceil(frame.extent.y / side));
  for (int level = 0; level < 32; ++level) {
    size_[level] = {std::ldexp(frame.extent.x / mx_, -level), std::ldexp(frame.extent.y / my_, -level)};
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  centers_.assign(static_cast<std::size_t>(mx_) * my_, Vec2{nan, nan});
}

Vec2 DartGrid::corner(Cell c, int level) const {
  const Vec2 s = size(level);
  return frame_.origin + Vec2{c.ix * s.x, c.iy * s.y};
}

bool DartGrid::conflicts(Vec2 z, Cell base) const {
  return any_in_block(base, [&](Vec2 c) { return is_conflict(squared_distance(c, z), r_); });
}

void DartGrid::prefetch_block(Cell b) const {
  const int x0 = std::max(static_cast<int>(b.ix) - 2, 0);
  for (int dy = -2; dy <= 2; ++dy) {
    const int iy = static_cast<int>(b.iy) + dy;
    if (iy < 0 || iy >= my_) continue;
    const Vec2* p = &centers_[static_cast<std::size_t>(iy) * mx_ + x0];
    __builtin_prefetch(p);
    __builtin_prefetch(p + 4);
  }
}

void DartGrid::keep_uncovered(Cell c, int level, bool split, std::vector<Cell>& out) const {
  const Cell base = base_of(c, level);
  if (filled(base)) return;
  // A disk covers a (sub)cell when it covers the corner farthest from its center. The
  // cell's center is a corner of each of its children, so only disks that reach the
  // center can cover the cell or a child: one scan collects them (a few at most).
  const Vec2 lo = corner(c, level), s = size(level), mid = lo + s * 0.5;
  Vec2 near[32];
  const int n = gather(base, mid, r_, near);
  auto covered = [&](Vec2 clo, Vec2 cs) {
    const Vec2 chi = clo + cs, cmid = clo + cs * 0.5;
    for (int k = 0; k < n; ++k) {
      const Vec2 p = near[k];
      const Vec2 far{p.x < cmid.x ? chi.x : clo.x, p.y < cmid.y ? chi.y : clo.y};
      if (is_covered(squared_distance(p, far), r_)) return true;
    }
    return false;
  };
  if (covered(lo, s)) return;
  if (!split) {
    out.push_back(c);
    return;
  }
  const Vec2 h = s * 0.5;
  for (std::uint32_t k = 0; k < 4; ++k) {
    if (!covered(lo + Vec2{(k & 1) * h.x, (k >> 1) * h.y}, h)) {
      out.push_back({2 * c.ix + (k & 1), 2 * c.iy + (k >> 1)});
    }
  }
}

int DartGrid::gather(Cell base, Vec2 q, double reach, Vec2 (&out)[32]) const {
  // Only the rows and columns of the block that [q - reach, q + reach] meets: 3 x 3
  // cells when q is near the middle of its base cell.
  const Vec2 b = size(0), lo = corner(base, 0);
  const int x0 = q.x - reach < lo.x - b.x ? -2 : -1, x1 = q.x + reach > lo.x + 2 * b.x ? 2 : 1;
  const int y0 = q.y - reach < lo.y - b.y ? -2 : -1, y1 = q.y + reach > lo.y + 2 * b.y ? 2 : 1;
  const double reach2 = reach * reach * (1 + 4 * kRelTol);
  const int bx = static_cast<int>(base.ix), by = static_cast<int>(base.iy);
  const bool inside = bx >= 2 && bx < mx_ - 2 && by >= 2 && by < my_ - 2;
  int n = 0;
  for (int dy = y0; dy <= y1; ++dy) {
    for (int dx = x0; dx <= x1; ++dx) {
      int ix = bx + dx, iy = by + dy;
      Vec2 off{0, 0};
      if (!inside && (ix < 0 || ix >= mx_ || iy < 0 || iy >= my_)) {
        if (!frame_.periodic) continue;
        const int wx = floor_div(ix, mx_), wy = floor_div(iy, my_);
        ix -= wx * mx_, iy -= wy * my_;
        off = {wx * frame_.extent.x, wy * frame_.extent.y};
      }
      const Vec2 p = centers_[static_cast<std::size_t>(iy) * mx_ + ix] + off;
      if (squared_distance(p, q) <= reach2 && n < 32) out[n++] = p;
    }
  }
  return n;
}

int DartGrid::uncovered_vertices(Vec2 lo, Vec2 hi, const Vec2* disks, int n,
                                 Vec2 (&out)[64]) const {
  int count = 0;
  // skip_a / skip_b: the disks whose circles the candidate lies on (-1: none).
  auto consider = [&](Vec2 x, int skip_a, int skip_b) {
    if (count == 64) return;
    for (int k = 0; k < n; ++k) {
      if (k != skip_a && k != skip_b && is_covered(squared_distance(x, disks[k]), r_)) return;
    }
    out[count++] = x;
  };
  const double slack = 1e-12 * (hi.x - lo.x + hi.y - lo.y);
  auto inside = [&](Vec2 x) {
    return x.x >= lo.x - slack && x.x <= hi.x + slack && x.y >= lo.y - slack && x.y <= hi.y + slack;
  };
  // Corners of the cell.
  consider(lo, -1, -1);
  consider({hi.x, lo.y}, -1, -1);
  consider({lo.x, hi.y}, -1, -1);
  consider(hi, -1, -1);
  const double r2 = r_ * r_;
  for (int i = 0; i < n; ++i) {
    const Vec2 p = disks[i];
    // Where circle i crosses the four edges.
    for (const double y : {lo.y, hi.y}) {
      const double h2 = r2 - (y - p.y) * (y - p.y);
      if (h2 < 0) continue;
      const double h = std::sqrt(h2);
      for (const double x : {p.x - h, p.x + h}) {
        if (x >= lo.x && x <= hi.x) consider({x, y}, i, -1);
      }
    }
    for (const double x : {lo.x, hi.x}) {
      const double h2 = r2 - (x - p.x) * (x - p.x);
      if (h2 < 0) continue;
      const double h = std::sqrt(h2);
      for (const double y : {p.y - h, p.y + h}) {
        if (y >= lo.y && y <= hi.y) consider({x, y}, i, -1);
      }
    }
    // Where circle i meets circle j inside the cell (a corner on further circles is
    // judged as the void corner search does: covered if they surround it).
    for (int j = i + 1; j < n; ++j) {
      const CircleIntersection x = intersect_circles(p, r_, disks[j], r_);
      for (int k = 0; k < x.count; ++k) {
        if (!inside(x.points[k]) || count == 64) continue;
        CornerCover cover(x.points[k], p, disks[j]);
        bool covered = false;
        for (int m = 0; m < n && !covered; ++m) covered = m != i && m != j && cover.add(disks[m], r_);
        if (!covered && !cover.covered()) out[count++] = x.points[k];
      }
    }
  }
  return count;
}

}  // namespace disktune::detail
