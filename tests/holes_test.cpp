// SPDX-License-Identifier: GPL-3.0-or-later
// The holes squeeze injection starts new disks at (src/tuning/holes.h): every Voronoi
// vertex once, widest empty circle first, checked against a brute-force periodic
// Delaunay triangulation (tests/brute_delaunay.h) and against CGAL's
// (periodic_delaunay), the same on any number of threads, and the Delaunay holes
// themselves where a packing is not maximal.
#include "../src/tuning/holes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "brute_delaunay.h"
#include "disktune/sampling.h"
#include "disktune/tuning.h"

namespace disktune {
namespace {

double torus_distance2(Vec2 a, Vec2 b, double W, double H) {
  double dx = std::fabs(a.x - b.x), dy = std::fabs(a.y - b.y);
  dx = std::min(dx, W - dx), dy = std::min(dy, H - dy);
  return dx * dx + dy * dy;
}

// Each expected point matched to its own hole within `tol` (one to one), and as many.
::testing::AssertionResult same_points(const std::vector<Vec2>& expected,
                                       const std::vector<Vec2>& holes, double W, double H,
                                       double tol) {
  if (expected.size() != holes.size())
    return ::testing::AssertionFailure()
           << expected.size() << " expected, " << holes.size() << " holes";
  std::vector<Vec2> by_x = holes;
  std::sort(by_x.begin(), by_x.end(), [](Vec2 a, Vec2 b) { return a.x < b.x; });
  std::vector<char> used(by_x.size(), 0);
  const auto match = [&](Vec2 e, std::size_t from, std::size_t to) {
    for (std::size_t k = from; k < to; ++k) {
      if (used[k] || torus_distance2(e, by_x[k], W, H) > tol * tol) continue;
      return used[k] = 1, true;
    }
    return false;
  };
  for (const Vec2 e : expected) {
    const auto lo = std::lower_bound(by_x.begin(), by_x.end(), e.x - tol,
                                     [](Vec2 a, double x) { return a.x < x; });
    const auto hi = std::upper_bound(by_x.begin(), by_x.end(), e.x + tol,
                                     [](double x, Vec2 a) { return x < a.x; });
    // Near the seam a match may lie at the other end: then every hole is tried.
    const bool found = match(e, static_cast<std::size_t>(lo - by_x.begin()),
                             static_cast<std::size_t>(hi - by_x.begin())) ||
                       match(e, 0, by_x.size());
    if (!found) return ::testing::AssertionFailure() << "no hole at (" << e.x << ", " << e.y << ")";
  }
  return ::testing::AssertionSuccess();
}

// The squared distance from each hole to the nearest center, by brute force: the holes
// come widest first, so it never grows along the list.
::testing::AssertionResult widest_first(const Packing& p, const std::vector<Vec2>& holes, double W,
                                        double H) {
  double before = 1e300;
  for (std::size_t k = 0; k < holes.size(); ++k) {
    double nearest = 1e300;
    for (const DiskId id : p.ids())
      nearest = std::min(nearest, torus_distance2(holes[k], p.center(id), W, H));
    if (nearest > before * (1 + 1e-9))
      return ::testing::AssertionFailure() << "hole " << k << " is wider than the one before it";
    before = nearest;
  }
  return ::testing::AssertionSuccess();
}

TEST(Holes, AreTheBruteForceDelaunayCircumcentersWidestFirst) {
  for (const std::uint64_t seed : {1, 2, 3, 4, 5}) {
    const PeriodicBox box(1.0, 0.8);
    const double r = 0.07;
    Rng rng(seed);
    Packing p = sample_mps(box, r, rng);
    if (seed > 3) squeeze_inject(p, rng, p.size() / 4);  // denser, still maximal
    std::vector<test::BrutePoint> pts;
    for (const DiskId id : p.ids()) pts.push_back({p.center(id).x, p.center(id).y});
    std::vector<Vec2> expected;
    double area = 0;
    for (const auto& t : test::brute_periodic_delaunay(pts, 1.0, 0.8, 2.2 * r)) {
      const auto& c = t.corners;
      const double bx = c[1].x - c[0].x, by = c[1].y - c[0].y, cx = c[2].x - c[0].x,
                   cy = c[2].y - c[0].y;
      const double d = 2 * (bx * cy - by * cx), b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
      expected.push_back(
          box.frame().wrap({c[0].x + (cy * b2 - by * c2) / d, c[0].y + (bx * c2 - cx * b2) / d}));
      area += d / 4;
    }
    ASSERT_NEAR(area, 0.8, 1e-9) << "the brute force missed triangles, seed " << seed;
    const std::vector<Vec2> holes = detail::holes_largest_first(p, 1);
    EXPECT_TRUE(same_points(expected, holes, 1.0, 0.8, 1e-9 * r))
        << "seed " << seed << ", " << p.size() << " disks";
    EXPECT_TRUE(widest_first(p, holes, 1.0, 0.8)) << "seed " << seed;
  }
}

TEST(Holes, TheSameOnAnyNumberOfThreadsAndAsCgalsDelaunayGives) {
  const PeriodicBox box(1.0, 1.0);
  for (const std::uint64_t seed : {1, 2}) {
    Rng rng(seed);
    Packing p = sample_mps(box, 0.01, rng);
    if (seed == 2) squeeze_inject(p, rng, p.size() / 2);
    const std::vector<Vec2> one = detail::holes_largest_first(p, 1);
    for (const unsigned threads : {2u, 3u}) {
      const std::vector<Vec2> more = detail::holes_largest_first(p, threads);
      ASSERT_EQ(one.size(), more.size());
      for (std::size_t k = 0; k < one.size(); ++k) {
        ASSERT_TRUE(one[k] == more[k])
            << "hole " << k << " on " << threads << " threads, seed " << seed;
      }
    }
    EXPECT_TRUE(same_points(detail::delaunay_holes_largest_first(p), one, 1.0, 1.0, 1e-9 * 0.01))
        << "seed " << seed;
  }
}

// A packing with voids (disks taken out of a sample), or in a box too narrow for the
// cells: exactly the Delaunay holes.
TEST(Holes, WhereThePackingIsNotMaximalTheyAreTheDelaunayHoles) {
  Rng rng(7);
  const PeriodicBox box(1.0, 1.0);
  Packing p = sample_mps(box, 0.05, rng);
  const std::vector<DiskId> ids = p.ids();
  for (std::size_t k = 0; k < ids.size(); k += 9) p.remove(ids[k]);
  EXPECT_TRUE(detail::holes_largest_first(p, 2) == detail::delaunay_holes_largest_first(p));
  // One disk taken out: its center is r or more from every other, so a void, whose
  // Voronoi vertices may lie past r without reaching the cells' starting squares.
  Packing whole = sample_mps(box, 0.05, rng);
  const std::vector<DiskId> all = whole.ids();
  for (std::size_t k = 0; k < 40; ++k) {
    Packing one_less = whole;
    one_less.remove(all[k]);
    EXPECT_TRUE(detail::holes_largest_first(one_less, 2) ==
                detail::delaunay_holes_largest_first(one_less))
        << "disk " << all[k] << " taken out";
  }
  const PeriodicBox narrow(0.2, 1.0);
  Packing q = sample_mps(narrow, 0.05, rng);
  EXPECT_TRUE(detail::holes_largest_first(q, 2) == detail::delaunay_holes_largest_first(q));
}

}  // namespace
}  // namespace disktune
