// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>

#include "disktune/frame.h"
#include "disktune/geometry.h"

namespace disktune {
namespace {

TEST(IntersectCircles, TwoPointsAtDistanceRFromBothCenters) {
  const auto x = intersect_circles({0, 0}, 1.0, {1.2, 0.3}, 1.0);
  ASSERT_EQ(x.count, 2);
  for (const Vec2& p : x.points) {
    EXPECT_NEAR(norm(p - Vec2{0, 0}), 1.0, 1e-15);
    EXPECT_NEAR(norm(p - Vec2{1.2, 0.3}), 1.0, 1e-15);
  }
}

TEST(IntersectCircles, UnequalRadii) {
  const auto x = intersect_circles({0, 0}, 2.0, {3, 0}, 1.5);
  ASSERT_EQ(x.count, 2);
  for (const Vec2& p : x.points) {
    EXPECT_NEAR(norm(p), 2.0, 1e-14);
    EXPECT_NEAR(norm(p - Vec2{3, 0}), 1.5, 1e-14);
  }
}

TEST(IntersectCircles, TangentGivesOnePoint) {
  const auto x = intersect_circles({0, 0}, 1.0, {2, 0}, 1.0);
  ASSERT_EQ(x.count, 1);
  EXPECT_NEAR(x.points[0].x, 1.0, 1e-15);
  EXPECT_NEAR(x.points[0].y, 0.0, 1e-15);
}

TEST(IntersectCircles, NearTangentWithinRoundingGivesTheTouchingPoint) {
  // Apart by one ulp more than 2r: still one point, never NaN.
  const double d = std::nextafter(2.0, 3.0);
  const auto x = intersect_circles({0, 0}, 1.0, {d, 0}, 1.0);
  ASSERT_EQ(x.count, 1);
  EXPECT_TRUE(std::isfinite(x.points[0].x));
  EXPECT_NEAR(x.points[0].x, 1.0, 1e-15);
}

TEST(IntersectCircles, DisjointNestedAndConcentricGiveNone) {
  EXPECT_EQ(intersect_circles({0, 0}, 1.0, {2.1, 0}, 1.0).count, 0);
  EXPECT_EQ(intersect_circles({0, 0}, 3.0, {0.5, 0}, 1.0).count, 0);
  EXPECT_EQ(intersect_circles({0, 0}, 1.0, {0, 0}, 1.0).count, 0);
}

TEST(IntersectCircles, TinyAndHugeScalesKeepRelativeAccuracy) {
  for (double s : {1e-9, 1e-3, 1.0, 1e6}) {
    const auto x = intersect_circles(Vec2{0.3, 0.7} * s, s, Vec2{1.1, 1.2} * s, s);
    ASSERT_EQ(x.count, 2) << s;
    for (const Vec2& p : x.points) {
      EXPECT_NEAR(norm(p - Vec2{0.3, 0.7} * s) / s, 1.0, 1e-14);
      EXPECT_NEAR(norm(p - Vec2{1.1, 1.2} * s) / s, 1.0, 1e-14);
    }
  }
}

TEST(Frame, WrapLandsInHalfOpenBox) {
  const Frame f{{0, 0}, {2, 3}, true};
  for (double x : {-1e-17, -2.0, 2.0, 4.5, -0.5, 1.999999999999}) {
    const Vec2 w = f.wrap({x, x});
    EXPECT_GE(w.x, 0.0);
    EXPECT_LT(w.x, 2.0);
    EXPECT_GE(w.y, 0.0);
    EXPECT_LT(w.y, 3.0);
  }
  EXPECT_EQ(f.wrap({2.0, 3.0}).x, 0.0);
}

}  // namespace
}  // namespace disktune
