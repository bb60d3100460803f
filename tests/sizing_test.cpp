// SPDX-License-Identifier: GPL-3.0-or-later
// Sizing functions: values against hand computation, rejection of bad expressions and
// grid files with messages that say where, the --sizing dispatch, and what sampling
// finds (range, gradation, disk count) against closed forms.
#include "disktune/sizing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "disktune/density.h"
#include "disktune/errors.h"
#include "test_util.h"

namespace disktune {
namespace {

using test::message_of;

using test::TempDir;

constexpr double kPi = 3.14159265358979323846;

std::vector<Vec2> rect(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// The unit square with a square hole [0.4, 0.6]^2.
std::shared_ptr<const PlanarDomain> square_with_hole() {
  return std::make_shared<const PlanarDomain>(rect(0, 0, 1, 1),
                                              std::vector<std::vector<Vec2>>{rect(0.4, 0.4, 0.6, 0.6)});
}

void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

const Frame kUnitBox{{0, 0}, {1, 1}, false};
const Frame kUnitTorus{{0, 0}, {1, 1}, true};

TEST(SizingConstant, SameEverywhereAndOnlyPositive) {
  const Sizing s = constant_sizing(0.02);
  EXPECT_EQ(s({0.3, 0.7}), 0.02);
  EXPECT_EQ(s({-5, 100}), 0.02);
  EXPECT_EQ(s.description(), "0.02");
  EXPECT_THROW(constant_sizing(0), InvalidInput);
  EXPECT_THROW(constant_sizing(-0.1), InvalidInput);
  EXPECT_THROW(constant_sizing(std::nan("")), InvalidInput);
}

TEST(SizingExpression, ValuesMatchHandComputation) {
  const Sizing linear = expression_sizing("0.01 + 0.02*x");
  EXPECT_NEAR(linear({0, 0}), 0.01, 1e-15);
  EXPECT_NEAR(linear({0.5, 0.3}), 0.02, 1e-15);
  EXPECT_NEAR(linear({1, 7}), 0.03, 1e-15);
  EXPECT_EQ(linear.description(), "0.01 + 0.02*x");

  const Sizing wave = expression_sizing("0.005*(1+sin(2*pi*x))+0.01");
  EXPECT_NEAR(wave({0.25, 0}), 0.02, 1e-15);
  EXPECT_NEAR(wave({0.75, 0}), 0.01, 1e-15);
  EXPECT_NEAR(wave({0.1, 0.9}), 0.005 * (1 + std::sin(2 * kPi * 0.1)) + 0.01, 1e-15);

  const Sizing both = expression_sizing("max(0.001, 0.01 + 0.002*x*y - abs(y)^2/100)");
  EXPECT_NEAR(both({2, 3}), std::max(0.001, 0.01 + 0.012 - 0.09), 1e-15);
  EXPECT_NEAR(both({2, 0.5}), 0.01 + 0.002 - 0.0025, 1e-15);
}

TEST(SizingExpression, CopiesOutliveTheOriginalAndShareSafelyAcrossThreads) {
  Sizing copy = constant_sizing(1);
  {
    const Sizing original = expression_sizing("0.01 + x + 10*y");
    copy = original;
  }
  EXPECT_NEAR(copy({0.5, 0.25}), 3.01, 1e-14);

  std::vector<std::thread> threads;
  std::vector<int> wrong(4, 0);
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&copy, &wrong, t] {
      for (int k = 0; k < 20000; ++k) {
        const double x = t + k * 1e-4, y = k * 1e-3;
        if (copy({x, y}) != 0.01 + x + 10 * y) ++wrong[t];
      }
    });
  }
  for (auto& th : threads) th.join();
  for (int t = 0; t < 4; ++t) EXPECT_EQ(wrong[t], 0) << "thread " << t;
}

