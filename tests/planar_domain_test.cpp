// SPDX-License-Identifier: GPL-3.0-or-later
// Planar domains: known areas, contains() and distance_to_boundary() against brute force
// over all segments, rejection of broken boundaries with messages that name the culprit,
// and the .poly, OFF and OBJ readers on the files in data/domains.
#include "disktune/planar_domain.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <string>

#include "disktune/errors.h"
#include "test_util.h"

namespace disktune {
namespace {

using test::message_of;

using test::TempDir;

const std::string kDomains = std::string(DISKTUNE_DATA_DIR) + "/domains/";

// Independent references: even-odd crossing with the crossing's x computed directly,
// and the smallest distance over every segment.
bool brute_contains(const std::vector<BoundarySegment>& segs, Vec2 p) {
  bool inside = false;
  for (const auto& s : segs) {
    if ((s.a.y > p.y) == (s.b.y > p.y)) continue;
    const double x = s.a.x + (p.y - s.a.y) * (s.b.x - s.a.x) / (s.b.y - s.a.y);
    if (x > p.x) inside = !inside;
  }
  return inside;
}

double brute_distance(const std::vector<BoundarySegment>& segs, Vec2 p) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& s : segs) {
    const Vec2 ab = s.b - s.a;
    const double t = std::clamp(dot(p - s.a, ab) / squared_norm(ab), 0.0, 1.0);
    best = std::min(best, distance(p, s.a + ab * t));
  }
  return best;
}

double signed_area(const std::vector<Vec2>& loop) {
  double sum = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) sum += cross(loop[i], loop[(i + 1) % loop.size()]);
  return sum / 2;
}

