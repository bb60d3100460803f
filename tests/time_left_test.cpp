// SPDX-License-Identifier: GPL-3.0-or-later
// PhaseTimeLeft against reports made from a known pace (constant, or falling
// exponentially with the disks done), whose time to the goal is worked out here in closed
// form; and the phase goal tune reports, against the area fraction's count worked out
// from the radius and the box.
#include "disktune/time_left.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "disktune/planar_domain.h"
#include "disktune/sampling.h"
#include "disktune/tuning.h"

namespace disktune {
namespace {

Progress report(double done, std::size_t start, std::size_t goal,
                Phase phase = Phase::void_injection) {
  const bool down = goal < start;
  const auto count = static_cast<std::size_t>(std::llround(down ? start - done : start + done));
  return {count, 0.0, phase, goal};
}

TEST(PhaseTimeLeft, AtAConstantPaceTheTimeLeftIsWhatIsLeftOverThePace) {
  PhaseTimeLeft clock;
  // 100 disks a second from 5000 toward 6000, reported every 0.05 s for 2 s.
  for (int k = 0; k <= 40; ++k) clock.add(3 + 0.05 * k, report(5.0 * k, 5000, 6000));
  EXPECT_NEAR(clock.seconds_left(), 8.0, 0.08);
  EXPECT_NEAR(clock.phase_seconds(), 2.0, 1e-12);
  EXPECT_NEAR(clock.phase_fraction(), 0.2, 0.01);
}

TEST(PhaseTimeLeft, ALongPhaseKeepsReadingItsLatestReports) {
  // 200,000 reports over 200 s at 50 disks a second, then 10 s at 20 (the window, 30 %
  // of the phase, sees both paces): the fit's old reports are dropped on the way.
  PhaseTimeLeft clock;
  double t = 0, done = 0;
  for (int k = 0; k < 200000; ++k, t += 0.001, done += 0.05)
    clock.add(t, report(done, 1000, 30000));
  EXPECT_NEAR(clock.phase_seconds(), 199.999, 1e-6);
  EXPECT_NEAR(clock.seconds_left(), (29000 - done + 0.05) / 50, 0.02 * (29000 - done) / 50);
  for (int k = 0; k < 10000; ++k, t += 0.001, done += 0.02) clock.add(t, report(done, 1000, 30000));
  // Pace 20 now, and falling as the fit sees it: more than the left over 20 a second.
  EXPECT_GT(clock.seconds_left(), (29000 - done) / 20);
}

TEST(PhaseTimeLeft, APaceThatFallsWithTheDisksDoneIsFollowed) {
  // pace(x) = r0 e^(-k x): x(t) = ln(1 + k r0 t) / k, the goal G at (e^(k G) - 1) / (k r0).
  const double r0 = 1000, k = 0.002, G = 1500;
  const double t_goal = std::expm1(k * G) / (k * r0);  // 9.54 s
  for (const bool down : {false, true}) {
    PhaseTimeLeft clock;
    const std::size_t start = down ? 9000 : 2000, goal = down ? 7500 : 3500;
    for (double t = 0; t <= 4 + 1e-9; t += 0.01)
      clock.add(t, report(std::log1p(k * r0 * t) / k, start, goal));
    const double left = t_goal - 4;
    EXPECT_NEAR(clock.seconds_left(), left, 0.05 * left) << (down ? "down" : "up");
    EXPECT_NEAR(clock.phase_fraction(), 4 / t_goal, 0.03);
    // A constant pace (the last second's) would say much less.
    const double recent = (std::log1p(k * r0 * 4) - std::log1p(k * r0 * 3)) / k;
    EXPECT_GT(clock.seconds_left(), 1.5 * (G - std::log1p(k * r0 * 4) / k) / recent);
  }
}

TEST(PhaseTimeLeft, ANewPhaseStartsANewFit) {
  PhaseTimeLeft clock;
  for (int k = 0; k <= 40; ++k) clock.add(0.05 * k, report(5.0 * k, 5000, 6000));
  clock.add(2.05, report(0, 5200, 5600, Phase::repeller_injection));
  EXPECT_EQ(clock.phase(), Phase::repeller_injection);
  EXPECT_TRUE(std::isnan(clock.seconds_left()));  // one report: too few to tell
  EXPECT_TRUE(std::isnan(clock.phase_fraction()));
  EXPECT_EQ(clock.phase_seconds(), 0);
  for (int k = 1; k <= 20; ++k)
    clock.add(2.05 + 0.1 * k, report(2.0 * k, 5200, 5600, Phase::repeller_injection));
  EXPECT_NEAR(clock.seconds_left(), 360 / 20.0, 0.2);  // 20 disks a second, 360 left
}

TEST(PhaseTimeLeft, AStalledCountNeverGetsThereAnUnmovedOneIsNotKnownAReachedGoalHasNothingLeft) {
  PhaseTimeLeft stalled;
  for (int k = 0; k <= 40; ++k) stalled.add(0.05 * k, report(k < 10 ? k : 10, 5000, 6000));
  EXPECT_TRUE(std::isinf(stalled.seconds_left()));
  EXPECT_EQ(stalled.phase_fraction(), 0);
  // A count that has not moved since the phase began is no stall (a squeeze stage under
  // way adds its disks at its end): not known yet.
  PhaseTimeLeft not_yet;
  for (int k = 0; k <= 40; ++k)
    not_yet.add(0.05 * k, report(0, 5000, 6000, Phase::squeeze_injection));
  EXPECT_TRUE(std::isnan(not_yet.seconds_left()));
  PhaseTimeLeft reached;
  for (int k = 0; k <= 10; ++k) reached.add(0.1 * k, report(10.0 * k, 5000, 5100));
  EXPECT_EQ(reached.seconds_left(), 0);
  EXPECT_EQ(reached.phase_fraction(), 1);
}

TEST(PhaseTimeLeft, TuneReportsWhereEachPhaseHandsOver) {
  const double r = 0.02;
  // The count at area fraction 1: the unit square's area over a disk of radius r/2.
  const double unit = 1.0 / (M_PI * r * r / 4);
  const auto count_at = [&](double eta) { return static_cast<std::size_t>(std::ceil(eta * unit)); };
  const auto goals = [](const std::vector<Progress>& seen, Phase phase) {
    std::vector<std::size_t> out;
    for (const Progress& s : seen)
      if (s.phase == phase) out.push_back(s.phase_goal);
    return out;
  };
  std::vector<Progress> seen;
  TuneOptions options;
  options.on_progress = [&](const Progress& progress) { return seen.push_back(progress), true; };
  {  // The periodic box: squeeze injection to squeeze_until (0.82), then the grains.
    const PeriodicBox box(1, 1);
    Rng rng(7);
    Packing p = sample_mps(box, r, rng);
    const std::size_t target = count_at(0.83);
    ASSERT_TRUE(tune(p, box, Target::count(target), rng, options).reached);
    const auto squeeze = goals(seen, Phase::squeeze_injection),
               grains = goals(seen, Phase::grain_injection);
    ASSERT_FALSE(squeeze.empty());
    ASSERT_FALSE(grains.empty());
    for (const std::size_t g : squeeze) EXPECT_EQ(g, count_at(options.squeeze_until));
    for (const std::size_t g : grains) EXPECT_EQ(g, target);
  }
  seen.clear();
  {  // A planar domain: void injection to void_until (0.70), then the repeller.
    const auto square =
        std::make_shared<const PlanarDomain>(std::vector<Vec2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}});
    Rng rng(7);
    Packing p = sample_mps(square, r, rng);
    const std::size_t target = target_count(Target::area_fraction(0.77), p, 1.0);
    ASSERT_TRUE(tune(p, *square, Target::count(target), rng, options).reached);
    const auto voids = goals(seen, Phase::void_injection),
               repeller = goals(seen, Phase::repeller_injection);
    ASSERT_FALSE(voids.empty());
    ASSERT_FALSE(repeller.empty());
    for (const std::size_t g : voids) EXPECT_EQ(g, std::min(target, count_at(options.void_until)));
    for (const std::size_t g : repeller)
      EXPECT_EQ(g, target);  // before its own repeller_until, 0.78
  }
}

}  // namespace
}  // namespace disktune