TEST(SizingExpression, SyntaxErrorNamesThePosition) {
  const std::string msg = message_of([] { expression_sizing("0.01 + * x"); });
  EXPECT_NE(msg.find("\"0.01 + * x\""), std::string::npos) << msg;
  EXPECT_NE(msg.find("position 7"), std::string::npos) << msg;
  EXPECT_NE(msg.find("x and y"), std::string::npos) << msg;
  EXPECT_THROW(expression_sizing("sin(x"), InvalidInput);
  EXPECT_THROW(expression_sizing(""), InvalidInput);
}

TEST(SizingExpression, UnknownVariableFailsAtConstruction) {
  const std::string msg = message_of([] { expression_sizing("0.01 + 0.1*z"); });
  EXPECT_NE(msg.find("\"z\""), std::string::npos) << msg;
  EXPECT_NE(msg.find("position 11"), std::string::npos) << msg;
  EXPECT_NE(msg.find("variables x and y"), std::string::npos) << msg;
}

TEST(SizingGrid, BilinearInsideAndClampedOutside) {
  TempDir dir;
  const std::string path = dir.file("r.txt");
  write(path,
        "# a 3 x 2 grid over [0, 2] x [0, 1]\n"
        "3 2  0 0  2 1\n"
        "\n"
        "0.01 0.02 0.03\n"
        "0.03 0.04 0.05  # row 1, at y = 1\n");
  const Sizing s = grid_sizing(path);
  // Nodes.
  EXPECT_NEAR(s({0, 0}), 0.01, 1e-15);
  EXPECT_NEAR(s({1, 1}), 0.04, 1e-15);
  EXPECT_NEAR(s({2, 1}), 0.05, 1e-15);
  // Cell centers: the mean of the four corners.
  EXPECT_NEAR(s({0.5, 0.5}), 0.025, 1e-15);
  EXPECT_NEAR(s({1.5, 0.5}), 0.035, 1e-15);
  // Bilinear, not just linear along an edge.
  EXPECT_NEAR(s({0.25, 0.75}), 0.25 * 0.75 * 0.04 + 0.75 * 0.75 * 0.03 + 0.25 * 0.25 * 0.02 +
                                   0.75 * 0.25 * 0.01,
              1e-15);
  // Clamped to the nearest edge or corner.
  EXPECT_NEAR(s({-5, -5}), 0.01, 1e-15);
  EXPECT_NEAR(s({10, 10}), 0.05, 1e-15);
  EXPECT_NEAR(s({0.5, 7}), 0.035, 1e-15);
  EXPECT_NEAR(s({1.5, -1}), 0.025, 1e-15);
  EXPECT_NE(s.description().find(path), std::string::npos);
}

TEST(SizingGrid, MissingFileIsAnIoError) {
  TempDir dir;
  const std::string msg = message_of<IoError>([&] { grid_sizing(dir.file("none.txt")); });
  EXPECT_NE(msg.find("none.txt"), std::string::npos) << msg;
}

TEST(SizingGrid, BadContentNamesTheLine) {
  TempDir dir;
  const std::string path = dir.file("bad.txt");
  auto message_for = [&](const std::string& text) {
    write(path, text);
    return message_of([&] { grid_sizing(path); });
  };
  std::string msg = message_for("2 2 0 0 1 1\n0.01 0.02\n0.01 -0.02\n");
  EXPECT_NE(msg.find(path + ", line 3"), std::string::npos) << msg;
  EXPECT_NE(msg.find("-0.02"), std::string::npos) << msg;
  EXPECT_NE(msg.find("not positive"), std::string::npos) << msg;

  msg = message_for("# header next\n2 2 0 0 1 1\n0.01\n0.01 0.02\n");
  EXPECT_NE(msg.find("line 3"), std::string::npos) << msg;
  EXPECT_NE(msg.find("nx = 2"), std::string::npos) << msg;

  msg = message_for("2 2 0 0 1\n");
  EXPECT_NE(msg.find("line 1"), std::string::npos) << msg;
  msg = message_for("2 2 0 0 1 1\n0.01 0.02\n");
  EXPECT_NE(msg.find("ends after 1 rows"), std::string::npos) << msg;
  msg = message_for("1 2 0 0 1 1\n0.01\n0.01\n");
  EXPECT_NE(msg.find("at least 2"), std::string::npos) << msg;
  msg = message_for("2 2 1 0 0 1\n0.01 0.02\n0.01 0.02\n");
  EXPECT_NE(msg.find("x0 < x1"), std::string::npos) << msg;
  msg = message_for("2 2 0 0 1 1\n0.01 0.02\n0.01 0.02\n0.5\n");
  EXPECT_NE(msg.find("line 4"), std::string::npos) << msg;
  msg = message_for("2 2 0 0 1 1\n0.01 abc\n0.01 0.02\n");
  EXPECT_NE(msg.find("'abc'"), std::string::npos) << msg;
}

