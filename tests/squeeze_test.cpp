// SPDX-License-Identifier: GPL-3.0-or-later
// Squeeze injection, checked by the independent oracle after every stage: conflict-free
// and maximal, the exact count, in square and oblong boxes, and only in the periodic box.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "disktune/density.h"
#include "disktune/errors.h"
#include "disktune/planar_domain.h"
#include "disktune/sampling.h"
#include "disktune/threads.h"
#include "disktune/tuning.h"
#include "test_util.h"

namespace disktune {
namespace {

::testing::AssertionResult valid(const PeriodicBox& box, const Packing& p, std::uint64_t seed) {
  const auto rep =
      oracle::check_all(test::box_of(box), p.max_radius(), test::centers_of(p), 1e-6, 3000, seed);
  if (rep.conflict_free() && rep.maximal()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << rep.summary();
}

// Stages of every size, from one disk to the whole way to eta 0.80 at once, each checked
// by the oracle; the count is exactly what was asked after each call.
TEST(Squeeze, EveryStageLeavesAValidPackingWithTheCountAsked) {
  const struct { double w, h, r; } boxes[] = {{1, 1, 0.03}, {1.3, 0.7, 0.025}, {0.4, 0.4, 0.05}};
  for (const auto& [w, h, r] : boxes) {
    for (const std::uint64_t seed : {1, 2, 3}) {
      SCOPED_TRACE("box " + std::to_string(w) + " x " + std::to_string(h) + " seed " +
                   std::to_string(seed));
      const PeriodicBox box(w, h);
      Rng rng(seed);
      Packing p = sample_mps(box, r, rng);
      const std::size_t goal = count_for_area_fraction(0.80, r, box.area());
      std::size_t stages = 0;
      const auto check = [&] {
        ++stages;
        ASSERT_TRUE(valid(box, p, seed * 1000 + stages));
      };
      const std::size_t start = p.size();
      for (const std::size_t step : {std::size_t{1}, std::size_t{7}, goal}) {
        const std::size_t before = p.size(), ask = std::min(step, goal - before);
        const std::size_t added = squeeze_inject(p, rng, ask, check);
        ASSERT_EQ(added, ask);
        ASSERT_EQ(p.size(), before + ask);
        ASSERT_TRUE(valid(box, p, seed));
      }
      EXPECT_EQ(p.size(), goal);
      EXPECT_GT(goal, start);
      EXPECT_GE(stages, 3u);
    }
  }
}

// From a sparse packing (ejected to eta 0.35, every disk alone covering part of the box),
// the pushes open voids that the stage must refill: each stage checked by the oracle. The
// refill can pass a small count asked (then the stage is tried smaller, down to none).
TEST(Squeeze, VoidsThePushesOpenAreRefilled) {
  const PeriodicBox box;
  for (const std::uint64_t seed : {1, 2, 3, 4}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    Rng rng(seed);
    Packing p = sample_mps(box, 0.04, rng);
    ASSERT_TRUE(tune(p, box, Target::area_fraction(0.35), rng).reached);
    std::size_t stages = 0, total = 0;
    for (const std::size_t step :
         {std::size_t{1}, std::size_t{2}, std::size_t{5}, std::size_t{20}, std::size_t{60}}) {
      const std::size_t before = p.size();
      const std::size_t added =
          squeeze_inject(p, rng, step, [&] { ASSERT_TRUE(valid(box, p, seed * 100 + ++stages)); });
      ASSERT_LE(added, step);
      ASSERT_EQ(p.size(), before + added);
      total += added;
    }
    EXPECT_GT(stages, 0u);
    EXPECT_GT(total, 0u);
    EXPECT_TRUE(valid(box, p, seed));
    std::printf("[figures] squeeze from eta 0.35: seed %d, %zu stages, %zu disks added\n",
                static_cast<int>(seed), stages, total);
  }
}

// The automatic schedule in the box: squeeze injection to the target, or to
// squeeze_until and then the grains, every target reached exactly and valid.
TEST(Squeeze, TheAutomaticScheduleSqueezesThenGrowsGrains) {
  const PeriodicBox box;
  for (const double eta : {0.60, 0.75, 0.81, 0.83}) {
    SCOPED_TRACE("eta " + std::to_string(eta));
    Rng rng(5);
    Packing p = sample_mps(box, 0.02, rng);
    std::vector<Phase> seen;
    TuneOptions o;
    o.on_progress = [&](const Progress& pr) {
      if (seen.empty() || seen.back() != pr.phase) seen.push_back(pr.phase);
      return true;
    };
    const TuneResult res = tune(p, box, Target::area_fraction(eta), rng, o);
    ASSERT_TRUE(res.reached);
    EXPECT_TRUE(valid(box, p, 7));
    ASSERT_FALSE(seen.empty());
    EXPECT_EQ(seen.front(), Phase::squeeze_injection);
    EXPECT_EQ(std::count(seen.begin(), seen.end(), Phase::void_injection), 0);
    const bool grains = std::find(seen.begin(), seen.end(), Phase::grain_injection) != seen.end();
    EXPECT_EQ(grains, eta > o.squeeze_until);
  }
}

// A box too narrow for the pushes' cells adds nothing (the phases after it go on); a
// planar domain or a sizing is refused with a message naming what to use instead.
// A stage of many disks first relaxes them as soft disks, every disk at once, strip by
// strip on every core: one, two and three threads give the same packing bit for bit
// (the unit box at r = 0.01 in 40 strips of cells; a box of 3 x 4 cells, in 2 strips).
TEST(Squeeze, SamePackingOnAnyNumberOfThreads) {
  const struct { double w, h, r, eta; } boxes[] = {{1, 1, 0.01, 0.80}, {0.037, 0.049, 0.01, 0.75}};
  for (const auto& b : boxes) {  // not a structured binding: the lambda captures it
    const PeriodicBox box(b.w, b.h);
    auto run = [&](unsigned threads) {
      set_default_threads(threads);
      Rng rng(5);
      Packing p = sample_mps(box, b.r, rng);
      const std::size_t ask = count_for_area_fraction(b.eta, b.r, box.area()) - p.size();
      EXPECT_EQ(squeeze_inject(p, rng, ask), ask);
      set_default_threads(0);
      return test::centers_of(p);
    };
    const auto one = run(1);
    EXPECT_EQ(run(2), one);
    EXPECT_EQ(run(3), one);
  }
}

// Past what can be packed (eta 0.92 is above the hexagonal lattice's 0.9069) the stages
// jam: each gives up within its budget and is taken back, and the call returns what it
// did add, with the packing valid (seeds 1-3, oracle).
TEST(Squeeze, PastJammingItAddsWhatFitsAndStaysValid) {
  const PeriodicBox box(0.5, 0.5);
  for (const std::uint64_t seed : {1, 2, 3}) {
    Rng rng(seed);
    Packing p = sample_mps(box, 0.05, rng);
    const std::size_t before = p.size();
    const std::size_t ask = count_for_area_fraction(0.92, 0.05, box.area()) - before;
    const std::size_t added = squeeze_inject(p, rng, ask);
    EXPECT_LT(added, ask);
    EXPECT_EQ(p.size(), before + added);
    EXPECT_TRUE(valid(box, p, seed));
  }
}

// A stage's moves take seconds at 10^6 disks: `poll` is called while they are worked out,
// the packing still as the call got it, and what it throws ends the call with the packing
// so. tune reports progress there: its callback returning false cancels mid-stage.
TEST(Squeeze, PollsWhileAStageRunsAndStopsWhereItThrows) {
  const PeriodicBox box(1, 1);
  struct Stop {};
  for (const int stop_at : {1, 3}) {
    Rng rng(2);
    Packing p = sample_mps(box, 0.01, rng);
    const auto given = test::centers_of(p);
    const std::size_t ask = count_for_area_fraction(0.80, 0.01, box.area()) - p.size();
    int polls = 0;
    EXPECT_THROW(squeeze_inject(p, rng, ask, {},
                                [&] {
                                  EXPECT_EQ(test::centers_of(p), given);
                                  if (++polls == stop_at) throw Stop{};
                                }),
                 Stop);
    EXPECT_EQ(polls, stop_at);
    EXPECT_EQ(test::centers_of(p), given);
    // Not stopped, it polls on and adds all, valid.
    polls = 0;
    EXPECT_EQ(squeeze_inject(p, rng, ask, {}, [&] { ++polls; }), ask);
    EXPECT_GE(polls, 4);
    EXPECT_TRUE(valid(box, p, 2));
  }
  Rng rng(4);
  Packing p = sample_mps(box, 0.01, rng);
  const auto given = test::centers_of(p);
  const std::size_t start = p.size();
  TuneOptions o;
  int mid_stage = 0;
  o.on_progress = [&](const Progress& progress) {
    mid_stage += progress.phase == Phase::squeeze_injection && progress.count == start;
    return mid_stage < 2;
  };
  EXPECT_THROW(tune(p, box, Target::area_fraction(0.80), rng, o), Cancelled);
  EXPECT_EQ(mid_stage, 2);
  EXPECT_EQ(test::centers_of(p), given);
}

TEST(Squeeze, OnlyInAPeriodicBoxWithOneRadius) {
  {
    const PeriodicBox box(0.1, 1);
    Rng rng(1);
    Packing p = sample_mps(box, 0.04, rng);
    const std::size_t before = p.size();
    EXPECT_EQ(squeeze_inject(p, rng, 3), 0u);
    EXPECT_EQ(p.size(), before);
  }
  const auto domain =
      std::make_shared<const PlanarDomain>(std::vector<Vec2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  Rng rng(1);
  Packing planar = sample_mps(domain, 0.05, rng);
  try {
    squeeze_inject(planar, rng, 5);
    FAIL() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("void or repeller"), std::string::npos) << e.what();
  }
  TuneOptions o;
  o.method = Method::squeeze_injection;
  EXPECT_THROW(tune(planar, *domain, Target::area_fraction(0.7), rng, o), InvalidInput);
}

}  // namespace
}  // namespace disktune
