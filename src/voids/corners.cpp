// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <sstream>

#include "../domain/point_text.h"
#include "../geometry/threads.h"
#include "corner_cover.h"
#include "disktune/errors.h"
#include "disktune/voids.h"
#include "packing_checks.h"

namespace disktune {
namespace {

// True when the corner x of the circles of a and b (indices i and j in `near`, if there)
// is covered by the other disks of `near`; other images of a and b do count.
bool corner_covered(const std::vector<Neighbor>& near, Vec2 x, Vec2 a, Vec2 b, std::size_t i,
                    std::size_t j) {
  detail::CornerCover cover(x, a, b);
  for (std::size_t k = 0; k < near.size(); ++k) {
    if (k != i && k != j && cover.add(near[k].image, near[k].radius)) return true;
  }
  return cover.covered();
}

// True when some disk of `near` (other than index i) covers the point x.
bool covered_by_others(const std::vector<Neighbor>& near, Vec2 x, std::size_t i) {
  for (std::size_t k = 0; k < near.size(); ++k) {
    if (k != i && is_covered(squared_distance(x, near[k].image), near[k].radius)) return true;
  }
  return false;
}

bool contains(const std::vector<DiskId>& ids, DiskId id) {
  return std::find(ids.begin(), ids.end(), id) != ids.end();
}

// In a planar domain, a point of the boundary no disk covers, if any. Together with
// the corners inside the domain this decides maximality: a void that reaches no
// boundary point is bounded by circles alone, so it has a corner in the domain.
std::optional<Vec2> uncovered_boundary_point(const Packing& packing) {
  if (!packing.domain()) return std::nullopt;
  for (const BoundarySegment& s : packing.domain()->segments()) {
    const auto gaps = uncovered_on_segment(packing, s.a, s.b, false);
    if (!gaps.empty()) return s.a + (s.b - s.a) * (0.5 * (gaps[0][0] + gaps[0][1]));
  }
  return std::nullopt;
}

// When no other circle meets p's (the void surrounds p, unless a disk holds all of p's
// circle): the first of four points of the circle that lies in the domain and that
// covered() says no disk covers.
template <class Covered>
void isolated_corner(const Packing& packing, DiskId p, Covered covered, std::vector<Corner>& out) {
  const Vec2 c = packing.center(p);
  const double r = packing.radius(p);
  for (const Vec2 dir : {Vec2{1, 0}, Vec2{0, 1}, Vec2{-1, 0}, Vec2{0, -1}}) {
    const Vec2 probe = c + dir * r;
    if (packing.inside(probe) && !covered(probe)) {
      out.push_back({probe, p, kNoDisk});
      return;
    }
  }
}

// The search as it was, kept for circles with more disks near them than the arrays below
// hold (small disks among ones several times larger): the same corners in the same order.
// The grid is asked twice then, as for a wide region; holding the disks found for it
// made every other call slower.
void corners_on_wide_circle(const Packing& packing, DiskId p, std::vector<Corner>& out) {
  const Vec2 c = packing.center(p);
  const double r = packing.radius(p);
  // Only disks within r + r_max can meet p's circle or cover a point of it.
  std::vector<Neighbor> near;
  near.reserve(24);
  packing.for_each_near(c, (r + packing.max_radius()) * (1 + 2 * kRelTol), [&](const Neighbor& n) {
    if (!(n.id == p && n.d2 == 0.0)) near.push_back(n);
  });
  const std::size_t none = near.size();  // p is not in `near`: index "none" stands for it
  bool met = false;
  for (std::size_t i = 0; i < near.size(); ++i) {
    const CircleIntersection x = intersect_circles(c, r, near[i].image, near[i].radius);
    met = met || x.count > 0;
    for (int k = 0; k < x.count; ++k) {
      if (packing.inside(x.points[k]) && !corner_covered(near, x.points[k], c, near[i].image, i, none)) {
        out.push_back({x.points[k], p, near[i].id});
      }
    }
  }
  const auto covered = [&](Vec2 x) { return covered_by_others(near, x, none); };
  if (!met) isolated_corner(packing, p, covered, out);
}

// The search as it was, kept for regions holding more disks than the arrays below (a
// call with a region several radii wide): the same corners in the same order.
void corners_in_wide_region(const Packing& packing, Vec2 center, double R,
                            const std::vector<DiskId>& ignore, std::vector<Corner>& out) {
  std::vector<Neighbor> near;
  near.reserve(32);
  const double rmax = packing.max_radius();
  packing.for_each_near(center, (R + rmax) * (1 + 2 * kRelTol), [&](const Neighbor& n) {
    if (!contains(ignore, n.id)) near.push_back(n);
  });
  std::sort(near.begin(), near.end(), [](const Neighbor& a, const Neighbor& b) { return a.d2 < b.d2; });
  const double lim = R * (1 + kRelTol);
  for (std::size_t i = 0; i < near.size(); ++i) {
    for (std::size_t j = i + 1; j < near.size(); ++j) {
      if (too_far_apart_to_meet(squared_distance(near[i].image, near[j].image), near[i].radius + near[j].radius))
        continue;
      if (!intersections_may_lie_in(near[i].image, near[i].radius, near[j].image, near[j].radius,
                                    center, lim))
        continue;
      const CircleIntersection x =
          intersect_circles(near[i].image, near[i].radius, near[j].image, near[j].radius);
      for (int k = 0; k < x.count; ++k) {
        const Vec2 pt = x.points[k];
        if (squared_distance(pt, center) <= lim * lim && packing.inside(pt) &&
            !corner_covered(near, pt, near[i].image, near[j].image, i, j)) {
          out.push_back({pt, near[i].id, near[j].id});
        }
      }
    }
  }
}

// A region of a dense packing holds 10-20 disks (R = r: 12 on average in the README's
// job), a circle 7-19 (an MPS 7.5, a crystal 17); past this, corners_in_wide_region and
// corners_on_wide_circle. At most 64: sets of disks are bits of a word.
constexpr int kNear = 48;

// Two doubles side by side (GCC and Clang vector extensions: SSE2 or NEON code, else
// scalar). Each operation is the scalar one lane by lane, so the lanes hold, bit for
// bit, what the scalar code of intersect_circles, too_far_apart_to_meet,
// intersections_may_lie_in and CornerCover computes. The search below goes without
// branches where the scalar one branched on every pair and point, half of them each
// way: those branches, mispredicted, were most of its time.
using Lanes = double __attribute__((vector_size(16)));
using Mask = long long __attribute__((vector_size(16)));  // lanes of all ones (true) or zeros

Lanes load(const double* p) {
  Lanes v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

Lanes select(Mask m, Lanes a, Lanes b) {  // m ? a : b, lane by lane
  return (Lanes)(((Mask)a & m) | ((Mask)b & ~m));
}

// Disks as arrays, with the two lanes past the last one padded (far away, radius 0:
// they meet no circle and cover nothing).
struct Disks {
  int n = 0;
  alignas(16) double x[kNear + 2], y[kNear + 2], r[kNear + 2];
  alignas(16) double conflict2[kNear + 2],
      cover2[kNear + 2];  // is_conflict's and is_covered's bounds, squared
  DiskId id[kNear];
};

// Appends to d, in the grid's order, the disks within R of center that skip() lets
// through, and their d2; false when they are more than kNear (then d is not all of them).
template <class Skip>
bool find_disks(const Packing& packing, Vec2 center, double R, Skip skip, Disks& d, double* d2) {
  bool wide = false;
  packing.for_each_near(center, R, [&](const Neighbor& g) {
    if (skip(g)) return;
    if (d.n == kNear) {
      wide = true;
      return;
    }
    const int k = d.n++;
    d.x[k] = g.image.x, d.y[k] = g.image.y, d.r[k] = g.radius, d.id[k] = g.id, d2[k] = g.d2;
  });
  return !wide;
}

// The squared bounds of the disks' radii and the padding past the last one.
void finish(Disks& s) {
  for (int k = 0; k < s.n; ++k) {
    const double lo = s.r[k] * (1.0 - kRelTol), hi = s.r[k] * (1.0 + kRelTol);
    s.conflict2[k] = lo * lo, s.cover2[k] = hi * hi;
  }
  for (int k = s.n; k < s.n + 2; ++k)
    s.x[k] = s.y[k] = HUGE_VAL, s.r[k] = s.conflict2[k] = s.cover2[k] = 0.0;
}

// The disks found, nearest the center first, as std::sort by d2 orders them. Without
// equal d2 every sort gives the one order, here by ranks (no branches); with some (2 %
// of the calls in the README's job) std::sort decides, on the same keys in the same
// order as it did, so equals keep the order it gives them.
void sort_by_distance(const Disks& found, double* d2, Disks& s) {
  const int n = found.n;
  d2[n] = d2[n + 1] = HUGE_VAL;  // padding: below nothing
  int rank[kNear];
  long long equal = 0;
  for (int k = 0; k < n; ++k) {
    const Lanes dk = {d2[k], d2[k]};
    Mask below = {0, 0}, same = {0, 0};
    for (int m = 0; m < n; m += 2) {
      const Lanes dm = load(d2 + m);
      below -= dm < dk;
      same -= dm == dk;
    }
    rank[k] = static_cast<int>(below[0] + below[1]);
    equal += same[0] + same[1];
  }
  if (equal > n) {  // each d2 equals itself; more is a tie
    struct Key {
      double d2;
      int index;
    };
    Key key[kNear];
    for (int k = 0; k < n; ++k) key[k] = {d2[k], k};
    std::sort(key, key + n, [](const Key& a, const Key& b) { return a.d2 < b.d2; });
    for (int k = 0; k < n; ++k) rank[key[k].index] = k;
  }
  s.n = n;
  for (int k = 0; k < n; ++k) {
    const int to = rank[k];
    s.x[to] = found.x[k], s.y[to] = found.y[k], s.r[to] = found.r[k], s.id[to] = found.id[k];
  }
  finish(s);
}

// The pairs (i, j), i < j, that too_far_apart_to_meet and intersections_may_lie_in
// keep, in (i, j) order, two pairs at a time; and in meets[i] the bits of the disks
// whose circles meet i's. With one radius a = 0.5 + 0 / (2 d2) is 0.5 exactly: no
// division.
template <bool kOneRadius>
int kept_pairs(const Disks& s, Vec2 center, double lim, std::uint8_t* ki, std::uint8_t* kj,
               std::uint64_t* meets) {
  const Lanes cx = {center.x, center.x}, cy = {center.y, center.y}, zero = {0.0, 0.0};
  const int n = s.n;
  int nk = 0;
  for (int i = 0; i <= n; ++i) meets[i] = 0;
  for (int i = 0; i < n; ++i) {
    const double xi = s.x[i], yi = s.y[i], ri = s.r[i];
    std::uint64_t row = 0;
    for (int j = i + 1; j < n; j += 2) {
      const Lanes rj = load(s.r + j);
      const Lanes ux = load(s.x + j) - xi, uy = load(s.y + j) - yi;
      const Lanes d2 = ux * ux + uy * uy;
      const Lanes rsum = ri + rj;
      const Lanes rs2 = rsum * rsum;
      const Mask meet = ~(d2 > rs2 + 8.0 * 2.220446049250313e-16 * select(d2 < rs2, rs2, d2));
      Lanes a = {0.5, 0.5};
      if (!kOneRadius) a = 0.5 + (ri * ri - rj * rj) / (2.0 * d2);
      const Lanes h2 = ri * ri - a * a * d2;
      const Lanes mcx = xi + ux * a - cx, mcy = yi + uy * a - cy;
      const Lanes h2p = select(h2 < 0.0, zero, h2);  // std::max(h2, 0.0)
      const Lanes t = mcx * mcx + mcy * mcy + h2p - lim * lim;
      const Lanes n_mc = -uy * mcx + ux * mcy;
      const Mask may = (t <= 0.0) | (t * t * d2 <= 4 * h2p * n_mc * n_mc * (1 + 1e-9));
      const Mask keep = meet & may & (d2 != 0.0);
      const std::uint64_t m0 = meet[0] & 1, m1 = meet[1] & (j + 1 < n);
      row |= m0 << j | m1 << (j + 1);
      meets[j] |= m0 << i;
      meets[j + 1] |= m1 << i;
      ki[nk] = i, kj[nk] = j;
      nk += keep[0] != 0;
      ki[nk] = i, kj[nk] = j + 1;
      nk += (keep[1] != 0) & (j + 1 < n);
    }
    meets[i] |= row;
  }
  return nk;
}

// intersect_circles for the circle (x1, y1, r1) and that of disk i of s, not concentric
// and not too far apart to meet: how many points it finds (a, then b), 0 when one circle
// is inside the other. Without branches, for the region's pairs and the circle's
// crossings alike; always inlined (a call per circle was a twentieth of a circle's
// search). With one radius a = 0.5 + 0 / (2 d2) is 0.5 exactly and no circle is inside
// another.
template <bool kOneRadius>
inline __attribute__((always_inline)) int intersect(double x1, double y1, double r1, const Disks& s,
                                                    int i, double& ax, double& ay, double& bx,
                                                    double& by) {
  const double r2 = s.r[i];
  const double ux = s.x[i] - x1, uy = s.y[i] - y1;
  const double d2 = ux * ux + uy * uy;
  bool nested = false;
  double a = 0.5;
  if (!kOneRadius) {
    const double rsum = r1 + r2, rdiff = r1 - r2;
    const double slack = 8.0 * 2.220446049250313e-16 * std::max(d2, rsum * rsum);
    nested = d2 < rdiff * rdiff - slack;
    a = 0.5 + (r1 * r1 - r2 * r2) / (2.0 * d2);
  }
  const double mx = x1 + ux * a, my = y1 + uy * a;
  const double h2 = r1 * r1 / d2 - a * a;
  const bool two = !(h2 <= 0.0);  // else tangent: m alone
  const double h = std::sqrt(two ? h2 : 0.0);
  const double ox = -uy * h, oy = ux * h;
  ax = two ? mx + ox : mx, ay = two ? my + oy : my;
  bx = mx - ox, by = my - oy;
  return !nested * (1 + two);
}

// The crossings of the kept pairs that lie in the region (each computed once), in
// order, with their pairs; a point out of the region is written and then written over,
// not branched around.
template <bool kOneRadius>
int crossings_in_region(const Disks& s, const std::uint8_t* ki, const std::uint8_t* kj, int nk,
                        Vec2 center, double lim2, double* px, double* py, std::uint8_t* pi,
                        std::uint8_t* pj) {
  int np = 0;
  for (int q = 0; q < nk; ++q) {
    const int i = ki[q], j = kj[q];
    double ax, ay, bx, by;
    const int count = intersect<kOneRadius>(s.x[i], s.y[i], s.r[i], s, j, ax, ay, bx, by);
    const double ea = (ax - center.x) * (ax - center.x) + (ay - center.y) * (ay - center.y);
    const double eb = (bx - center.x) * (bx - center.x) + (by - center.y) * (by - center.y);
    px[np] = ax, py[np] = ay, pi[np] = i, pj[np] = j;
    np += (count > 0) & (ea <= lim2);
    px[np] = bx, py[np] = by, pi[np] = i, pj[np] = j;
    np += (count == 2) & (eb <= lim2);
  }
  return np;
}

// 0, 1, 2, ... as doubles: lane indices to compare (SSE2 compares doubles, not 64-bit
// integers).
struct Indices {
  alignas(16) double k[kNear + 2];
  constexpr Indices() : k() {
    for (int i = 0; i < kNear + 2; ++i) k[i] = i;
  }
};
constexpr Indices kIndex;

// corner_covered(near, x, a, b, i, j) for the crossing x of the circles centered at a
// and b, those of disks i and j of s (-1: a disk not in s), over all other disks of s. A
// disk holding x strictly settles CornerCover's verdict whichever comes first; only
// without one do the disks through it count, handed over in order (add() skips the
// rest), so the verdict, up to the cap on directions, is the same.
bool scan_covered(const Disks& s, double px, double py, Vec2 a, int i, Vec2 b, int j) {
  const Lanes vx = {px, px}, vy = {py, py};
  const Lanes li = {double(i), double(i)}, lj = {double(j), double(j)};
  Mask strict = {0, 0}, any = {0, 0};
  alignas(16) long long through[kNear + 2];
  for (int k = 0; k < s.n; k += 2) {
    const Lanes ex = vx - load(s.x + k), ey = vy - load(s.y + k);
    const Lanes e2 = ex * ex + ey * ey;
    const Lanes lk = load(kIndex.k + k);
    const Mask other = (lk != li) & (lk != lj);
    strict |= (e2 < load(s.conflict2 + k)) & other;
    const Mask on = (e2 <= load(s.cover2 + k)) & other;
    std::memcpy(through + k, &on, sizeof on);
    any |= on;
  }
  if (strict[0] | strict[1]) return true;
  if (!(any[0] | any[1])) return false;  // on no third circle: CornerCover has two directions
  detail::CornerCover cover({px, py}, a, b);
  for (int k = 0; k < s.n; ++k) {
    if (through[k]) cover.add({s.x[k], s.y[k]}, s.r[k]);
  }
  return cover.covered();
}

// scan_covered for the crossing (px, py) of the circles of i and j, after a first try.
bool crossing_covered(const Disks& s, const std::uint64_t* meets, double px, double py, int i,
                      int j) {
  {
    // Tried first: the first two disks whose circles meet both (a disk holding the
    // crossing strictly does, up to rounding); they settle 4 in 5 crossings.
    std::uint64_t both = meets[i] & meets[j];
    const int k1 = both ? __builtin_ctzll(both) : s.n;  // s.n: padding
    both &= both - 1;
    const int k2 = both ? __builtin_ctzll(both) : s.n;
    const Lanes ex = px - Lanes{s.x[k1], s.x[k2]}, ey = py - Lanes{s.y[k1], s.y[k2]};
    const Mask in = ex * ex + ey * ey < Lanes{s.conflict2[k1], s.conflict2[k2]};
    if (in[0] | in[1]) return true;
  }
  return scan_covered(s, px, py, {s.x[i], s.y[i]}, i, {s.x[j], s.y[j]}, j);
}

template <bool kOneRadius>
void corners_of(const Packing& packing, const Disks& s, Vec2 center, double R,
                std::vector<Corner>& out) {
  const double lim = R * (1 + kRelTol);
  std::uint8_t ki[kNear * (kNear - 1) / 2 + 1], kj[kNear * (kNear - 1) / 2 + 1];
  std::uint64_t meets[kNear + 1];
  const int nk = kept_pairs<kOneRadius>(s, center, lim, ki, kj, meets);
  constexpr int kChunk = 32;  // pairs at a time, two crossings each
  double px[2 * kChunk], py[2 * kChunk];
  std::uint8_t pi[2 * kChunk], pj[2 * kChunk];
  for (int q = 0; q < nk; q += kChunk) {
    const int np = crossings_in_region<kOneRadius>(s, ki + q, kj + q, std::min(kChunk, nk - q),
                                                   center, lim * lim, px, py, pi, pj);
    for (int c = 0; c < np; ++c) {
      // The domain test last: both are pure, and most crossings are covered.
      const Vec2 x{px[c], py[c]};
      if (!crossing_covered(s, meets, px[c], py[c], pi[c], pj[c]) && packing.inside(x))
        out.push_back({x, s.id[pi[c]], s.id[pj[c]]});
    }
  }
}

// p's corners: its crossings with the circles of the disks near it, in the grid's order,
// as intersect_circles(c, r, image, radius) gives them. Nearly every crossing is held
// strictly by some disk, but seldom by one a cheap first guess names (for p and a
// neighbour, the disks whose circles meet both are most of the neighbours; the next one
// round p holds the crossing half the time when packings are dense), so every crossing
// is tested against every disk, four crossings and two disks at a time, without
// branches; the few not held go to scan_covered. False when no circle meets p's.
template <bool kOneRadius>
bool circle_corners(const Packing& packing, DiskId p, const Disks& s, std::vector<Corner>& out) {
  const Vec2 c = packing.center(p);
  const double r = packing.radius(p);
  // The crossings in order, each with its disk; a point that is not one is written and
  // then written over, not branched around.
  double px[2 * kNear + 4], py[2 * kNear + 4];
  int pj[2 * kNear + 4];
  int np = 0;
  for (int j = 0; j < s.n; ++j) {
    const double ux = s.x[j] - c.x, uy = s.y[j] - c.y;
    const double d2 = ux * ux + uy * uy;
    const bool meet = (d2 != 0.0) & !too_far_apart_to_meet(d2, r + s.r[j]);
    double ax, ay, bx, by;
    const int count = meet * intersect<kOneRadius>(c.x, c.y, r, s, j, ax, ay, bx, by);
    px[np] = ax, py[np] = ay, pj[np] = j;
    np += count > 0;
    px[np] = bx, py[np] = by, pj[np] = j;
    np += count == 2;
  }
  for (int q = np; q < np + 4; ++q) px[q] = py[q] = 0.0;  // the last four's padding
  for (int q0 = 0; q0 < np; q0 += 4) {
    Mask in[4] = {};
    for (int k = 0; k < s.n; k += 2) {
      const Lanes kx = load(s.x + k), ky = load(s.y + k), lim2 = load(s.conflict2 + k);
      for (int q = 0; q < 4; ++q) {
        const Lanes ex = px[q0 + q] - kx, ey = py[q0 + q] - ky;
        in[q] |= ex * ex + ey * ey < lim2;
      }
    }
    for (int q = 0; q < 4 && q0 + q < np; ++q) {
      const double x = px[q0 + q], y = py[q0 + q];
      const int j = pj[q0 + q];
      // Disk j was tested too: it holds neither of its crossings strictly but for
      // rounding, and where it seems to, the scan decides.
      const double ex = x - s.x[j], ey = y - s.y[j];
      const bool held = (in[q][0] | in[q][1]) && !(ex * ex + ey * ey < s.conflict2[j]);
      // The domain test last: both are pure, and most crossings are covered.
      if (!held && !scan_covered(s, x, y, c, -1, {s.x[j], s.y[j]}, j) && packing.inside({x, y}))
        out.push_back({{x, y}, p, s.id[j]});
    }
  }
  return np > 0;
}

}  // namespace

void corners_in_region(const Packing& packing, Vec2 center, double R,
                       const std::vector<DiskId>& ignore, std::vector<Corner>& out) {
  Disks found;  // in the grid's order
  alignas(16) double d2[kNear + 2];
  const DiskId* ig = ignore.data();
  const std::size_t ni = ignore.size();
  const auto ignored = [&](const Neighbor& g) {
    for (std::size_t k = 0; k < ni; ++k)
      if (ig[k] == g.id) return true;
    return false;
  };
  const double reach = (R + packing.max_radius()) * (1 + 2 * kRelTol);
  if (!find_disks(packing, center, reach, ignored, found, d2))
    return corners_in_wide_region(packing, center, R, ignore, out);
  if (found.n < 2) return;
  Disks s;  // nearest the center first
  sort_by_distance(found, d2, s);
  bool one_radius = true;
  for (int k = 1; k < s.n; ++k) one_radius &= s.r[k] == s.r[0];
  if (one_radius)
    corners_of<true>(packing, s, center, R, out);
  else
    corners_of<false>(packing, s, center, R, out);
}

namespace {

// corners_on_circle; where `conflict` is given, also sets it when some disk conflicts
// with p (those within r of p are among the disks the one search finds).
void circle_corners_and_conflict(const Packing& packing, DiskId p, std::vector<Corner>& out,
                                 bool* conflict) {
  const Vec2 c = packing.center(p);
  const double r = packing.radius(p);
  Disks s;  // in the grid's order, p not among them (its other images are)
  alignas(16) double d2[kNear + 2];
  // Only disks within r + r_max can meet p's circle or cover a point of it.
  const auto self = [&](const Neighbor& g) {
    if (conflict && g.id != p && is_conflict(g.d2, std::min(r, g.radius))) *conflict = true;
    return g.id == p && g.d2 == 0.0;
  };
  if (!find_disks(packing, c, (r + packing.max_radius()) * (1 + 2 * kRelTol), self, s, d2))
    return corners_on_wide_circle(packing, p, out);
  finish(s);
  bool one_radius = true;
  for (int k = 0; k < s.n; ++k) one_radius &= s.r[k] == r;
  const bool met = one_radius ? circle_corners<true>(packing, p, s, out)
                              : circle_corners<false>(packing, p, s, out);
  if (!met) {  // covered_by_others over s
    isolated_corner(
        packing, p,
        [&](Vec2 x) {
          for (int k = 0; k < s.n; ++k)
            if (is_covered(squared_distance(x, {s.x[k], s.y[k]}), s.r[k])) return true;
          return false;
        },
        out);
  }
}

}  // namespace

void corners_on_circle(const Packing& packing, DiskId p, std::vector<Corner>& out) {
  circle_corners_and_conflict(packing, p, out, nullptr);
}

namespace detail {

namespace {

// A disk conflicting with disk `id`, or kNoDisk.
DiskId conflicting_disk(const Packing& packing, DiskId id) {
  const double r = packing.radius(id);
  DiskId other = kNoDisk;
  packing.any_near(packing.center(id), r, [&](const Neighbor& n) {
    if (n.id != id && is_conflict(n.d2, std::min(r, n.radius))) other = n.id;
    return other != kNoDisk;
  });
  return other;
}

}  // namespace

// Disk by disk on every core, the first in id order reported (the check reads only).
std::optional<std::array<DiskId, 2>> first_conflict(const Packing& packing) {
  const std::vector<DiskId> ids = packing.ids();
  const std::size_t i = first_index(ids.size(), thread_count(0), [&](std::size_t k) {
    return conflicting_disk(packing, ids[k]) != kNoDisk;
  });
  if (i == ids.size()) return std::nullopt;
  return std::array<DiskId, 2>{ids[i], conflicting_disk(packing, ids[i])};
}

std::optional<std::string> first_hole(const Packing& packing) {
  if (packing.empty()) return "the whole domain";
  if (const auto hole = uncovered_boundary_point(packing)) return "the boundary point " + point_text(*hole);
  const std::vector<DiskId> ids = packing.ids();
  const std::size_t i = first_index(ids.size(), thread_count(0), [&](std::size_t k) {
    thread_local std::vector<Corner> corners;
    corners.clear();
    corners_on_circle(packing, ids[k], corners);
    return !corners.empty();
  });
  if (i == ids.size()) return std::nullopt;
  std::vector<Corner> corners;
  corners_on_circle(packing, ids[i], corners);
  return "the point " + point_text(packing.frame().wrap(corners.front().point));
}

// The two searches above in one: each disk's neighbours found once (the check of a
// tuned packing of 1.5 M disks 0.78-0.92 -> 0.58-0.77 s on two cores, of a sample of 10^6
// 0.39-0.45 -> 0.31-0.38 s).
bool conflict_free_and_maximal(const Packing& packing) {
  if (uncovered_boundary_point(packing)) return false;
  const std::vector<DiskId> ids = packing.ids();
  return first_index(ids.size(), thread_count(0), [&](std::size_t k) {
           thread_local std::vector<Corner> corners;
           corners.clear();
           bool conflict = false;
           circle_corners_and_conflict(packing, ids[k], corners, &conflict);
           return conflict || !corners.empty();
         }) == ids.size();
}

}  // namespace detail

bool is_maximal(const Packing& packing) { return !detail::first_hole(packing); }

}  // namespace disktune