TEST(SizingBoundary, GradesWithDistanceToTheNearestBoundary) {
  const auto domain = square_with_hole();
  const Sizing s = boundary_grading_sizing(domain, 0.005, 0.05, 0.1);
  EXPECT_NEAR(s({0, 0.5}), 0.005, 1e-15);            // on the outer boundary
  EXPECT_NEAR(s({0.4, 0.5}), 0.005, 1e-15);          // on the hole
  EXPECT_NEAR(s({0.2, 0.5}), 0.005 + 0.1 * 0.2, 1e-15);  // halfway between
  EXPECT_NEAR(s({0.1, 0.1}), 0.005 + 0.1 * 0.1, 1e-15);
  // Nearer the hole's corner (0.4, 0.4) than the outer sides.
  EXPECT_NEAR(s({0.25, 0.25}), 0.005 + 0.1 * 0.15 * std::sqrt(2.0), 1e-15);
  // Capped at r_max.
  const Sizing steep = boundary_grading_sizing(domain, 0.005, 0.05, 1);
  EXPECT_NEAR(steep({0.2, 0.5}), 0.05, 1e-15);
  EXPECT_NEAR(steep({0.02, 0.5}), 0.025, 1e-15);

  EXPECT_THROW(boundary_grading_sizing(domain, 0, 0.05, 0.1), InvalidInput);
  EXPECT_THROW(boundary_grading_sizing(domain, 0.06, 0.05, 0.1), InvalidInput);
  EXPECT_THROW(boundary_grading_sizing(domain, 0.005, 0.05, -0.1), InvalidInput);
  EXPECT_THROW(boundary_grading_sizing(nullptr, 0.005, 0.05, 0.1), InvalidInput);
}

TEST(SizingParse, DispatchesOnTheSpec) {
  EXPECT_EQ(parse_sizing("0.02", nullptr)({0.5, 0.5}), 0.02);
  EXPECT_EQ(parse_sizing(" 2e-2 ", nullptr)({0.5, 0.5}), 0.02);
  EXPECT_NEAR(parse_sizing("0.01 + 0.02*x", nullptr)({1, 0}), 0.03, 1e-15);

  TempDir dir;
  const std::string path = dir.file("grid.txt");
  write(path, "2 2 0 0 1 1\n0.01 0.03\n0.01 0.03\n");
  EXPECT_NEAR(parse_sizing(path, nullptr)({0.5, 0.5}), 0.02, 1e-15);

  const auto domain = square_with_hole();
  EXPECT_NEAR(parse_sizing("boundary:0.005,0.05,0.1", domain)({0.2, 0.5}), 0.025, 1e-15);
  EXPECT_NEAR(parse_sizing("boundary: 0.005, 0.05, 0.1", domain)({0.2, 0.5}), 0.025, 1e-15);
}

