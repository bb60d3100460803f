// SPDX-License-Identifier: GPL-3.0-or-later
//
// Tests of both oracles with one radius per disk (varying radii, section 6 of the
// paper). They must fail hand-made packings with one known defect each, pass valid
// graded ones, and give the same reports as the one-radius entry points when all
// radii are equal.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "oracle/oracle.h"
#include "oracle/oracle_lattices.h"
#include "oracle/planar_oracle.h"

namespace {

using oracle::test::hex;
using oracle::test::Lattice;
using oracle::test::rect;

using oracle::Box;
using oracle::Domain;
using oracle::Method;
using oracle::PlanarOptions;
using oracle::PlanarReport;
using oracle::Points;
using oracle::Report;
using Radii = std::vector<double>;

const double kSqrt2 = std::sqrt(2.0);
const double kSqrt3 = std::sqrt(3.0);

struct Disks {
  Points c;
  Radii r;
  void add(double x, double y, double radius) {
    c.push_back({x, y});
    r.push_back(radius);
  }
};

bool mentions(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// ---------------------------------------------------------------- radii 1, 2, 3
//
// Disks of radii 1, 2, 3 on the corners A = (0,0), B = (3,0), D = (0,4) of the 3-4-5
// triangle touch pairwise (|AB| = 1+2, |AD| = 1+3, |BD| = 2+3) at the tangent points
// below, and enclose a curvilinear triangle: a void whose corners are those points.
// They are where the incircle (center (1,1), radius 1) touches the sides, so the
// incircle contains the void: a disk there ("plug") fills it, without conflicts (its
// center is sqrt2, sqrt5, sqrt10 from A, B, D, each >= the smaller radius 1).
const double kTangent[3][2] = {{1, 0}, {0, 1}, {1.8, 1.6}};  // AB, AD, BD
const double kAway[3][2] = {{0, -1}, {-1, 0}, {0.8, 0.6}};   // unit normals, off the void
constexpr double kOuterR = 1.5;

// The three disks with centers at scale * (A, B, D): 1 tangent, < 1 overlapping,
// > 1 apart. outer: one more disk per tangent point, its circle through the point from
// the side away from the void, so each corner of the void lies exactly on a third
// circle, on one side only. plug: the incircle disk.
Disks soddy(double scale, bool outer, bool plug, double ox = 0, double oy = 0) {
  Disks d;
  d.add(ox, oy, 1);
  d.add(ox + 3 * scale, oy, 2);
  d.add(ox, oy + 4 * scale, 3);
  if (outer)
    for (int k = 0; k < 3; ++k)
      d.add(ox + kTangent[k][0] + kOuterR * kAway[k][0],
            oy + kTangent[k][1] + kOuterR * kAway[k][1], kOuterR);
  if (plug) d.add(ox + 1, oy + 1, 1);
  return d;
}

double segment_distance(double px, double py, const double* a, const double* b) {
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  const double t =
      std::clamp(((px - a[0]) * dx + (py - a[1]) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
  return std::hypot(a[0] + t * dx - px, a[1] + t * dy - py);
}

// soddy() at kOrigin in a torus, the rest filled by a hexagonal lattice of radius-0.5
// disks (spacing 0.6 >= 0.5: no conflicts; covering radius 0.6/sqrt3 = 0.35 < 0.5).
// Filler disks are left out within 0.52 of the triangle of the tangent points (which
// contains the void: its sides bulge inwards), so none reaches into the void, and
// within 0.52 of a big center (closer than the smaller radius would be a conflict).
// The filler centers that the big disks cover are allowed (covered_centers).
// That nothing else is uncovered is what the plugged scenes check below.
const double kOrigin[2] = {4, 3.5};

struct Scene {
  Box box;
  Disks d;
};

Scene soddy_torus(double scale, bool outer, bool plug) {
  Scene s{{}, soddy(scale, outer, plug, kOrigin[0], kOrigin[1])};
  const double q = 0.5, a = 0.6, h = a * kSqrt3 / 2;
  const int cols = 20, rows = 24;
  s.box = {cols * a, rows * h};
  const std::size_t big = s.d.c.size();
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < cols; ++i) {
      const double x = a * (i + 0.5 * (j % 2)), y = j * h;
      bool keep = true;
      for (int k = 0; k < 3; ++k)
        keep = keep && segment_distance(x - kOrigin[0], y - kOrigin[1], kTangent[k],
                                        kTangent[(k + 1) % 3]) > q + 0.02;
      for (std::size_t k = 0; k < big; ++k)
        keep = keep && std::hypot(x - s.d.c[k][0], y - s.d.c[k][1]) > q + 0.02;
      if (keep) s.d.add(x, y, q);
    }
  return s;
}

// Distance of a witness from the incircle's center (which contains the void).
double from_incenter(const oracle::Uncovered& u, double ox = kOrigin[0], double oy = kOrigin[1]) {
  return std::hypot(u.x - ox - 1, u.y - oy - 1);
}

TEST(OracleVarying, HoleBetweenDisksOfRadii123IsFound) {
  // Scale 0.999: the three circles cross, near the tangent points, and a hole remains;
  // its three corners are crossings no third disk covers. 1.001: the circles do not
  // meet and the hole reaches the outer disks.
  for (const double scale : {0.999, 1.001}) {
    SCOPED_TRACE(scale);
    const Scene s = soddy_torus(scale, true, false);
    const Report rep = oracle::check_all(s.box, s.d.r, s.d.c, 1e-6, /*probes=*/0);
    EXPECT_TRUE(rep.conflict_free()) << rep.summary();
    EXPECT_FALSE(rep.maximal()) << rep.summary();
    ASSERT_GT(rep.uncovered_count, 0u);
    for (const auto& u : rep.uncovered) {
      EXPECT_LT(from_incenter(u), 1.01) << u.why;
      EXPECT_TRUE(mentions(u.why, "corner of disks")) << u.why;
    }
    EXPECT_EQ(rep.r, 3.0);
    EXPECT_EQ(rep.r_min, 0.5);
    EXPECT_TRUE(mentions(rep.summary(), "radii in [0.5, 3]")) << rep.summary();
  }
  const Scene overlapping = soddy_torus(0.999, true, false);
  const Report exact =
      oracle::check_all(overlapping.box, overlapping.d.r, overlapping.d.c, 1e-6, 0);
  EXPECT_EQ(exact.uncovered_count, 3u) << exact.summary();  // one corner per pair

  // The plug fills the hole, and nothing else was uncovered: the probes agree.
  const Scene plugged = soddy_torus(0.999, true, true);
  const Report rep = oracle::check_all(plugged.box, plugged.d.r, plugged.d.c, 1e-6, 50000);
  EXPECT_TRUE(rep.conflict_free()) << rep.summary();
  EXPECT_TRUE(rep.maximal()) << rep.summary();
}

TEST(OracleVarying, TangentCuspVoidIsFoundBesideItsCorners) {
  // Scale 1: disks 0 (radius 1) and 1 (radius 2) touch at (1, 0), and so do the other
  // pairs. The outer disks put each tangent point exactly on a third circle, on the
  // side away from the void, so every corner of the void counts as covered (within
  // tol). Only the probes beside the corners, into the cusps, see the void.
  const Scene s = soddy_torus(1.0, true, false);
  const Report rep = oracle::check_all(s.box, s.d.r, s.d.c, 1e-6, /*probes=*/0);
  EXPECT_TRUE(rep.conflict_free()) << rep.summary();
  EXPECT_FALSE(rep.maximal()) << rep.summary();
  ASSERT_EQ(rep.uncovered_count, 3u) << rep.summary();  // one probe per tangent point
  for (const auto& u : rep.uncovered) {
    EXPECT_TRUE(mentions(u.why, "probe beside the corner of disks")) << u.why;
    EXPECT_LT(from_incenter(u), 1.0) << u.why;
  }
  // The cusp between the disks of radii 1 and 2: 0.01 * (smaller radius) from (1, 0).
  const auto cusp = std::find_if(rep.uncovered.begin(), rep.uncovered.end(),
                                 [](const auto& u) { return mentions(u.why, "disks 0 and 1"); });
  ASSERT_NE(cusp, rep.uncovered.end()) << rep.summary();
  EXPECT_NEAR(cusp->x, kOrigin[0] + 1, 1e-12);
  EXPECT_NEAR(cusp->y, kOrigin[1] + 0.01, 1e-12);

  // Without the outer disks the tangent points themselves are witnesses (and the void
  // spills out past them, where the outer disks were the only cover).
  const Scene bare = soddy_torus(1.0, false, false);
  const Report corners = oracle::check_all(bare.box, bare.d.r, bare.d.c, 1e-6, 0);
  EXPECT_FALSE(corners.maximal());
  for (const auto& u : corners.uncovered) EXPECT_LT(from_incenter(u), 1.5) << u.why;
  for (int k = 0; k < 3; ++k) {
    const double x = kOrigin[0] + kTangent[k][0], y = kOrigin[1] + kTangent[k][1];
    EXPECT_TRUE(std::any_of(corners.uncovered.begin(), corners.uncovered.end(), [&](const auto& u) {
      return std::hypot(u.x - x, u.y - y) < 1e-9 && mentions(u.why, "corner of disks");
    })) << corners.summary();
  }

  // The plug covers the cusps too.
  const Scene plugged = soddy_torus(1.0, true, true);
  const Report full = oracle::check_all(plugged.box, plugged.d.r, plugged.d.c, 1e-6, 50000);
  EXPECT_TRUE(full.conflict_free()) << full.summary();
  EXPECT_TRUE(full.maximal()) << full.summary();
}

// The same three disks alone in their triangle, as a planar domain: the disks cover it
// but for the void (each side is covered by its two end disks, |AB| = 1+2 etc.).
const Domain kTriangle{{{{0, 0}, {3, 0}, {0, 4}}}};

TEST(PlanarOracleVarying, HoleAndTangentCuspInATriangle) {
  PlanarOptions opt;
  opt.probes = 0;
  // Overlapping: the hole's corners.
  Disks d = soddy(0.999, false, false);
  const Domain scaled{{{{0, 0}, {3 * 0.999, 0}, {0, 4 * 0.999}}}};
  PlanarReport rep = oracle::check_planar(scaled, d.c, d.r, opt);
  EXPECT_TRUE(rep.conflict_free() && rep.inside() && rep.on_boundary() && rep.boundary_maximal())
      << rep.summary();
  EXPECT_FALSE(rep.maximal());
  EXPECT_EQ(rep.uncovered_count, 3u) << rep.summary();
  for (const auto& u : rep.uncovered) {
    EXPECT_TRUE(mentions(u.why, "corner of disks")) << u.why;
    EXPECT_LT(from_incenter(u, 0, 0), 1.0) << u.why;
  }
  d = soddy(0.999, false, true);
  EXPECT_TRUE(oracle::check_planar(scaled, d.c, d.r).ok());

  // Tangent, with the outer disks: only the probes beside the corners see the void.
  // The outer disks' centers lie outside the triangle, hence no containment check.
  d = soddy(1.0, true, false);
  opt.containment = false;
  rep = oracle::check_planar(kTriangle, d.c, d.r, opt);
  EXPECT_FALSE(rep.maximal()) << rep.summary();
  EXPECT_TRUE(rep.conflict_free() && rep.on_boundary() && rep.boundary_maximal()) << rep.summary();
  ASSERT_EQ(rep.uncovered_count, 3u) << rep.summary();
  for (const auto& u : rep.uncovered) {
    EXPECT_TRUE(mentions(u.why, "probe beside the corner of disks")) << u.why;
    EXPECT_TRUE(oracle::even_odd_inside(kTriangle, u.x, u.y));
  }
  d = soddy(1.0, true, true);
  opt.probes = 20000;
  EXPECT_TRUE(oracle::check_planar(kTriangle, d.c, d.r, opt).ok());
}

// ---------------------------------------------------------------- conflicts

TEST(OracleVarying, ConflictIsTheSmallerDiskCoveringTheOtherCenter) {
  // A disk of radius 1 at (5, 5) and one of radius 3 at distance d to its right.
  struct Case {
    double d;
    bool conflict, covered;
  };
  // d = 0.5: each center inside the other disk; 0.99: the small disk still covers the
  // big center; 1.01: only the big disk covers the small center (allowed); 3.01: none.
  for (const Case k : {Case{0.5, true, false}, Case{0.99, true, false}, Case{1.01, false, true},
                       Case{3.01, false, false}}) {
    SCOPED_TRACE(k.d);
    const Points c{{5, 5}, {5 + k.d, 5}};
    const Report rep = oracle::check_conflicts(Box{10, 10}, Radii{1, 3}, c);
    EXPECT_EQ(rep.conflict_free(), !k.conflict) << rep.summary();
    EXPECT_EQ(rep.conflict_count, k.conflict ? 1u : 0u);
    EXPECT_EQ(rep.covered_center_count, k.covered ? 1u : 0u);
    const auto& list = k.conflict ? rep.conflicts : rep.covered_centers;
    if (k.conflict || k.covered) {
      ASSERT_EQ(list.size(), 1u);
      EXPECT_EQ(list[0].i, 0u);
      EXPECT_EQ(list[0].j, 1u);
      EXPECT_NEAR(list[0].distance, k.d, 1e-12);
    }
    EXPECT_NEAR(rep.min_distance, k.d, 1e-12);

    // The planar oracle, in a square around them, agrees.
    PlanarOptions opt;
    opt.boundary = opt.maximality = false;
    const PlanarReport pr =
        oracle::check_planar(Domain{{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}}}, c, Radii{1, 3}, opt);
    EXPECT_EQ(pr.conflict_count, rep.conflict_count) << pr.summary();
    EXPECT_EQ(pr.covered_center_count, rep.covered_center_count);
    EXPECT_EQ(pr.conflict_free(), !k.conflict);
  }
}

// ---------------------------------------------------------------- graded lattices
//
// A rectangular lattice whose column gaps h_k (between columns k and k+1) change by
// 0.05 per column, row spacing v = 1; every disk of column k has radius
//   r_k = 1.01 * hypot(m_k / 2, 1/2),  m_k = the larger gap beside column k.
// Covered: a point of the cell between columns k and k+1 and two rows lies within
// h_k/2 horizontally and 1/2 vertically of a corner of its own half of the cell, so
// within hypot(h_k/2, 1/2) <= r/1.01 of that corner's disk (1% margin >> tol).
// No conflicts, and no covered centers: with gaps in [0.8, 1.2] every radius lies in
// [1.01 * hypot(0.4, 0.5), 1.01 * hypot(0.6, 0.5)] = [0.647, 0.789], below every
// center distance (>= min(gap, v) = 0.8).
double graded_radius(double left_gap, double right_gap) {
  return 1.01 * std::hypot(std::max(left_gap, right_gap) / 2, 0.5);
}

// In a 16 x 8 torus: 16 columns, gaps 0.8, 0.85, ..., 1.2 (gap 8), ..., 0.85 (gap 15,
// wrapping to column 0); they add up to 16. 8 rows.
Disks graded_torus() {
  std::vector<double> gap(16), x(16, 0.0);
  for (int k = 0; k < 16; ++k) gap[k] = 0.8 + 0.05 * std::min(k, 16 - k);
  for (int k = 1; k < 16; ++k) x[k] = x[k - 1] + gap[k - 1];
  Disks d;
  for (int row = 0; row < 8; ++row)
    for (int k = 0; k < 16; ++k) d.add(x[k], row, graded_radius(gap[(k + 15) % 16], gap[k]));
  return d;
}
const Box kGradedBox{16, 8};

TEST(OracleVarying, GradedLatticePasses) {
  const Disks d = graded_torus();
  const Report rep = oracle::check_all(kGradedBox, d.r, d.c);
  EXPECT_TRUE(rep.conflict_free()) << rep.summary();
  EXPECT_TRUE(rep.maximal()) << rep.summary();
  EXPECT_EQ(rep.covered_center_count, 0u);
  EXPECT_NEAR(rep.min_distance, 0.8, 1e-12);
  EXPECT_NEAR(rep.r_min, 1.01 * std::hypot(0.425, 0.5), 1e-12);  // beside gaps 0.8, 0.85
  EXPECT_NEAR(rep.r, 1.01 * std::hypot(0.6, 0.5), 1e-12);
  // No probe is farther from its nearest center than the widest half cell's corner.
  EXPECT_LE(rep.max_probe_gap, std::hypot(0.6, 0.5));
  // Both ways of finding neighbours say the same.
  const Report grid = oracle::check_all(kGradedBox, d.r, d.c, 1e-6, 1000, 1, Method::grid);
  const Report all = oracle::check_all(kGradedBox, d.r, d.c, 1e-6, 1000, 1, Method::all_pairs);
  EXPECT_TRUE(grid.maximal() && all.maximal() && grid.conflict_free() && all.conflict_free());
}

TEST(OracleVarying, GradedLatticeWithoutOneDiskHasAHole) {
  Disks d = graded_torus();
  const std::size_t k = 3 * 16 + 8;  // row 3, the widest column (gaps 1.15 and 1.2)
  const auto gone = d.c[k];
  d.c.erase(d.c.begin() + k);
  d.r.erase(d.r.begin() + k);
  // Every other center is >= 1 away from it, and every radius is <= 0.789.
  const Report rep = oracle::check_all(kGradedBox, d.r, d.c, 1e-6, 0);
  EXPECT_TRUE(rep.conflict_free()) << rep.summary();
  EXPECT_FALSE(rep.maximal());
  for (const auto& u : rep.uncovered)
    EXPECT_LT(std::hypot(u.x - gone[0], u.y - gone[1]), 1.0) << u.why;
}

TEST(OracleVarying, CoveredCentersAreReportedButAllowed) {
  // A disk of radius 0.05, 0.1 above the center of a disk of radius 0.789 (row 3, the
  // widest column): the big disk covers its center (0.1 < 0.789), it does not cover
  // the big center (0.1 >= 0.05). Its circle meets no other (the nearest other center,
  // 0.9 above it, has radius 0.789 < 0.9 - 0.05), but lies inside the big disk, so
  // nothing is uncovered.
  Disks d = graded_torus();
  const std::size_t big = 3 * 16 + 8;
  d.add(d.c[big][0], d.c[big][1] + 0.1, 0.05);
  const Report rep = oracle::check_all(kGradedBox, d.r, d.c);
  EXPECT_TRUE(rep.conflict_free()) << rep.summary();
  EXPECT_TRUE(rep.maximal()) << rep.summary();
  ASSERT_EQ(rep.covered_center_count, 1u) << rep.summary();
  EXPECT_EQ(rep.covered_centers[0].i, big);
  EXPECT_EQ(rep.covered_centers[0].j, d.c.size() - 1);
  EXPECT_NEAR(rep.covered_centers[0].distance, 0.1, 1e-12);
  EXPECT_TRUE(mentions(rep.summary(), "covered by a larger disk (allowed): 1")) << rep.summary();

  // Without the big disk, the small circle borders the hole left behind.
  d.c.erase(d.c.begin() + big);
  d.r.erase(d.r.begin() + big);
  const Report hole = oracle::check_all(kGradedBox, d.r, d.c, 1e-6, 0);
  EXPECT_EQ(hole.covered_center_count, 0u);
  EXPECT_FALSE(hole.maximal());
  const std::string isolated =
      "circle of disk " + std::to_string(d.c.size() - 1) + " meets no other circle";
  EXPECT_TRUE(std::any_of(hole.uncovered.begin(), hole.uncovered.end(), [&](const auto& u) {
    return u.why == isolated;
  })) << hole.summary();

  // Planar: the same pair inside a square.
  PlanarOptions opt;
  opt.boundary = opt.maximality = false;
  const PlanarReport pr = oracle::check_planar(Domain{{{{-1, -1}, {2, -1}, {2, 2}, {-1, 2}}}},
                                               Points{{0, 0}, {0, 0.1}}, Radii{0.789, 0.05}, opt);
  EXPECT_TRUE(pr.ok()) << pr.summary();
  EXPECT_EQ(pr.covered_center_count, 1u);
}

// The planar variant: the 9 x 9 square with 10 columns at gaps 0.8, 0.85, ..., 1.2
// (adding up to 9) and 10 rows at spacing 1, so the outermost rows and columns lie on
// the boundary and every corner of the square has a disk. The radii are those of the
// torus (a missing gap counts as 0), so the same argument covers the square. 1D: the
// boundary disks of a side are at most 1.2 apart and have radii > 1.2 / 2.
Disks graded_square() {
  std::vector<double> x(10, 0.0);
  for (int k = 1; k < 10; ++k) x[k] = x[k - 1] + 0.8 + 0.05 * (k - 1);
  Disks d;
  for (int row = 0; row < 10; ++row)
    for (int k = 0; k < 10; ++k)
      d.add(x[k], row, graded_radius(k > 0 ? x[k] - x[k - 1] : 0, k < 9 ? x[k + 1] - x[k] : 0));
  return d;
}
const Domain kSquare9{{{{0, 0}, {9, 0}, {9, 9}, {0, 9}}}};

TEST(PlanarOracleVarying, GradedSquarePasses) {
  const Disks d = graded_square();
  ASSERT_NEAR(d.c.back()[0], 9.0, 1e-12);
  const PlanarReport rep = oracle::check_planar(kSquare9, d.c, d.r);
  EXPECT_TRUE(rep.ok()) << rep.summary();
  EXPECT_EQ(rep.boundary_count, 36u);
  EXPECT_EQ(rep.covered_center_count, 0u);
  EXPECT_NEAR(rep.min_distance, 0.8, 1e-12);
  EXPECT_NEAR(rep.r_min, 1.01 * std::hypot(0.4, 0.5), 1e-12);
  EXPECT_NEAR(rep.r, 1.01 * std::hypot(0.6, 0.5), 1e-12);

  // An inner disk removed: a hole (centers around it >= 0.8 away, radii <= 0.789).
  Disks holed = d;
  const std::size_t k = 4 * 10 + 5;
  holed.c.erase(holed.c.begin() + k);
  holed.r.erase(holed.r.begin() + k);
  PlanarOptions opt;
  opt.probes = 0;
  const PlanarReport hole = oracle::check_planar(kSquare9, holed.c, holed.r, opt);
  EXPECT_FALSE(hole.maximal()) << hole.summary();
  EXPECT_TRUE(hole.boundary_maximal() && hole.conflict_free());
  for (const auto& u : hole.uncovered)
    EXPECT_LT(std::hypot(u.x - d.c[k][0], u.y - d.c[k][1]), 1.0) << u.why;

  // A boundary disk removed from the widest side (x = 9): the side has a gap.
  Disks gap = d;
  gap.c.erase(gap.c.begin() + 4 * 10 + 9);
  gap.r.erase(gap.r.begin() + 4 * 10 + 9);
  const PlanarReport side = oracle::check_planar(kSquare9, gap.c, gap.r, opt);
  EXPECT_FALSE(side.boundary_maximal()) << side.summary();
  EXPECT_FALSE(side.maximal());
}

// ---------------------------------------------------------------- one radius, two ways

void expect_identical(const Report& a, const Report& b) {
  EXPECT_EQ(a.conflicts_checked, b.conflicts_checked);
  EXPECT_EQ(a.maximality_checked, b.maximality_checked);
  EXPECT_EQ(a.n, b.n);
  EXPECT_EQ(a.r, b.r);
  EXPECT_EQ(a.r_min, b.r_min);
  EXPECT_EQ(a.tol, b.tol);
  EXPECT_EQ(a.conflict_count, b.conflict_count);
  EXPECT_EQ(a.covered_center_count, 0u);
  EXPECT_EQ(b.covered_center_count, 0u);
  EXPECT_EQ(a.uncovered_count, b.uncovered_count);
  EXPECT_EQ(a.min_distance, b.min_distance);
  EXPECT_EQ(a.max_probe_gap, b.max_probe_gap);
  ASSERT_EQ(a.conflicts.size(), b.conflicts.size());
  for (std::size_t k = 0; k < a.conflicts.size(); ++k) {
    EXPECT_EQ(a.conflicts[k].i, b.conflicts[k].i);
    EXPECT_EQ(a.conflicts[k].j, b.conflicts[k].j);
    EXPECT_EQ(a.conflicts[k].distance, b.conflicts[k].distance);
  }
  ASSERT_EQ(a.uncovered.size(), b.uncovered.size());
  for (std::size_t k = 0; k < a.uncovered.size(); ++k) {
    EXPECT_EQ(a.uncovered[k].x, b.uncovered[k].x);
    EXPECT_EQ(a.uncovered[k].y, b.uncovered[k].y);
    EXPECT_EQ(a.uncovered[k].why, b.uncovered[k].why);
  }
  EXPECT_EQ(a.summary(), b.summary());
}

TEST(OracleVarying, OneRadiusGivesIdenticalReportsBothWays) {
  Lattice moved = hex(10, 12);
  moved.pts[45][0] += 0.3 * moved.s;  // three conflicts
  Lattice gappy = hex(10, 12);
  gappy.pts.erase(gappy.pts.begin() + 57);
  const Lattice H = hex(10, 12), S = rect(10, 10, 0.1, 0.1), R = rect(20, 6, 0.1, 0.15);
  struct Case {
    const Lattice* L;
    double r;
  };
  const double cover_r = std::hypot(0.1, 0.15) / 2;
  for (const Case k :
       {Case{&H, H.s}, Case{&H, H.s / kSqrt3 * 1.001}, Case{&H, H.s / kSqrt3},
        Case{&H, H.s / kSqrt3 * 0.999}, Case{&moved, moved.s}, Case{&gappy, 0.6 * H.s},
        Case{&S, 0.1 / kSqrt2 * 0.999}, Case{&S, 0.1 / kSqrt2}, Case{&R, cover_r * 0.999},
        Case{&R, cover_r * 1.001}}) {
    const Radii radii(k.L->pts.size(), k.r);
    for (const Method m : {Method::all_pairs, Method::grid}) {
      SCOPED_TRACE(testing::Message() << "r=" << k.r << " grid=" << (m == Method::grid));
      expect_identical(oracle::check_all(k.L->box, k.r, k.L->pts, 1e-6, 3000, 7, m),
                       oracle::check_all(k.L->box, radii, k.L->pts, 1e-6, 3000, 7, m));
    }
    expect_identical(oracle::check_conflicts(k.L->box, k.r, k.L->pts),
                     oracle::check_conflicts(k.L->box, radii, k.L->pts));
    expect_identical(oracle::check_maximal(k.L->box, k.r, k.L->pts, 1e-6, 0),
                     oracle::check_maximal(k.L->box, radii, k.L->pts, 1e-6, 0));
  }
}

TEST(PlanarOracleVarying, OneRadiusGivesIdenticalReportsBothWays) {
  const Domain square{{{{0, 0}, {5, 0}, {5, 5}, {0, 5}}}};
  Points full;
  for (double x : {0.0, 1.25, 2.5, 3.75, 5.0})
    for (double y : {0.0, 1.25, 2.5, 3.75, 5.0}) full.push_back({x, y});
  Points holed = full, crowded = full;
  holed.erase(holed.begin() + 12);
  crowded.push_back({0.5, 0.5});
  for (const Points* c : {&full, &holed, &crowded}) {
    for (const double r : {1.0, 0.9}) {
      const PlanarReport a = oracle::check_planar(square, *c, r);
      const PlanarReport b = oracle::check_planar(square, *c, Radii(c->size(), r));
      EXPECT_EQ(a.summary(), b.summary());
      EXPECT_EQ(a.ok(), b.ok());
      EXPECT_EQ(a.covered_center_count, 0u);
      EXPECT_EQ(b.covered_center_count, 0u);
      EXPECT_EQ(a.uncovered_count, b.uncovered_count);
      EXPECT_EQ(a.boundary_gap_count, b.boundary_gap_count);
      EXPECT_EQ(a.min_distance, b.min_distance);
      EXPECT_EQ(a.max_probe_gap, b.max_probe_gap);
      ASSERT_EQ(a.uncovered.size(), b.uncovered.size());
      for (std::size_t k = 0; k < a.uncovered.size(); ++k) {
        EXPECT_EQ(a.uncovered[k].x, b.uncovered[k].x);
        EXPECT_EQ(a.uncovered[k].y, b.uncovered[k].y);
        EXPECT_EQ(a.uncovered[k].why, b.uncovered[k].why);
      }
    }
  }
}

// ---------------------------------------------------------------- random radii

struct Random {
  Points c;
  Radii r;
};

// n uniform centers with radii uniform in [r0, r1].
Random random_disks(const Box& box, std::size_t n, double r0, double r1, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ux(0, box.width), uy(0, box.height), ur(r0, r1);
  Random d;
  for (std::size_t k = 0; k < n; ++k) {
    d.c.push_back({ux(rng), uy(rng)});
    d.r.push_back(ur(rng));
  }
  return d;
}

TEST(OracleVarying, GridAgreesWithAllPairs) {
  int maximal = 0, not_maximal = 0;
  std::uint64_t seed = 0;
  for (const Box box : {Box{1.3, 0.8}, Box{0.3, 0.2}}) {
    for (const double r : {0.02, 0.045, 0.07}) {
      ++seed;
      const std::size_t n = box.width > 1 ? 1000 : 15;
      const Random d = random_disks(box, n, r / 3, r * (box.width > 1 ? 1.0 : 3.0), seed);
      const Report a = oracle::check_all(box, d.r, d.c, 1e-6, 3000, seed, Method::all_pairs);
      const Report g = oracle::check_all(box, d.r, d.c, 1e-6, 3000, seed, Method::grid);
      SCOPED_TRACE(g.summary());
      EXPECT_EQ(a.conflict_count, g.conflict_count);
      EXPECT_EQ(a.covered_center_count, g.covered_center_count);
      EXPECT_EQ(a.uncovered_count, g.uncovered_count);
      EXPECT_EQ(a.min_distance, g.min_distance);
      EXPECT_EQ(a.max_probe_gap, g.max_probe_gap);
      EXPECT_GT(a.covered_center_count, 0u);  // the test does see unequal pairs
      (a.maximal() ? maximal : not_maximal)++;
    }
  }
  EXPECT_GT(maximal, 0);
  EXPECT_GT(not_maximal, 0);
}

TEST(OracleVarying, ProbesNeverFindAVoidTheCornersMissed) {
  // As in oracle_test.cpp, with radii spread over a factor of 3 (so disks inside other
  // disks and circles crossing at all angles occur).
  std::mt19937_64 rng(7);
  int probed = 0, exact_only = 0, neither = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const Box box{std::uniform_real_distribution<double>(0.3, 1.5)(rng),
                  std::uniform_real_distribution<double>(0.3, 1.5)(rng)};
    const std::size_t n = 5 + rng() % 300;
    const double typical = std::sqrt(box.width * box.height / n);
    const double r = typical * std::uniform_real_distribution<double>(1.0, 2.5)(rng);
    const Random d = random_disks(box, n, r / 3, r, rng());
    const Report exact = oracle::check_maximal(box, d.r, d.c, 1e-6, 0, 1, Method::grid);
    const Report probes = oracle::check_maximal(box, d.r, d.c, 1e-6, 10000, trial, Method::grid);
    SCOPED_TRACE(probes.summary());
    const bool probe_found = probes.uncovered_count > exact.uncovered_count;
    if (probe_found) {
      EXPECT_FALSE(exact.maximal());
    }
    if (exact.maximal()) {
      ++neither;
    } else {
      (probe_found ? probed : exact_only)++;
    }
  }
  EXPECT_GT(probed, 0);
  EXPECT_GT(neither, 0);
  (void)exact_only;
}

// ---------------------------------------------------------------- input

TEST(OracleVarying, RejectsBadRadii) {
  const Points two{{0.1, 0.1}, {0.5, 0.5}};
  EXPECT_THROW(oracle::check_all(Box{}, Radii{0.1}, two), std::invalid_argument);
  EXPECT_THROW(oracle::check_all(Box{}, Radii{0.1, 0}, two), std::invalid_argument);
  EXPECT_THROW(oracle::check_all(Box{}, Radii{0.1, -1}, two), std::invalid_argument);
  EXPECT_THROW(oracle::check_all(Box{}, Radii{0.1, NAN}, two), std::invalid_argument);
  EXPECT_THROW(oracle::check_conflicts(Box{}, Radii{0.1, INFINITY}, two), std::invalid_argument);
  const Domain unit{{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}}};
  EXPECT_THROW(oracle::check_planar(unit, two, Radii{0.1}), std::invalid_argument);
  EXPECT_THROW(oracle::check_planar(unit, two, Radii{0.1, 0}), std::invalid_argument);
  EXPECT_NO_THROW(oracle::check_planar(unit, two, Radii{0.1, 0.2}));
  // No disks: not maximal, whichever entry point.
  EXPECT_FALSE(oracle::check_all(Box{}, Radii{}, Points{}).maximal());
}

}  // namespace
