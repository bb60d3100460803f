// SPDX-License-Identifier: GPL-3.0-or-later
#include "disktune/voids.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "disktune/sampling.h"
#include "disktune/sizing.h"
#include "disktune/tuning.h"
#include "lattices.h"
#include "test_util.h"

namespace disktune {
namespace {

// A hexagonal lattice that tiles a periodic box exactly: `cols` points a row at
// spacing s = 1/cols, an even number of rows s*sqrt(3)/2 apart.
struct Hex {
  PeriodicBox box;
  double s;
  std::vector<Vec2> points;
};
Hex hex_lattice(int cols, int rows) {
  const double s = 1.0 / cols, dy = s * std::sqrt(3.0) / 2;
  Hex h{PeriodicBox(1.0, rows * dy), s, {}};
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < cols; ++i) h.points.push_back({(i + 0.5 * (j % 2)) * s, j * dy});
  }
  return h;
}

Packing packing_of(const Hex& h, double r) {
  Packing p(h.box.frame(), r);
  for (const Vec2& c : h.points) p.insert(c, r);
  return p;
}

TEST(Corners, RemovedDiskOfTouchingHexLatticeLeavesNoVoid) {
  // Spacing r: every neighbour circle passes through the removed center, so the void
  // is a single point, covered within the tolerance (six cocircular circles).
  const Hex h = hex_lattice(20, 20);
  const Packing p = packing_of(h, h.s);
  const DiskId gone = 45;
  std::vector<Corner> corners;
  corners_in_region(p, p.center(gone), h.s, {gone}, corners);
  EXPECT_TRUE(corners.empty());
}

TEST(Corners, RemovedDiskOfCoveringHexLatticeLeavesSixCorners) {
  const Hex h = hex_lattice(20, 20);
  const double r = 1.01 * h.s / std::sqrt(3.0);
  const Packing p = packing_of(h, r);
  for (const DiskId gone : {DiskId{0}, DiskId{45}, DiskId{399}}) {  // corners of the box too
    std::vector<Corner> corners;
    const Vec2 c = p.center(gone);
    corners_in_region(p, c, r, {gone}, corners);
    ASSERT_EQ(corners.size(), 6u) << gone;
    for (const Corner& k : corners) {
      EXPECT_LE(distance(k.point, c), r);
      EXPECT_NEAR(distance(k.point, c), h.s * (std::sqrt(3.0) / 2 - std::sqrt(r * r / (h.s * h.s) - 0.25)), 1e-12);
    }
    // With the disk present there is nothing to find.
    std::vector<Corner> none;
    corners_in_region(p, c, r, {}, none);
    EXPECT_TRUE(none.empty());
  }
}

TEST(Corners, CocircularSquareIsCoveredOnlyWithinTheTolerance) {
  // Four disks at the corners of a square of side a: the square's center lies on all
  // four circles when r = a/sqrt(2).
  const PeriodicBox box;
  const double a = 0.2;
  auto corners_for = [&](double r) {
    Packing p(box.frame(), r);
    for (const Vec2& c : {Vec2{0.4, 0.4}, Vec2{0.6, 0.4}, Vec2{0.4, 0.6}, Vec2{0.6, 0.6}}) p.insert(c, r);
    std::vector<Corner> out;
    corners_in_region(p, {0.5, 0.5}, 0.01, {}, out);
    return out;
  };
  const double r0 = a / std::sqrt(2.0);
  EXPECT_TRUE(corners_for(r0).empty());
  EXPECT_TRUE(corners_for(r0 * (1 - 1e-12)).empty());  // a void far below the tolerance
  EXPECT_EQ(corners_for(r0 * (1 - 1e-6)).size(), 4u);  // a real void: four corners
  EXPECT_TRUE(corners_for(r0 * (1 + 1e-6)).empty());
}

TEST(Corners, ATripleCornerIsAVoidCornerUnlessItsCirclesSurroundIt) {
  // Three circles through one point c: their disks cover a neighbourhood of c only when
  // the directions to their centers are not all in one half-plane. Injection makes such
  // points (disks sit exactly r from the corners they were built from); a tolerance
  // test alone would call c covered either way and miss the void.
  const PeriodicBox box;
  const double r = 0.1;
  const Vec2 c{0.5, 0.5};
  auto corners_at_c = [&](std::initializer_list<double> degrees) {
    Packing p(box.frame(), r);
    for (const double deg : degrees) {
      const double a = deg * 3.14159265358979323846 / 180;
      p.insert(c + Vec2{std::cos(a), std::sin(a)} * r, r);
    }
    std::vector<Corner> out;
    corners_in_region(p, c, 1e-6, {}, out);
    return out.size();
  };
  EXPECT_GT(corners_at_c({0, 60, 120}), 0u);    // the wedge between 120 and 360 is void
  EXPECT_GT(corners_at_c({10, 95, 185}), 0u);   // a gap of 185 degrees: still a wedge
  EXPECT_EQ(corners_at_c({0, 120, 240}), 0u);   // surrounded: covered
  EXPECT_EQ(corners_at_c({0, 90, 175, 270}), 0u);
}