TEST(SizingParse, RefusesWhatItCannotUse) {
  std::string msg = message_of([] { parse_sizing("boundary:0.005,0.05,0.1", nullptr); });
  EXPECT_NE(msg.find("sizing \"boundary:0.005,0.05,0.1\": boundary grading needs a planar domain"),
            std::string::npos)
      << msg;
  // What to change is the domain: a front end adds its own name for it.
  try {
    parse_sizing("boundary:0.005,0.05,0.1", nullptr);
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.remedy(), InvalidInput::Remedy::domain);
  }
  const auto domain = square_with_hole();
  msg = message_of([&] { parse_sizing("boundary:0.005,0.05", domain); });
  EXPECT_NE(msg.find("boundary:RMIN,RMAX,G"), std::string::npos) << msg;
  EXPECT_THROW(parse_sizing("boundary:0.005,0.05,0.1,2", domain), InvalidInput);
  EXPECT_THROW(parse_sizing("boundary:0.05,0.005,0.1", domain), InvalidInput);
  EXPECT_THROW(parse_sizing("-0.01", nullptr), InvalidInput);
  EXPECT_THROW(parse_sizing("0", nullptr), InvalidInput);
  EXPECT_THROW(parse_sizing("  ", nullptr), InvalidInput);
  msg = message_of([] { parse_sizing("no_such_folder/grid.txt", nullptr); });
  EXPECT_NE(msg.find("no such file"), std::string::npos) << msg;
}

TEST(SizingMeasure, LinearRampOnTheUnitSquare) {
  const Sizing s = expression_sizing("0.01 + 0.1*x");
  const SizingStats st = measure_sizing(s, kUnitBox, nullptr);
  EXPECT_NEAR(st.min, 0.01, 1e-9);
  EXPECT_NEAR(st.max, 0.11, 1e-9);
  EXPECT_NEAR(st.lipschitz, 0.1, 1e-9);
}

TEST(SizingMeasure, PeriodicFrameSeesTheSeam) {
  // Not periodic: a jump of about 0.1 across the seam, over one grid step.
  const SizingStats ramp = measure_sizing(expression_sizing("0.01 + 0.1*x"), kUnitTorus, nullptr);
  EXPECT_GT(ramp.lipschitz, 10);
  EXPECT_NEAR(ramp.min, 0.01, 1e-9);
  // Periodic: only the true slope, 0.005 * 2 pi at most.
  const SizingStats wave =
      measure_sizing(expression_sizing("0.01 + 0.005*sin(2*pi*x)"), kUnitTorus, nullptr, 10000);
  EXPECT_NEAR(wave.lipschitz, 0.005 * 2 * kPi, 1e-4);
  EXPECT_LE(wave.lipschitz, 0.005 * 2 * kPi);
}

TEST(SizingMeasure, DomainSkipsTheHoleAndKeepsBoundaryExtremes) {
  const auto domain = square_with_hole();
  // Invalid inside the hole only: skipped, so no complaint.
  const Sizing holey([](Vec2 p) {
    return (p.x > 0.41 && p.x < 0.59 && p.y > 0.41 && p.y < 0.59) ? -1.0 : 0.01;
  }, "holey");
  const SizingStats flat = measure_sizing(holey, domain->frame(), domain.get(), 40000);
  EXPECT_EQ(flat.min, 0.01);
  EXPECT_EQ(flat.lipschitz, 0);
  // Distance to the boundary is 1-Lipschitz, so the grading's L is g, reached near walls.
  const Sizing graded = boundary_grading_sizing(domain, 0.005, 1, 0.1);
  const SizingStats st = measure_sizing(graded, domain->frame(), domain.get(), 40000);
  EXPECT_NEAR(st.min, 0.005, 1e-15);
  EXPECT_LE(st.lipschitz, 0.1 + 1e-12);
  EXPECT_GT(st.lipschitz, 0.099);
}

