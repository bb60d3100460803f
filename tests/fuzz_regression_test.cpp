// SPDX-License-Identifier: GPL-3.0-or-later
// Inputs the fuzz targets (tests/fuzz/) found to crash a reader, reduced to what matters:
// each is read again here and must give a domain or sizing, or InvalidInput, as
// documented; under the sanitizers (cmake/setup.sh test) a relapse also shows as the
// sanitizer's report. The inputs stay in the fuzz corpora as well.
#include <gtest/gtest.h>

#include <fstream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "disktune/errors.h"
#include "disktune/planar_domain.h"
#include "disktune/sizing.h"
#include "disktune/surface_io.h"
#include "disktune/surface_packing.h"
#include "disktune/surface_sizing.h"
#include "test_util.h"

namespace disktune {
namespace {

using test::TempDir;

std::string written(const TempDir& dir, const std::string& name, const std::string& text) {
  const std::string path = dir.file(name);
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// A quadrilateral 1 wide and 7.7e121 long: the segment grid of the loop validation took
// sqrt(area / n) as its cell side, which gave more rows than an int64 counts (undefined
// behaviour). The domain is valid and now reads.
TEST(FuzzRegression, PolyDomainFarLongerThanWide) {
  TempDir dir;
  const std::string path = written(dir, "thin.poly",
                                   "4 2 0 0\n"
                                   "1 0 0\n"
                                   "2 1 0\n"
                                   "3 1 7.7e121\n"
                                   "4 0 1\n"
                                   "4 0\n"
                                   "1 1 2\n2 2 3\n3 3 4\n4 4 1\n"
                                   "0\n");
  const PlanarDomain domain = read_poly(path);
  EXPECT_TRUE(domain.contains({0.5, 0.5}));
  EXPECT_FALSE(domain.contains({-1e121, 0.5}));  // (the tolerance is relative to the size)
  EXPECT_NEAR(domain.distance_to_boundary({0.5, 0.5}), 0.5, 1e-12);
  // Its feature sizing: the corner (0, 0) is 1 from the segments not ending there; the
  // far end (1, 7.7e121) of the one from there to (0, 1) once made that distance 0.
  const Sizing sizing = feature_sizing(std::make_shared<const PlanarDomain>(domain), 7.7e119);
  EXPECT_NEAR(sizing({0, 0}), kFeatureShare * 1, 1e-12);
  EXPECT_GE(sizing({0.5, 0}), kFeatureShare * 1);  // farther than 1 from (0, 1) and x = 1
}

// "auto:.0000000000959038974" on the unit square: the feature sizing walked each side in
// steps of 7 r_max / 0.45 (its search for other boundary parts reached no farther), about
// 10^11 of them; the sanitized fuzzer timed out. The walk now steps as far as the other
// parts allow. The radius is r_max everywhere (no part is within r_max / 0.45 of another).
TEST(FuzzRegression, FeatureSizingWithATinyRadius) {
  const auto square = std::make_shared<const PlanarDomain>(std::vector<Vec2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  for (const auto& [text, r_max] : {std::pair{"auto:1e-9", 1e-9}, {"auto:9.59038974e-11", 9.59038974e-11}}) {
    const Sizing sizing = parse_sizing(text, square);
    EXPECT_NEAR(sizing({0.5, 0.5}), r_max, 1e-3 * r_max);
    EXPECT_NEAR(sizing({0, 0}), r_max, 1e-3 * r_max);
  }
  const Sizing again = parse_sizing("auto:.0000000000959038974\r", square);
  EXPECT_NEAR(again({0.3, 1}), 9.59038974e-11, 1e-20);
}

// A triangle with a corner 1e-308 from the opposite side (the fuzzer, 2026-12-04): the
// squared distance underflowed to 0, so the feature sizing gave radius 0 there. Such a
// domain reads, and its feature sizing is refused, naming the place.
TEST(FuzzRegression, FeatureCloserThanADoubleCanMeasure) {
  TempDir dir;
  const std::string path = written(dir, "tiny.poly", "3 2 0 0\n1 1e-308 0\n2 0e304 0\n3 0 1\n3 0\n1 1 2\n2 2 3\n3 3 1\n");
  const auto domain = std::make_shared<const PlanarDomain>(read_poly(path));
  try {
    feature_sizing(domain, 0.01);
    ADD_FAILURE() << "a feature 1e-308 wide was taken";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("closer than the arithmetic can measure"), std::string::npos) << e.what();
  }
}

// Corners at x = -1e308 and 1e308: the width overflowed, so the segment grid's cell count
// was NaN (undefined as an int64). The file is refused.
TEST(FuzzRegression, PolyDomainWiderThanADouble) {
  TempDir dir;
  const std::string path = written(dir, "wide.poly",
                                   "3 2 0 0\n1 -1e308 0\n2 1e308 0\n3 0 1\n"
                                   "3 0\n1 1 2\n2 2 3\n3 3 1\n");
  const std::string msg = test::message_of([&] { read_poly(path); });
  EXPECT_NE(msg.find("farther than a double can measure"), std::string::npos) << msg;
}

// A grid from -1e308 to 1e308: x1 - x0 overflows, so a point's place (x - x0) / (x1 - x0)
// was NaN and its cell index undefined. The file is refused instead.
TEST(FuzzRegression, SizingGridWiderThanADouble) {
  TempDir dir;
  const std::string path = written(dir, "wide.txt", "2 2 -1e308 0 1e308 1\n1 1\n1 1\n");
  const std::string msg = test::message_of([&] { grid_sizing(path); });
  EXPECT_NE(msg.find("line 1: the grid's rectangle is too large"), std::string::npos) << msg;
}

// A surface sample at x = 1e300: the grid that finds the triangles near a point cast
// x / cell to an int64 (undefined beyond 2^63). The point is refused as off the surface.
TEST(FuzzRegression, SurfaceCsvPointFarAway) {
  TempDir dir;
  const std::string path = written(dir, "far.csv", "x,y,z,r\n0.2,0.2,0,0.25\n1e300,0,0,0.25\n");
  auto triangle =
      std::make_shared<const SurfaceDomain>(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
                                            std::vector<SurfaceDomain::Triangle>{{0, 1, 2}});
  SurfacePacking packing(triangle, SurfaceSizing::constant(0.25));
  const std::string msg = test::message_of([&] { read_surface_csv(path, packing); });
  EXPECT_NE(msg.find("far.csv:3: point"), std::string::npos) << msg;
  EXPECT_NE(msg.find("lies farther than"), std::string::npos) << msg;
}

}  // namespace
}  // namespace disktune