std::vector<Vec2> rect(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

bool mentions(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

void write_file(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

Vec2 point_in_box(Rng& rng, const Frame& f, double margin) {
  const Vec2 lo = f.origin - f.extent * margin, size = f.extent * (1 + 2 * margin);
  return lo + Vec2{uniform01(rng) * size.x, uniform01(rng) * size.y};
}

TEST(PlanarDomain, AreaOfSquareWithSquareHole) {
  const PlanarDomain d(rect(0, 0, 1, 1), {rect(0.3, 0.3, 0.7, 0.7)});
  EXPECT_NEAR(d.area(), 1 - 0.16, 1e-15);
  EXPECT_EQ(d.loops().size(), 2u);
  EXPECT_EQ(d.segments().size(), 8u);
  EXPECT_FALSE(d.frame().periodic);
  EXPECT_EQ(d.frame().origin, Vec2(0, 0));
  EXPECT_EQ(d.frame().extent, Vec2(1, 1));
}

TEST(PlanarDomain, StoresOuterCounterclockwiseAndHolesClockwise) {
  std::vector<Vec2> outer = rect(0, 0, 4, 2);
  std::reverse(outer.begin(), outer.end());  // given clockwise
  const PlanarDomain d(outer, {rect(1, 0.5, 1.5, 1), rect(2, 0.5, 3, 1.5)});
  EXPECT_GT(signed_area(d.loops()[0]), 0);
  EXPECT_LT(signed_area(d.loops()[1]), 0);
  EXPECT_LT(signed_area(d.loops()[2]), 0);
  EXPECT_EQ(d.loops()[0][0], outer[0]);  // vertex 0 stays first
  EXPECT_NEAR(d.area(), 8 - 0.25 - 1, 1e-14);
}

TEST(PlanarDomain, ContainsMatchesBruteForceOnDataDomains) {
  for (const char* name : {"square_with_hole.poly", "gear.poly", "sharp_corners.poly"}) {
    const PlanarDomain d = read_poly(kDomains + name);
    const auto segs = d.segments();
    Rng rng(7);
    int inside = 0, checked = 0;
    for (int i = 0; i < 20000; ++i) {
      const Vec2 p = point_in_box(rng, d.frame(), 0.05);
      if (brute_distance(segs, p) < 1e-9) continue;  // on the boundary: closed vs even-odd
      ++checked;
      const bool expected = brute_contains(segs, p);
      inside += expected;
      ASSERT_EQ(d.contains(p), expected) << name << " at (" << p.x << ", " << p.y << ")";
    }
    EXPECT_GT(inside, 1000) << name;
    EXPECT_GT(checked - inside, 1000) << name;
    // The boundary itself belongs to the closed domain.
    for (const auto& s : segs) {
      EXPECT_TRUE(d.contains(s.a)) << name;
      EXPECT_TRUE(d.contains((s.a + s.b) * 0.5)) << name;
    }
  }
}

TEST(PlanarDomain, ContainsIsExactWhereBoundariesFollowGridLines) {
  // Dyadic corners: edges along the background grid's lines and through its vertices,
  // and queries on those lines too, where every tie has to be broken consistently.
  const std::vector<PlanarDomain> domains{
      PlanarDomain(rect(0, 0, 1, 1), {rect(0.25, 0.25, 0.75, 0.75)}),
      PlanarDomain({{0, 0}, {1, 0}, {0, 1}}),
      PlanarDomain({{0, 0}, {1, 0}, {1, 1}, {0.5, 0.25}, {0, 1}}),
      PlanarDomain({{0, 0}, {2, 0}, {2, 1}, {1.5, 1}, {1.5, 0.5}, {1, 0.5}, {1, 1}, {0, 1}},
                   {{{0.25, 0.25}, {0.5, 0.125}, {0.75, 0.25}, {0.5, 0.375}}})};
  for (const PlanarDomain& d : domains) {
    const auto segs = d.segments();
    for (int i = -4; i <= 132; ++i) {
      for (int j = -4; j <= 68; ++j) {
        const Vec2 p{i / 64.0, j / 64.0};
        const bool expected = brute_distance(segs, p) < 1e-15 || brute_contains(segs, p);
        ASSERT_EQ(d.contains(p), expected) << "at (" << p.x << ", " << p.y << ")";
      }
    }
  }
}

TEST(PlanarDomain, DistanceToBoundaryMatchesBruteForce) {
  for (const char* name : {"square_with_hole.poly", "gear.poly", "sharp_corners.poly"}) {
    const PlanarDomain d = read_poly(kDomains + name);
    const auto segs = d.segments();
    Rng rng(11);
    for (int i = 0; i < 5000; ++i) {
      const Vec2 p = point_in_box(rng, d.frame(), 0.5);  // far outside too
      ASSERT_NEAR(d.distance_to_boundary(p), brute_distance(segs, p), 1e-12) << name;
    }
  }
}

TEST(PlanarDomain, RandomPointsAreInsideAndUniform) {
  const PlanarDomain d = read_poly(kDomains + "square_with_hole.poly");
  const auto segs = d.segments();
  Rng rng(3);
  int low = 0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const Vec2 p = d.random_point(rng);
    ASSERT_TRUE(brute_contains(segs, p) || brute_distance(segs, p) < 1e-12);
    low += p.y < 0.5;
  }
  // Below y = 0.5 lie 0.5 - 0.08 (half the hole) of the area 0.8.
  EXPECT_NEAR(static_cast<double>(low) / n, 0.42 / 0.8, 0.02);
}

TEST(PlanarDomain, RefusesSelfIntersectingBowtie) {
  const std::vector<Vec2> bowtie{{0, 0}, {1, 1}, {1, 0}, {0, 1}};
  EXPECT_THROW(PlanarDomain{bowtie}, InvalidInput);
  const std::string msg = message_of([&] { PlanarDomain{bowtie}; });
  EXPECT_TRUE(mentions(msg, "segment 0 of loop 0")) << msg;
  EXPECT_TRUE(mentions(msg, "segment 2 of loop 0")) << msg;
  EXPECT_TRUE(mentions(msg, "(0.5, 0.5)")) << msg;
}

TEST(PlanarDomain, RefusesHoleOutsideOuter) {
  auto make = [] { PlanarDomain(rect(0, 0, 1, 1), {rect(2, 2, 2.5, 2.5)}); };
  EXPECT_THROW(make(), InvalidInput);
  const std::string msg = message_of(make);
  EXPECT_TRUE(mentions(msg, "loop 1 (hole 0) is not inside")) << msg;
}

TEST(PlanarDomain, RefusesHoleCrossingOuter) {
  auto make = [] { PlanarDomain(rect(0, 0, 1, 1), {rect(0.8, 0.4, 1.2, 0.6)}); };
  EXPECT_THROW(make(), InvalidInput);
  const std::string msg = message_of(make);
  EXPECT_TRUE(mentions(msg, "segment 1 of loop 0")) << msg;
  EXPECT_TRUE(mentions(msg, "of loop 1 (hole 0)")) << msg;
}

TEST(PlanarDomain, RefusesOverlappingAndNestedHoles) {
  auto overlap = [] {
    PlanarDomain(rect(0, 0, 1, 1), {rect(0.1, 0.1, 0.5, 0.5), rect(0.4, 0.4, 0.8, 0.8)});
  };
  EXPECT_THROW(overlap(), InvalidInput);
  std::string msg = message_of(overlap);
  EXPECT_TRUE(mentions(msg, "loop 1 (hole 0)") && mentions(msg, "loop 2 (hole 1)")) << msg;

  auto nested = [] {
    PlanarDomain(rect(0, 0, 1, 1), {rect(0.1, 0.1, 0.9, 0.9), rect(0.4, 0.4, 0.6, 0.6)});
  };
  EXPECT_THROW(nested(), InvalidInput);
  msg = message_of(nested);
  EXPECT_TRUE(mentions(msg, "loop 2 (hole 1) lies inside loop 1 (hole 0)")) << msg;
}

TEST(PlanarDomain, RefusesTouchingLoops) {
  // A hole vertex on the outer boundary: touching counts as meeting.
  auto make = [] { PlanarDomain(rect(0, 0, 1, 1), {{{1, 0.5}, {0.8, 0.4}, {0.8, 0.6}}}); };
  const std::string msg = message_of(make);
  EXPECT_TRUE(mentions(msg, "segment 1 of loop 0")) << msg;
  EXPECT_TRUE(mentions(msg, "(1, 0.5)")) << msg;
}

TEST(PlanarDomain, RefusesFewVerticesRepeatsAndSpikes) {
  std::string msg = message_of([] { PlanarDomain(rect(0, 0, 1, 1), {{{0.2, 0.2}, {0.3, 0.3}}}); });
  EXPECT_TRUE(mentions(msg, "loop 1 (hole 0) has 2 vertices")) << msg;

  msg = message_of([] { PlanarDomain({{0, 0}, {1, 0}, {1, 0}, {1, 1}, {0, 1}}); });
  EXPECT_TRUE(mentions(msg, "vertex 1") && mentions(msg, "vertex 2")) << msg;
  EXPECT_TRUE(mentions(msg, "same point (1, 0)")) << msg;

  msg = message_of([] { PlanarDomain({{0, 0}, {2, 0}, {1, 0}, {1, 1}}); });
  EXPECT_TRUE(mentions(msg, "turns back on itself at vertex 1")) << msg;

  msg = message_of([] { PlanarDomain({{0, 0}, {1, 0}, {std::nan(""), 1}}); });
  EXPECT_TRUE(mentions(msg, "vertex 2")) << msg;
  EXPECT_THROW(PlanarDomain({{0, 0}, {1, 1}, {2, 2}, {3, 3}}), InvalidInput);  // no area
}

TEST(PlanarDomain, ValidatesLargeInputsQuickly) {
  // 10^5 segments: the grids keep validation near-linear (all pairs would take minutes).
  auto circle = [](Vec2 c, double r, int n) {
    std::vector<Vec2> out;
    for (int i = 0; i < n; ++i) {
      const double a = 2 * M_PI * i / n;
      out.push_back(c + Vec2{r * std::cos(a), r * std::sin(a)});
    }
    return out;
  };
  const PlanarDomain d(circle({0, 0}, 1, 90000), {circle({0, 0}, 0.5, 10000)});
  const double expected =
      0.5 * 90000 * std::sin(2 * M_PI / 90000) - 0.5 * 0.25 * 10000 * std::sin(2 * M_PI / 10000);
  EXPECT_NEAR(d.area(), expected, 1e-9);
  EXPECT_TRUE(d.contains({0.75, 0}));
  EXPECT_FALSE(d.contains({0.25, 0}));
  EXPECT_NEAR(d.distance_to_boundary({0.75, 0}), 0.25, 1e-6);

  auto crossed = circle({0, 0}, 1, 100000);
  std::swap(crossed[500], crossed[50000]);
  EXPECT_THROW(PlanarDomain{crossed}, InvalidInput);
}

TEST(PlanarDomain, ValidateRadiusRefusesCloseCorners) {
  const PlanarDomain d = read_poly(kDomains + "square_with_hole.poly");
  EXPECT_NO_THROW(d.validate_radius(0.1));
  EXPECT_NO_THROW(d.validate_radius(0.14));
  // The notch corner (0.4, 0.8) and the hole corner (0.3, 0.7) are 0.1414 apart.
  const std::string msg = message_of([&] { d.validate_radius(0.15); });
  EXPECT_TRUE(mentions(msg, "loop 0 (the outer boundary)") && mentions(msg, "loop 1 (hole 0)"))
      << msg;
  EXPECT_TRUE(mentions(msg, "0.14142") && mentions(msg, "use r <= 0.1414")) << msg;
  EXPECT_THROW(d.validate_radius(1e-6), InvalidInput);  // some 5.6e11 disks
  EXPECT_THROW(d.validate_radius(0), InvalidInput);
  EXPECT_THROW(d.validate_radius(std::nan("")), InvalidInput);
}

TEST(PolyReader, ReadsDataDomains) {
  const PlanarDomain square = read_poly(kDomains + "square_with_hole.poly");
  EXPECT_EQ(square.loops().size(), 2u);
  EXPECT_EQ(square.loops()[0].size(), 8u);
  EXPECT_NEAR(square.area(), 0.8, 1e-12);

  const PlanarDomain gear = read_poly(kDomains + "gear.poly");
  ASSERT_EQ(gear.loops().size(), 6u);
  EXPECT_EQ(gear.loops()[0].size(), 64u);
  EXPECT_EQ(gear.loops()[1].size(), 24u);
  EXPECT_NEAR(gear.area(), 2.20496835769809, 1e-8);  // the polygon's exact area

  const PlanarDomain star = read_poly(kDomains + "sharp_corners.poly");
  ASSERT_EQ(star.loops().size(), 2u);
  EXPECT_EQ(star.loops()[0].size(), 14u);
  EXPECT_NEAR(star.area(), 0.9362217571715524, 1e-8);
}

TEST(PolyReader, ReadsOneBasedNumbersAndComments) {
  TempDir dir;
  // The hole's segments come first: the outer loop is found by size, not position.
  write_file(dir.file("a.poly"),
             "# a 3 x 3 square with a unit hole, numbered from 1\n"
             "\n"
             "8 2 1 1   # vertices, dimension, attributes, markers\n"
             "1 0 0 7.5 1\n2 3 0 7.5 1\n3 3 3 7.5 1\n4 0 3 7.5 1\n"
             "5 1 1 0 2\n6 2 1 0 2\n7 2 2 0 2\n8 1 2 0 2\n"
             "8 1\n"
             "1 5 6 2\n2 6 7 2\n3 7 8 2\n4 8 5 2 # last segment of the hole\n"
             "5 1 2 1\n6 2 3 1\n7 3 4 1\n8 4 1 1\n"
             "1\n"
             "1 1.5 1.5\n");
  const PlanarDomain d = read_poly(dir.file("a.poly"));
  EXPECT_NEAR(d.area(), 8, 1e-14);
  EXPECT_EQ(d.loops()[0][0], Vec2(0, 0));
  EXPECT_FALSE(d.contains({1.5, 1.5}));
  EXPECT_TRUE(d.contains({0.5, 1.5}));
}

TEST(PolyReader, RefusesBrokenFilesWithFileAndLine) {
  TempDir dir;
  const std::string path = dir.file("b.poly");
  write_file(path, "0 2 0 0\n4 0\n1 1 2\n");
  std::string msg = message_of([&] { read_poly(path); });
  EXPECT_TRUE(mentions(msg, path + ", line 1") && mentions(msg, ".node")) << msg;

  // Vertices 0 and 3 end only one segment each: the chain is open.
  write_file(path, "4 2 0 0\n0 0 0\n1 1 0\n2 1 1\n3 0 1\n3 0\n0 0 1\n1 1 2\n2 2 3\n0\n");
  msg = message_of([&] { read_poly(path); });
  EXPECT_TRUE(mentions(msg, ", line 2: vertex 0 ends only one segment (line 7)")) << msg;

  // A second loop without a hole point.
  write_file(path,
             "7 2 0 0\n0 0 0\n1 3 0\n2 3 3\n3 0 3\n4 1 1\n5 2 1\n6 1 2\n"
             "7 0\n0 0 1\n1 1 2\n2 2 3\n3 3 0\n4 4 5\n5 5 6\n6 6 4\n0\n");
  msg = message_of([&] { read_poly(path); });
  EXPECT_TRUE(mentions(msg, "the loop through vertices 4, 5, 6") && mentions(msg, "hole point"))
      << msg;

  // An island inside the hole: refused as a nested loop.
  write_file(path,
             "11 2 0 0\n0 0 0\n1 9 0\n2 9 9\n3 0 9\n4 1 1\n5 8 1\n6 8 8\n7 1 8\n"
             "8 4 4\n9 5 4\n10 4 5\n"
             "11 0\n0 0 1\n1 1 2\n2 2 3\n3 3 0\n4 4 5\n5 5 6\n6 6 7\n7 7 4\n"
             "8 8 9\n9 9 10\n10 10 8\n1\n0 2 2\n");
  msg = message_of([&] { read_poly(path); });
  EXPECT_TRUE(mentions(msg, "nested") && mentions(msg, "the loop through vertices 8, 9, 10"))
      << msg;

  write_file(path, "3 2 0 0\n0 0 0\n1 1 0\n2 x 1\n");
  msg = message_of([&] { read_poly(path); });
  EXPECT_TRUE(mentions(msg, "line 4") && mentions(msg, "'x'")) << msg;

  EXPECT_THROW(read_poly(dir.file("missing.poly")), IoError);
}

TEST(PlanarDomain, FromTrianglesOfSquareWithHole) {
  // A 3 x 3 grid of unit cells without the middle one, two triangles per cell, some
  // given clockwise.
  std::vector<Vec2> pts;
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) pts.push_back({double(i), double(j)});
  }
  std::vector<std::array<std::size_t, 3>> tris;
  for (std::size_t j = 0; j < 3; ++j) {
    for (std::size_t i = 0; i < 3; ++i) {
      if (i == 1 && j == 1) continue;
      const std::size_t a = 4 * j + i, b = a + 1, c = a + 5, e = a + 4;
      tris.push_back({a, b, c});
      tris.push_back((i + j) % 2 ? std::array<std::size_t, 3>{a, e, c} : std::array{a, c, e});
    }
  }
  const PlanarDomain d = planar_domain_from_triangles(pts, tris);
  ASSERT_EQ(d.loops().size(), 2u);
  EXPECT_EQ(d.loops()[0].size(), 12u);  // straight-angle vertices are kept
  EXPECT_EQ(d.loops()[1].size(), 4u);
  EXPECT_NEAR(d.area(), 8, 1e-14);

  auto too_many = tris;
  too_many.push_back({0, 1, 6});  // a third triangle on edge (0, 1)
  const std::string msg = message_of([&] { planar_domain_from_triangles(pts, too_many); });
  EXPECT_TRUE(mentions(msg, "vertex 0 (0, 0)") && mentions(msg, "vertex 1 (1, 0)")) << msg;

  // Two triangles sharing only a vertex: two loops touch there.
  const std::vector<Vec2> bow{{0, 0}, {1, 0}, {1, 1}, {2, 1}, {2, 2}};
  EXPECT_THROW(planar_domain_from_triangles(bow, {{{0, 1, 2}}, {{2, 3, 4}}}), InvalidInput);
  EXPECT_THROW(planar_domain_from_triangles(bow, {{{0, 1, 7}}}), InvalidInput);
}