TEST(SizingMeasure, NonPositiveRadiusNamesThePoint) {
  const Sizing bad([](Vec2 p) { return p.x > 0.5 ? -1.0 : 0.01; }, "bad");
  const std::string msg = message_of([&] { measure_sizing(bad, kUnitBox, nullptr, 100); });
  EXPECT_NE(msg.find("\"bad\""), std::string::npos) << msg;
  EXPECT_NE(msg.find("r = -1 at ("), std::string::npos) << msg;
  const Sizing nan([](Vec2) { return std::nan(""); }, "nan");
  EXPECT_THROW(measure_sizing(nan, kUnitBox, nullptr, 100), InvalidInput);
  EXPECT_THROW(measure_sizing(constant_sizing(1), kUnitBox, nullptr, 2), InvalidInput);
}

TEST(SizingGradation, RefusesAtOrAboveTheLimit) {
  SizingStats st;
  st.lipschitz = 0.6;
  const std::string msg = message_of([&] { check_gradation(st); });
  EXPECT_NE(msg.find("L = 0.6 "), std::string::npos) << msg;
  EXPECT_NE(msg.find("at or above 0.5"), std::string::npos) << msg;
  EXPECT_NE(msg.find("no angle bound"), std::string::npos) << msg;
  EXPECT_NE(msg.find("make r vary more slowly"), std::string::npos) << msg;
  st.lipschitz = 0.5;
  EXPECT_THROW(check_gradation(st), InvalidInput);
  st.lipschitz = 0.3;
  EXPECT_NO_THROW(check_gradation(st));
  // A stricter caller's limit: the message gives the weak angle bound (8.85 degrees).
  const std::string strict = message_of([&] { check_gradation(st, 0.25); });
  EXPECT_NE(strict.find("8.85 degrees"), std::string::npos) << strict;
}

TEST(SizingDensity, ConstantRadiusMatchesAreaFraction) {
  const double eta = 0.7, r = 0.01;
  const auto n = count_for_density(eta, constant_sizing(r), kUnitTorus, nullptr);
  EXPECT_NEAR(static_cast<double>(n), static_cast<double>(count_for_area_fraction(eta, r, 1.0)), 1);
  const auto domain = square_with_hole();
  const auto nd = count_for_density(eta, constant_sizing(r), domain->frame(), domain.get());
  EXPECT_NEAR(static_cast<double>(nd),
              static_cast<double>(count_for_area_fraction(eta, r, domain->area())), 1);
}

TEST(SizingDensity, LinearRadiusMatchesTheClosedForm) {
  // Integral over the unit square of 4 / (pi r^2) with r = 0.01 (1 + x):
  // 4/pi * 1e4 * (1 - 1/2).
  const double eta = 0.7;
  const double exact = eta * 4 / kPi * 1e4 * 0.5;
  const Sizing s = expression_sizing("0.01 + 0.01*x");
  const auto n = count_for_density(eta, s, kUnitBox, nullptr);
  EXPECT_NEAR(static_cast<double>(n), exact, 1e-3 * exact);
  EXPECT_NEAR(density_integral(s, kUnitBox, nullptr), exact / eta, 1e-5 * exact / eta);
  // A frame that misses the domain has nothing to integrate.
  const auto domain = square_with_hole();
  EXPECT_THROW(density_integral(s, Frame{{5, 5}, {1, 1}, false}, domain.get()), InvalidInput);
}

TEST(SizingDensity, RefusesBadEtaAndAbsurdCounts) {
  const Sizing s = constant_sizing(0.01);
  EXPECT_THROW(count_for_density(0, s, kUnitBox, nullptr), InvalidInput);
  EXPECT_THROW(count_for_density(-0.5, s, kUnitBox, nullptr), InvalidInput);
  EXPECT_THROW(count_for_density(std::nan(""), s, kUnitBox, nullptr), InvalidInput);
  EXPECT_THROW(count_for_density(0.5, constant_sizing(10), kUnitBox, nullptr), InvalidInput);
  const std::string msg =
      message_of([] { count_for_density(0.7, constant_sizing(1e-6), kUnitBox, nullptr); });
  EXPECT_NE(msg.find("more than the 4e9 a packing can number"), std::string::npos) << msg;
}

}  // namespace
}  // namespace disktune