TEST(Corners, TangentCirclesWithTheirOtherCirclesOnOneSideLeaveAVoid) {
  // The densest lattice (r = spacing) without the three disks at the edge midpoints of
  // a triangle of side 2r: each midpoint is the tangent point of two corner disks and
  // lies on two circles outside the triangle, so the directions to its circles fill a
  // closed half-plane exactly, and the hole inside (circumradius 2r/sqrt3) borders it.
  const double a = 0.1;
  Packing p = test::hex_lattice(10, 12, a, a);
  const Vec2 P = p.center(25), e1{1, 0}, e2{0.5, std::sqrt(3.0) / 2};
  for (const Vec2 m : {e1, e2, e1 + e2}) {
    DiskId gone = kNoDisk;
    p.for_each_near(P + m * a, 1e-9, [&](const Neighbor& n) { gone = n.id; });
    ASSERT_NE(gone, kNoDisk);
    p.remove(gone);
  }
  EXPECT_FALSE(is_maximal(p));
  std::vector<Corner> corners;
  corners_in_region(p, P + (e1 + e2) * (2 * a / 3), a, {}, corners);
  ASSERT_FALSE(corners.empty());
  for (const Corner& c : corners) {  // each a tangent point (on four circles, once per pair)
    double nearest = 1;
    for (const Vec2 m : {e1, e2, e1 + e2}) nearest = std::min(nearest, distance(c.point, P + m * a));
    EXPECT_LT(nearest, 1e-6 * a);
  }
}

TEST(Corners, OnCircleFindsIsolatedDisksAndTheirCorners) {
  const PeriodicBox box;
  Packing p(box.frame(), 0.1);
  const DiskId lone = p.insert({0.5, 0.5}, 0.1);
  std::vector<Corner> out;
  corners_on_circle(p, lone, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].b, kNoDisk);
  const DiskId other = p.insert({0.65, 0.5}, 0.1);
  out.clear();
  corners_on_circle(p, lone, out);
  ASSERT_EQ(out.size(), 2u);
  for (const Corner& k : out) {
    EXPECT_EQ(k.b, other);
    EXPECT_NEAR(distance(k.point, {0.5, 0.5}), 0.1, 1e-15);
    EXPECT_NEAR(distance(k.point, {0.65, 0.5}), 0.1, 1e-15);
  }
}

// The library's maximality test agrees with the oracle on samples with holes punched.
TEST(Corners, IsMaximalAgreesWithTheOracle) {
  int non_maximal = 0;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const PeriodicBox box(1.0, 0.8);
    Rng rng(seed);
    Packing p = sample_mps(box, 0.04, rng);
    const auto full = oracle::check_maximal(test::box_of(box), 0.04, test::centers_of(p), 1e-6, 2000, seed);
    ASSERT_TRUE(full.maximal()) << full.summary();
    EXPECT_TRUE(is_maximal(p));
    const int holes = static_cast<int>(seed % 3);
    for (int k = 0; k < holes; ++k) p.remove(p.ids()[uniform_index(rng, p.size())]);
    const auto cut = oracle::check_maximal(test::box_of(box), 0.04, test::centers_of(p), 1e-6, 2000, seed);
    EXPECT_EQ(is_maximal(p), cut.maximal()) << "seed " << seed << ": " << cut.summary();
    non_maximal += !cut.maximal();
  }
  EXPECT_GT(non_maximal, 0);  // the comparison did see both answers
}