TEST(PlanarDomain, ReadsOffWithCommentAndObj) {
  TempDir dir;
  write_file(dir.file("sq.off"),
             "# a unit square as two triangles\nOFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
             "3 0 1 2\n3 0 2 3\n");
  const PlanarDomain off = read_planar_domain(dir.file("sq.off"));
  EXPECT_NEAR(off.area(), 1, 1e-15);
  EXPECT_EQ(off.loops()[0].size(), 4u);

  write_file(dir.file("sq.obj"), "v 0 0 2\nv 1 0 2\nv 1 1 2\nv 0 1 2\nf 1 2 3\nf 1 3 4\n");
  EXPECT_NEAR(read_planar_domain(dir.file("sq.obj")).area(), 1, 1e-15);

  write_file(dir.file("tilt.off"), "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0.5\n3 0 1 2\n");
  std::string msg = message_of([&] { read_planar_domain(dir.file("tilt.off")); });
  EXPECT_TRUE(mentions(msg, "not planar: vertex 2 has z=0.5")) << msg;

  write_file(dir.file("quad.off"), "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n");
  msg = message_of([&] { read_planar_domain(dir.file("quad.off")); });
  EXPECT_TRUE(mentions(msg, "face 0 has 4 vertices")) << msg;

  msg = message_of([&] { read_planar_domain(dir.file("sq.stl")); });
  EXPECT_TRUE(mentions(msg, ".poly") && mentions(msg, ".off") && mentions(msg, ".obj")) << msg;
  EXPECT_THROW(read_planar_domain(dir.file("missing.off")), IoError);
}

TEST(PlanarDomain, DataOffMatchesDataPoly) {
  const PlanarDomain off = read_planar_domain(kDomains + "square_with_hole.off");
  const PlanarDomain poly = read_planar_domain(kDomains + "square_with_hole.poly");
  EXPECT_NEAR(off.area(), poly.area(), 1e-12);
  EXPECT_EQ(off.loops().size(), 2u);
  Rng rng(5);
  for (int i = 0; i < 2000; ++i) {
    const Vec2 p = point_in_box(rng, poly.frame(), 0.05);
    EXPECT_EQ(off.contains(p), poly.contains(p));
  }
}

}  // namespace
}  // namespace disktune
