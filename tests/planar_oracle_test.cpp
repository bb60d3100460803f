// SPDX-License-Identifier: GPL-3.0-or-later
// The planar oracle must be able to fail: hand-made packings (radius 1) with one defect
// each, which it has to name, and valid ones it has to pass. The layouts were checked
// by hand and on a dense grid of points (largest gap to a center noted per layout).
#include "oracle/planar_oracle.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace {

using oracle::check_planar;
using oracle::Domain;
using oracle::PlanarOptions;
using oracle::PlanarReport;
using oracle::Points;
using Loop = std::vector<std::array<double, 2>>;

Loop rect(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// Points of an axis grid: every (x, y) with x, y in `ticks`.
Points grid(const std::vector<double>& ticks) {
  Points out;
  for (double x : ticks)
    for (double y : ticks) out.push_back({x, y});
  return out;
}

// [0,2]^2 with disks of radius 1 at the 9 points of spacing 1: no pair closer than 1,
// every point within sqrt(1/2) of a center (the cell centers are the farthest).
const Domain kSquare2{{rect(0, 0, 2, 2)}};
Points square2() { return grid({0, 1, 2}); }

// [0,5]^2 with the 25 points of spacing 1.25: pairs >= 1.25 apart, gaps <= 0.884.
const Domain kSquare5{{rect(0, 0, 5, 5)}};
Points square5() { return grid({0, 1.25, 2.5, 3.75, 5}); }

bool mentions(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(PlanarOracle, ValidGridPasses) {
  const PlanarReport rep = check_planar(kSquare2, square2(), 1.0);
  EXPECT_TRUE(rep.ok()) << rep.summary();
  EXPECT_TRUE(rep.inside() && rep.on_boundary() && rep.conflict_free());
  EXPECT_TRUE(rep.maximal() && rep.boundary_maximal());
  EXPECT_EQ(rep.n, 9u);
  EXPECT_EQ(rep.boundary_count, 8u);  // all but (1, 1)
  EXPECT_DOUBLE_EQ(rep.min_distance, 1.0);
  EXPECT_EQ(rep.probes, 20000u);
  EXPECT_LE(rep.max_probe_gap, std::sqrt(0.5) + 1e-12);
  EXPECT_GT(rep.max_probe_gap, 0.6);  // probes do reach the cell centers' regions

  const PlanarReport rep5 = check_planar(kSquare5, square5(), 1.0);
  EXPECT_TRUE(rep5.ok()) << rep5.summary();
  EXPECT_EQ(rep5.boundary_count, 16u);
}

TEST(PlanarOracle, EitherOrientationAndAreas) {
  Domain cw = kSquare2;
  std::reverse(cw.loops[0].begin(), cw.loops[0].end());
  EXPECT_TRUE(check_planar(cw, square2(), 1.0).ok());
  EXPECT_DOUBLE_EQ(oracle::domain_area(cw), 4.0);
  const Domain ring{{rect(0, 0, 6, 6), rect(1, 1, 5, 5)}};  // both counterclockwise
  EXPECT_DOUBLE_EQ(oracle::domain_area(ring), 36.0 - 16.0);
  EXPECT_TRUE(oracle::even_odd_inside(ring, 0.5, 3));
  EXPECT_FALSE(oracle::even_odd_inside(ring, 3, 3));
  EXPECT_FALSE(oracle::even_odd_inside(ring, 7, 3));
  EXPECT_DOUBLE_EQ(oracle::distance_to_boundary(ring, 3, 3), 2.0);
}

TEST(PlanarOracle, FindsConflict) {
  Points c = square2();
  c.push_back({0.5, 0.5});  // sqrt(1/2) from four grid points
  const PlanarReport rep = check_planar(kSquare2, c, 1.0);
  EXPECT_FALSE(rep.ok());
  EXPECT_FALSE(rep.conflict_free()) << rep.summary();
  EXPECT_EQ(rep.conflict_count, 4u);
  for (const auto& k : rep.conflicts) {
    EXPECT_EQ(std::max(k.i, k.j), 9u);
    EXPECT_NEAR(k.distance, std::sqrt(0.5), 1e-15);
  }
  EXPECT_TRUE(rep.inside() && rep.on_boundary() && rep.maximal() && rep.boundary_maximal())
      << rep.summary();
  EXPECT_TRUE(mentions(rep.summary(), "Conflicts: 4")) << rep.summary();
}

TEST(PlanarOracle, FindsUncoveredHoleInTheMiddle) {
  Points c = square5();
  c.erase(c.begin() + 12);  // (2.5, 2.5): its neighbours are 1.25 away, so a void opens
  for (std::size_t probes : {std::size_t{0}, std::size_t{20000}}) {
    PlanarOptions opt;
    opt.probes = probes;
    const PlanarReport rep = check_planar(kSquare5, c, 1.0, opt);
    EXPECT_FALSE(rep.maximal()) << rep.summary();
    EXPECT_FALSE(rep.ok());
    EXPECT_TRUE(rep.inside() && rep.on_boundary() && rep.conflict_free() && rep.boundary_maximal())
        << rep.summary();
    bool corner = false;
    for (const auto& u : rep.uncovered) {
      // The void reaches 0.25 from (2.5, 2.5) on the axes, 0.416 on the diagonals
      // (where the circles of (1.25, 2.5) and (2.5, 1.25) cross).
      EXPECT_LE(std::hypot(u.x - 2.5, u.y - 2.5), 0.417) << u.why;
      corner |= mentions(u.why, "corner of disks");
    }
    EXPECT_TRUE(corner) << "the exact part alone must find the void";
    if (probes > 0) {
      EXPECT_GT(rep.max_probe_gap, 1.0);
    }
  }
}

TEST(PlanarOracle, FindsCornerWithoutDisk) {
  // [0,2]^2 without a disk on (0,0); (0.3, 0) covers it (gaps <= 0.864, pairs >= 1).
  const Points c{{0.3, 0}, {2, 0}, {0, 1}, {0, 2}, {1, 2}, {2, 2}, {2, 1}, {1, 1}};
  const PlanarReport rep = check_planar(kSquare2, c, 1.0);
  EXPECT_FALSE(rep.on_boundary()) << rep.summary();
  EXPECT_FALSE(rep.ok());
  ASSERT_EQ(rep.bare_corner_count, 1u);
  EXPECT_EQ(rep.bare_corners[0].loop, 0u);
  EXPECT_EQ(rep.bare_corners[0].vertex, 0u);
  EXPECT_NEAR(rep.bare_corners[0].nearest_center, 0.3, 1e-15);
  EXPECT_EQ(rep.off_boundary_count, 0u);
  EXPECT_TRUE(rep.inside() && rep.conflict_free() && rep.maximal() && rep.boundary_maximal())
      << rep.summary();
}

TEST(PlanarOracle, FindsDiskOutsideTheDomain) {
  Points c = square2();
  c.push_back({3, 1});  // 1 from (2, 1): no conflict, but outside
  const PlanarReport rep = check_planar(kSquare2, c, 1.0);
  EXPECT_FALSE(rep.inside()) << rep.summary();
  EXPECT_FALSE(rep.ok());
  ASSERT_EQ(rep.outside_count, 1u);
  EXPECT_EQ(rep.outside[0].i, 9u);
  EXPECT_DOUBLE_EQ(rep.outside[0].distance_to_boundary, 1.0);
  EXPECT_TRUE(rep.on_boundary() && rep.conflict_free() && rep.maximal() && rep.boundary_maximal())
      << rep.summary();

  // Within r*tol of the boundary counts as inside, beyond it does not.
  c.back() = {2 + 0.5e-6, 1.5};
  EXPECT_EQ(check_planar(kSquare2, c, 1.0, {}).outside_count, 0u);
  c.back() = {2 + 2e-6, 1.5};
  EXPECT_EQ(check_planar(kSquare2, c, 1.0, {}).outside_count, 1u);
}

TEST(PlanarOracle, FindsUncoveredPartOfBoundarySegment) {
  Points c = square5();
  const auto it = std::find(c.begin(), c.end(), std::array<double, 2>{2.5, 0});
  ASSERT_NE(it, c.end());
  *it = {2.5, 0.2};  // off the bottom edge: 2D still covered (gaps <= 0.877, pairs >= 1.05)
  const PlanarReport rep = check_planar(kSquare5, c, 1.0);
  EXPECT_FALSE(rep.boundary_maximal()) << rep.summary();
  EXPECT_FALSE(rep.ok());
  ASSERT_EQ(rep.boundary_gap_count, 1u);
  const auto& g = rep.boundary_gaps[0];
  EXPECT_EQ(g.loop, 0u);
  EXPECT_EQ(g.segment, 0u);  // (0,0) -> (5,0)
  EXPECT_NEAR(g.t0, 2.25 / 5, 1e-6);
  EXPECT_NEAR(g.t1, 2.75 / 5, 1e-6);
  EXPECT_NEAR(g.x, 2.5, 1e-9);
  EXPECT_EQ(g.y, 0.0);
  EXPECT_TRUE(rep.inside() && rep.on_boundary() && rep.conflict_free() && rep.maximal())
      << rep.summary();

  // Flagging the moved disk as a boundary disk: it is off the boundary.
  PlanarOptions opt;
  opt.boundary_flags.assign(c.size(), 0);
  for (std::size_t i = 0; i < c.size(); ++i)
    opt.boundary_flags[i] = c[i][0] == 0 || c[i][0] == 5 || c[i][1] == 0 || c[i][1] == 5 ||
                            c[i][1] == 0.2;
  const PlanarReport flagged = check_planar(kSquare5, c, 1.0, opt);
  ASSERT_EQ(flagged.off_boundary_count, 1u) << flagged.summary();
  EXPECT_NEAR(flagged.off_boundary[0].distance_to_boundary, 0.2, 1e-15);
}

TEST(PlanarOracle, FindsVoidAtTheBoundaryWithoutProbes) {
  // Without the disk at (2.5, 0) a void opens on the bottom edge: its corners on the edge
  // are where the circles of (1.25, 0) and (3.75, 0) meet it, at x = 2.25 and 2.75.
  Points c = square5();
  c.erase(std::find(c.begin(), c.end(), std::array<double, 2>{2.5, 0}));
  PlanarOptions opt;
  opt.probes = 0;
  const PlanarReport rep = check_planar(kSquare5, c, 1.0, opt);
  EXPECT_FALSE(rep.maximal());
  EXPECT_FALSE(rep.boundary_maximal());
  int on_edge = 0;
  for (const auto& u : rep.uncovered) {
    EXPECT_LE(std::hypot(u.x - 2.5, u.y), 0.5) << u.why;
    if (mentions(u.why, "meets segment 0 of loop 0")) {
      ++on_edge;
      EXPECT_NEAR(std::fabs(u.x - 2.5), 0.25, 1e-12);
      EXPECT_EQ(u.y, 0.0);
    }
  }
  EXPECT_EQ(on_edge, 2) << rep.summary();
}

TEST(PlanarOracle, HolesAreNotPartOfTheDomain) {
  // A ring of width 1 between [0,6]^2 and the hole [1,5]^2, disks on every integer point
  // of both boundaries: covered (gaps <= sqrt(1/2)); the hole's middle is 2 from them.
  Points c;
  for (int x = 0; x <= 6; ++x)
    for (int y = 0; y <= 6; ++y) {
      const bool outer = x == 0 || x == 6 || y == 0 || y == 6;
      const bool inner = x >= 1 && x <= 5 && y >= 1 && y <= 5 && (x == 1 || x == 5 || y == 1 || y == 5);
      if (outer || inner) c.push_back({double(x), double(y)});
    }
  Loop outer_cw = rect(0, 0, 6, 6);
  std::reverse(outer_cw.begin(), outer_cw.end());
  const Domain ring{{outer_cw, rect(1, 1, 5, 5)}};  // orientations "wrong" on purpose
  const PlanarReport rep = check_planar(ring, c, 1.0);
  EXPECT_TRUE(rep.ok()) << rep.summary();
  EXPECT_EQ(rep.boundary_count, c.size());

  // Without the hole the middle is an uncovered void.
  const Domain filled{{outer_cw}};
  const PlanarReport rep2 = check_planar(filled, c, 1.0);
  EXPECT_FALSE(rep2.maximal()) << rep2.summary();
  for (const auto& u : rep2.uncovered) EXPECT_LE(std::hypot(u.x - 3, u.y - 3), 2.0) << u.why;
}

TEST(PlanarOracle, FindsCircleMeetingNoOtherCircle) {
  // [0,4.4]^2, boundary disks at spacing 1.1 and one disk in the middle, 2.2 from the
  // nearest boundary disk: its circle meets none, and a ring of void surrounds it.
  const std::vector<double> ticks{0, 1.1, 2.2, 3.3, 4.4};
  Points c;
  for (double x : ticks)
    for (double y : ticks)
      if (x == 0 || x == 4.4 || y == 0 || y == 4.4) c.push_back({x, y});
  c.push_back({2.2, 2.2});
  PlanarOptions opt;
  opt.probes = 0;
  const PlanarReport rep = check_planar({{rect(0, 0, 4.4, 4.4)}}, c, 1.0, opt);
  EXPECT_FALSE(rep.maximal());
  const auto isolated = std::find_if(rep.uncovered.begin(), rep.uncovered.end(), [](const auto& u) {
    return mentions(u.why, "circle of disk 16 meets no other circle");
  });
  ASSERT_NE(isolated, rep.uncovered.end()) << rep.summary();
  EXPECT_NEAR(isolated->x, 1.2, 1e-15);  // its leftmost point
  EXPECT_NEAR(isolated->y, 2.2, 1e-15);
}

TEST(PlanarOracle, ChecksCanBeSwitchedOff) {
  Points c = square2();
  c.push_back({0.5, 0.5});
  PlanarOptions opt;
  opt.conflicts = false;
  opt.maximality = false;
  const PlanarReport rep = check_planar(kSquare2, c, 1.0, opt);
  EXPECT_TRUE(rep.ok()) << rep.summary();  // containment and boundary only
  EXPECT_FALSE(rep.conflict_free());       // not checked reads as false
  EXPECT_TRUE(mentions(rep.summary(), "Conflicts: not checked"));
}

TEST(PlanarOracle, RejectsBadInput) {
  EXPECT_THROW(check_planar(kSquare2, square2(), 0.0), std::invalid_argument);
  EXPECT_THROW(check_planar(kSquare2, Points{std::array<double, 2>{std::nan(""), 0.0}}, 1.0), std::invalid_argument);
  EXPECT_THROW(check_planar(Domain{{Loop{{0, 0}, {1, 0}}}}, square2(), 1.0), std::invalid_argument);
  PlanarOptions opt;
  opt.boundary_flags = {1, 0};
  EXPECT_THROW(check_planar(kSquare2, square2(), 1.0, opt), std::invalid_argument);
  opt = {};
  opt.tol = 1;
  EXPECT_THROW(check_planar(kSquare2, square2(), 1.0, opt), std::invalid_argument);
}

TEST(PlanarOracle, HandlesManyDisksQuickly) {
  // 10^5 disks on a hexagonal lattice of spacing 1.5 r in a 473 x 410 rectangle.
  const double r = 1, a = 1.5 * r, h = a * std::sqrt(3.0) / 2;
  Points c;
  for (int j = 0; j < 316; ++j)
    for (int i = 0; i < 316; ++i) c.push_back({i * a + (j % 2) * a / 2, j * h});
  PlanarOptions opt;
  opt.boundary = false;  // the lattice does not sit on the rectangle's edges
  opt.maximality = false;
  const PlanarReport rep = check_planar({{rect(0, 0, 316 * a, 316 * h)}}, c, r, opt);
  EXPECT_TRUE(rep.inside() && rep.conflict_free()) << rep.summary();
  EXPECT_NEAR(rep.min_distance, a, 1e-9);
}

}  // namespace