// The corners of corners_in_region against a brute force over every pair of disk
// images near the region (all disks, all nine images in the box, no grid), on sampled
// and tuned packings, one radius and radii that vary, at the regions the tuning asks
// for (a disk lifted), at random centers, and at regions wide enough (4 r) to hold
// more disks than the search's arrays (its other path). A crossing in the region held
// by no third disk, by a margin, must be reported with its pair; one strictly inside a
// third must not; each reported corner must be such a crossing not strictly held.
// Crossings within 1e-7 r of a third circle are left out of the first rule (their
// verdict is the tolerance's).
TEST(Corners, RegionSearchMatchesABruteForceOverEveryPair) {
  struct Image {
    DiskId id;
    Vec2 c;
    double r;
  };
  std::size_t regions = 0, corners = 0, wide = 0;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const PeriodicBox box(1.0, 1.0);
    Rng rng(seed);
    const double r = 0.03;
    Packing p = seed % 2 ? sample_mps(box, r, rng)
                         : sample_mps(box,
                                      std::make_shared<const Sizing>(expression_sizing(
                                          "0.025 + 0.005 * sin(6.283185307179586 * x)")),
                                      rng);
    const double eta = seed <= 2 ? 0.8 : 0.7;
    tune(p, box, Target::area_fraction(eta), rng);
    const double rmax = p.max_radius();
    const std::vector<DiskId> ids = p.ids();
    const auto check = [&](Vec2 center, double R, const std::vector<DiskId>& ignore) {
      std::vector<Corner> found;
      corners_in_region(p, center, R, ignore, found);
      std::vector<Image> near;
      for (const DiskId d : ids) {
        if (std::find(ignore.begin(), ignore.end(), d) != ignore.end()) continue;
        for (int i = -1; i <= 1; ++i)
          for (int j = -1; j <= 1; ++j) {
            const Vec2 c = p.center(d) + Vec2{double(i), double(j)};
            if (norm(c - center) <= R + 2 * rmax) near.push_back({d, c, p.radius(d)});
          }
      }
      wide += near.size() > 48;
      const auto held_by_third = [&](Vec2 x, std::size_t a, std::size_t b, double margin) {
        for (std::size_t k = 0; k < near.size(); ++k)
          if (k != a && k != b && norm(x - near[k].c) < near[k].r * (1 + margin)) return true;
        return false;
      };
      std::vector<bool> matched(found.size(), false);
      for (std::size_t a = 0; a < near.size(); ++a)
        for (std::size_t b = a + 1; b < near.size(); ++b) {
          const Vec2 u = near[b].c - near[a].c;
          const double d = norm(u), ra = near[a].r, rb = near[b].r;
          if (d > (ra + rb) * (1 + 1e-12) || d < std::abs(ra - rb) || d == 0) continue;
          const double along = (d * d + ra * ra - rb * rb) / (2 * d);
          const double half = std::sqrt(std::max(0.0, ra * ra - along * along));
          const Vec2 e = u * (1 / d), n{-e.y, e.x};
          for (const double side : {-1.0, 1.0}) {
            const Vec2 x = near[a].c + e * along + n * (side * half);
            const double to_rim = norm(x - center) - R;
            const bool on_rim = std::abs(to_rim) < 1e-7 * r;  // in or out: either way
            const bool in_region = to_rim < 0;
            const bool held = held_by_third(x, a, b, -1e-7), clear = !held_by_third(x, a, b, 1e-7);
            bool reported = false;
            for (std::size_t k = 0; k < found.size(); ++k) {
              const bool same_pair = (found[k].a == near[a].id && found[k].b == near[b].id) ||
                                     (found[k].a == near[b].id && found[k].b == near[a].id);
              if (same_pair && norm(found[k].point - x) < 1e-9) {
                reported = true;
                matched[k] = true;
              }
            }
            if (on_rim) continue;
            if (in_region && clear) {
              EXPECT_TRUE(reported) << "missed crossing at (" << x.x << ", " << x.y << ")";
            }
            if (held || !in_region) {
              EXPECT_FALSE(reported) << "held crossing at (" << x.x << ", " << x.y << ")";
            }
          }
        }
      for (std::size_t k = 0; k < found.size(); ++k)
        EXPECT_TRUE(matched[k]) << "corner at (" << found[k].point.x << ", " << found[k].point.y
                                << ") is no crossing of its two circles; "
                                << norm(found[k].point - center) / R;
      ++regions;
      corners += found.size();
    };
    for (std::size_t k = 0; k < ids.size(); k += 3) {
      const DiskId d = ids[k];
      check(p.center(d), p.radius(d) * (1 + 1e-9), {d});  // the void lifting d leaves
      const Vec2 z{uniform01(rng), uniform01(rng)};
      check(z, r, {});
      if (k % 30 == 0) check(z, 4 * r, {ids[(k + 1) % ids.size()]});
    }
  }
  EXPECT_GT(corners, 1000u);  // the comparison saw corners, and regions of both paths
  EXPECT_GT(wide, 10u);
  EXPECT_GT(regions, 1000u);
}

}  // namespace
}  // namespace disktune
