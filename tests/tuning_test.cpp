// SPDX-License-Identifier: GPL-3.0-or-later
// Injection operations and the scheduler, checked by the independent oracle after
// every single operation.
#include "disktune/tuning.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "../src/tuning/phase_loop.h"
#include "../src/tuning/undo_log.h"
#include "../src/tuning/void_repair.h"
#include "disktune/density.h"
#include "disktune/errors.h"
#include "disktune/mesh.h"
#include "disktune/planar_domain.h"
#include "disktune/sampling.h"
#include "test_util.h"

namespace disktune {
namespace {

::testing::AssertionResult valid(const PeriodicBox& box, const Packing& p, std::uint64_t seed) {
  const double r = p.max_radius();
  const auto rep = oracle::check_all(test::box_of(box), r, test::centers_of(p), 1e-6, 3000, seed);
  if (rep.conflict_free() && rep.maximal()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << rep.summary();
}

using Op = std::size_t (*)(Packing&, DiskId, Rng&, std::size_t);

// Runs an operation on random disks, checking the packing with the oracle after every
// single call. `sign` is +1 for injection (the count grows by the return value), -1 for
// ejection (it shrinks by it).
void run_each_op_checked(Op op, const char* name, int sign = +1) {
  const std::tuple<double, double, double> cases[] = {
      {1.0, 1.0, 0.08}, {1.0, 1.0, 0.05}, {2.0, 0.6, 0.07}, {0.5, 0.5, 0.2}};
  for (const auto& [w, h, r] : cases) {
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
      const PeriodicBox box(w, h);
      Rng rng(seed);
      Packing p = sample_mps(box, r, rng);
      std::size_t count = p.size(), added_total = 0;
      for (int step = 0; step < 120; ++step) {
        const std::vector<DiskId> ids = p.ids();
        const DiskId id = ids[uniform_index(rng, ids.size())];
        const std::size_t added = op(p, id, rng, 1000);
        ASSERT_EQ(static_cast<long>(p.size()), static_cast<long>(count) + sign * static_cast<long>(added)) << name;
        count = p.size();
        added_total += added;
        ASSERT_TRUE(valid(box, p, seed * 1000 + step))
            << name << " " << w << "x" << h << " r=" << r << " seed=" << seed << " step=" << step;
      }
      if (count > 10) {  // a handful of disks may leave nothing to do
        EXPECT_GT(added_total, 0u) << name << " never changed the count: " << w << "x" << h << " r=" << r;
      }
    }
  }
}

TEST(Injection, VoidInjectionKeepsTheInvariantsAfterEveryOperation) {
  run_each_op_checked(&void_inject, "void");
}

TEST(Injection, RepellerInjectionKeepsTheInvariantsAfterEveryOperation) {
  run_each_op_checked(&repeller_inject, "repeller");
}

TEST(Ejection, SiftingKeepsTheInvariantsAfterEveryOperation) {
  run_each_op_checked(&sift_eject, "sift", -1);
}

TEST(Ejection, AttractorEjectionKeepsTheInvariantsAfterEveryOperation) {
  run_each_op_checked(&attractor_eject, "attractor", -1);
}

TEST(Ejection, WideAttractorEjectionKeepsTheInvariantsAfterEveryOperation) {
  run_each_op_checked(&wide_attractor_eject, "wide attractor", -1);
}

TEST(Ejection, HitsExactCountsWithFallingCountsAndValidStates) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const PeriodicBox box(1.0, 0.8);
    Rng rng(seed);
    const Packing mps = sample_mps(box, 0.05, rng);
    for (const Method m : {Method::automatic, Method::sift_ejection, Method::attractor_ejection,
                           Method::crystal_ejection}) {
      for (const std::size_t fewer : {1u, 9u, 35u}) {
        Packing p = mps;
        std::size_t last = p.size();
        int checked = 0;
        TuneOptions opt;
        opt.method = m;
        opt.after_operation = [&](const Packing& q) {
          ASSERT_LE(q.size(), last);
          last = q.size();
          if (++checked % 7 == 0) {
            ASSERT_TRUE(valid(box, q, checked));
          }
        };
        const TuneResult res = tune(p, box, Target::count(mps.size() - fewer), rng, opt);
        EXPECT_TRUE(res.reached) << "seed " << seed << " -" << fewer << " method " << static_cast<int>(m);
        EXPECT_EQ(p.size(), mps.size() - fewer);
        EXPECT_TRUE(valid(box, p, seed));
      }
    }
  }
}

TEST(Ejection, CrystalEjectionNeverGrowsAndKeepsTheInvariantsAtEveryNinthStep) {
  for (const auto& [w, h, r] : {std::tuple{1.0, 1.0, 0.04}, {1.5, 0.7, 0.05}}) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      const PeriodicBox box(w, h);
      Rng rng(seed);
      Packing p = sample_mps(box, r, rng);
      const std::size_t start = p.size();
      std::size_t last = start;
      int steps = 0;
      const std::size_t removed = crystal_eject(p, rng, 100000, [&] {
        ASSERT_LE(p.size(), last);
        last = p.size();
        if (++steps % 9 == 0) {
          // box.width(): C++17 lambdas cannot capture structured bindings (clang).
          ASSERT_TRUE(valid(box, p, steps))
              << box.width() << "x" << box.height() << " seed " << seed;
        }
      });
      EXPECT_EQ(p.size(), start - removed);
      EXPECT_GT(removed, start / 5) << w << "x" << h << " seed " << seed;
      ASSERT_TRUE(valid(box, p, seed));
    }
  }
}

TEST(Ejection, PhasesAloneReachTheirPlateaus) {
  const PeriodicBox box;
  Rng rng(3);
  const Packing mps = sample_mps(box, 0.03, rng);
  for (const auto& [m, eta_max] : {std::pair{Method::sift_ejection, 0.46}, {Method::attractor_ejection, 0.37},
                                   {Method::crystal_ejection, 0.40}}) {
    Packing p = mps;
    TuneOptions opt;
    opt.method = m;
    const TuneResult res = tune(p, box, Target::area_fraction(0.31), rng, opt);
    EXPECT_FALSE(res.reached);
    EXPECT_LT(area_fraction(p.size(), 0.03, box.area()), eta_max) << static_cast<int>(m);
    EXPECT_TRUE(valid(box, p, 3));
  }
}

TEST(Injection, CrystalGrowthNeverShrinksKeepsTheInvariantsAtEverySeventhStepAndGrowsOneCrystal) {
  // Box, radius, and the area fraction the crystal must pass: a few disks in a small
  // box are mostly seam (the lattice does not fit the period), so less is expected.
  const std::tuple<double, double, double, double> cases[] = {
      {1.0, 1.0, 0.06, 0.82}, {1.5, 0.7, 0.05, 0.82}, {0.6, 0.6, 0.15, 0.65}};
  for (const auto& [w, h, r, eta_min] : cases) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      const PeriodicBox box(w, h);
      Rng rng(seed);
      Packing p = sample_mps(box, r, rng);
      const std::size_t start = p.size();
      std::size_t last = start;
      int steps = 0;
      const std::size_t added = crystal_inject(p, rng, 100000, [&] {
        ASSERT_GE(p.size(), last);
        last = p.size();
        if (++steps % 7 == 0) {
          ASSERT_TRUE(valid(box, p, steps))
              << box.width() << "x" << box.height() << " r=" << p.max_radius() << " seed " << seed;
        }
      });
      EXPECT_EQ(p.size(), start + added);
      ASSERT_TRUE(valid(box, p, seed));
      std::size_t frozen = 0;
      for (DiskId id : p.ids()) frozen += (p.flags(id) & kFrozen) != 0;
      EXPECT_GT(frozen, p.size() * 3 / 4) << "the crystal did not spread";
      EXPECT_GT(area_fraction(p.size(), r, box.area()), eta_min) << w << "x" << h << " r=" << r;
    }
  }
}

// Obtuse triangles of the periodic Delaunay triangulation, as a fraction.
double obtuse_fraction(const Packing& p) {
  const TriangleMesh mesh = periodic_delaunay(p);
  std::size_t obtuse = 0;
  for (const auto& t : mesh.triangles) {
    const Vec2 a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
    obtuse += dot(b - a, c - a) < 0 || dot(a - b, c - b) < 0 || dot(a - c, b - c) < 0;
  }
  return static_cast<double>(obtuse) / static_cast<double>(mesh.triangles.size());
}

TEST(Injection, AngleInjectionKeepsTheInvariantsAndRemovesObtuseTriangles) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const PeriodicBox box(1.0, 0.9);
    Rng rng(seed);
    Packing p = sample_mps(box, 0.03, rng);
    const double before = obtuse_fraction(p);
    std::size_t last = p.size();
    int steps = 0;
    TuneOptions opt;
    opt.method = Method::angle_injection;
    opt.after_operation = [&](const Packing& q) {
      ASSERT_GE(q.size(), last);
      last = q.size();
      if (++steps % 10 == 0) {
        ASSERT_TRUE(valid(box, q, steps)) << "seed " << seed << " step " << steps;
      }
    };
    tune(p, box, Target::area_fraction(0.9), rng, opt);  // to stagnation
    ASSERT_TRUE(valid(box, p, seed));
    // Fig. 5 of the paper: "significantly reduced, but some remain" (measured: ~5x).
    EXPECT_LT(obtuse_fraction(p), 0.4 * before) << "seed " << seed << ": from " << before;
  }
}

TEST(Injection, MaxAddedIsNeverExceededAndARefusedOperationChangesNothing) {
  const PeriodicBox box;
  Rng rng(9);
  Packing p = sample_mps(box, 0.06, rng);
  for (int step = 0; step < 300; ++step) {
    const auto before = test::centers_of(p);
    const std::vector<DiskId> ids = p.ids();
    const std::size_t added = repeller_inject(p, ids[uniform_index(rng, ids.size())], rng, 0);
    ASSERT_EQ(added, 0u);
    ASSERT_EQ(p.size(), before.size());
  }
  EXPECT_TRUE(valid(box, p, 5));
}

TEST(Injection, FixedAndFrozenDisksNeverMove) {
  const PeriodicBox box;
  Rng rng(4);
  Packing p = sample_mps(box, 0.07, rng);
  std::vector<std::pair<DiskId, Vec2>> pinned;
  for (DiskId id : p.ids()) {
    if (id % 3 == 0) {
      p.set_flags(id, id % 2 ? kFixed : kFrozen);
      pinned.push_back({id, p.center(id)});
    }
  }
  for (int step = 0; step < 300; ++step) {
    const std::vector<DiskId> ids = p.ids();
    repeller_inject(p, ids[uniform_index(rng, ids.size())], rng, 1000);
  }
  for (const auto& [id, c] : pinned) {
    ASSERT_TRUE(p.alive(id));
    EXPECT_EQ(p.center(id), c);
  }
  EXPECT_TRUE(valid(box, p, 6));
}

TEST(Tune, HitsExactCountsWithMonotoneCountsAndValidStates) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const PeriodicBox box(1.0, 0.8);
    Rng rng(seed);
    const Packing mps = sample_mps(box, 0.05, rng);
    for (const std::size_t extra : {1u, 7u, 40u}) {
      Packing p = mps;
      std::size_t last = p.size();
      int checked = 0;
      TuneOptions opt;
      opt.after_operation = [&](const Packing& q) {
        ASSERT_GE(q.size(), last);
        last = q.size();
        if (++checked % 5 == 0) {
          ASSERT_TRUE(valid(box, q, checked));
        }
      };
      const TuneResult res = tune(p, box, Target::count(mps.size() + extra), rng, opt);
      EXPECT_TRUE(res.reached) << "seed " << seed << " +" << extra;
      EXPECT_EQ(p.size(), mps.size() + extra);
      EXPECT_TRUE(valid(box, p, seed));
    }
  }
}

TEST(Tune, CrystalPhaseHitsExactCounts) {
  const PeriodicBox box;
  Rng rng(12);
  const Packing mps = sample_mps(box, 0.03, rng);
  for (const double eta : {0.6, 0.75, 0.83, 0.86}) {
    Packing p = mps;
    TuneOptions opt;
    opt.method = Method::crystal_injection;
    const TuneResult res = tune(p, box, Target::area_fraction(eta), rng, opt);
    EXPECT_TRUE(res.reached) << eta;
    EXPECT_EQ(p.size(), count_for_area_fraction(eta, 0.03, 1.0));
    EXPECT_TRUE(valid(box, p, 4));
  }
}

// Grain injection from many nuclei (a grain per 40 disks here, so that a small packing
// gets a dozen): the oracle after every step it keeps, the count never past the target,
// and the automatic schedule and the method alone hit exact counts past where the grains
// stall (one crystal then grows through them).
TEST(Tune, GrainInjectionKeepsEveryStepValid) {
  const PeriodicBox box;
  for (const std::uint64_t seed : {1, 2, 3}) {
    Rng rng(seed);
    Packing p = sample_mps(box, 0.03, rng);
    const std::size_t start = p.size(), room = count_for_area_fraction(0.85, 0.03, 1.0) - start;
    std::size_t steps = 0, last = start;
    const std::size_t added = grain_inject(
        p, rng, room,
        [&] {
          ++steps;
          ASSERT_GE(p.size(), last);
          last = p.size();
          ASSERT_TRUE(valid(box, p, seed * 1000 + steps));
        },
        40);
    EXPECT_GT(steps, 10u) << "seed " << seed;
    EXPECT_EQ(p.size(), start + added);
    EXPECT_LE(added, room);
    EXPECT_TRUE(valid(box, p, seed));
  }
}

// The automatic schedule's injection phases by target: the random phases, then grains,
// below TuneOptions::grains_from_sample; grains from the start at and past it.
TEST(Tune, TargetsPastGrainsFromSampleStartWithGrains) {
  const auto phases = [](double eta, double from) {
    TuneOptions o;
    o.grains_from_sample = from;
    std::vector<Phase> out;
    for (const auto& plan : detail::plan_for<Packing>(o, false, true, &angle_inject, false, eta))
      out.push_back(plan.phase);
    return out;
  };
  const std::vector<Phase> random_first = {Phase::void_injection, Phase::repeller_injection,
                                           Phase::grain_injection, Phase::crystal_injection,
                                           Phase::repeller_injection};
  const std::vector<Phase> grains_first = {Phase::grain_injection, Phase::crystal_injection,
                                           Phase::repeller_injection};
  EXPECT_EQ(phases(0.80, 0.84), random_first);
  EXPECT_EQ(phases(0.8399, 0.84), random_first);
  EXPECT_EQ(phases(0.84, 0.84), grains_first);
  EXPECT_EQ(phases(0.89, 0.84), grains_first);
  EXPECT_EQ(phases(0.89, 2.0), random_first);
  // Watched in a run: no void or repeller injection before the grains.
  const PeriodicBox box;
  Rng rng(3);
  Packing p = sample_mps(box, 0.02, rng);
  std::vector<Phase> seen;
  TuneOptions opt;
  opt.on_progress = [&](const Progress& pr) {
    if (seen.empty() || seen.back() != pr.phase) seen.push_back(pr.phase);
    return true;
  };
  ASSERT_TRUE(tune(p, box, Target::area_fraction(0.85), rng, opt).reached);
  ASSERT_FALSE(seen.empty());
  EXPECT_EQ(seen.front(), Phase::grain_injection);
  EXPECT_EQ(std::count(seen.begin(), seen.end(), Phase::void_injection), 0);
  EXPECT_TRUE(valid(box, p, 3));
}

TEST(Tune, GrainPhasesHitExactCounts) {
  const PeriodicBox box;
  Rng rng(12);
  const Packing mps = sample_mps(box, 0.02, rng);
  for (const Method method : {Method::automatic, Method::grain_injection}) {
    for (const double eta : {0.82, 0.85, 0.88}) {
      Packing p = mps;
      TuneOptions opt;
      opt.method = method;
      const TuneResult res = tune(p, box, Target::area_fraction(eta), rng, opt);
      EXPECT_TRUE(res.reached) << eta;
      EXPECT_EQ(p.size(), count_for_area_fraction(eta, 0.02, 1.0));
      EXPECT_TRUE(valid(box, p, 5));
    }
  }
}

// The last crystal step can need more disks to refill its voids than the target
// allows; it must then be taken back whole, not left with the voids half filled (seeds 3
// and 17 left a hole before; found by the planar oracle).
TEST(Tune, CrystalStepsThatWouldOvershootAreTakenBackWhole) {
  const PeriodicBox box;
  for (const std::uint64_t seed : {3, 17, 21, 22, 23, 24}) {
    Rng rng(seed);
    Packing p = sample_mps(box, 0.03, rng);
    TuneOptions opt;
    opt.method = Method::crystal_injection;
    const TuneResult res = tune(p, box, Target::area_fraction(0.85), rng, opt);
    EXPECT_TRUE(res.reached) << "seed " << seed;
    EXPECT_TRUE(valid(box, p, seed)) << "seed " << seed;
  }
}

TEST(Tune, EachPhaseAloneReachesItsPlateauAndStops) {
  const PeriodicBox box;
  Rng rng(2);
  const Packing mps = sample_mps(box, 0.04, rng);
  for (const Method m : {Method::void_injection, Method::repeller_injection, Method::angle_injection}) {
    Packing p = mps;
    TuneOptions opt;
    opt.method = m;
    const TuneResult res = tune(p, box, Target::area_fraction(0.9), rng, opt);
    EXPECT_FALSE(res.reached);  // 0.9 is beyond what these phases reach
    const double eta = area_fraction(p.size(), 0.04, box.area());
    EXPECT_GT(eta, 0.70) << static_cast<int>(m);
    EXPECT_TRUE(valid(box, p, 3));
  }
}

TEST(Tune, TargetsAreValidated) {
  const double r = 0.01;
  EXPECT_EQ(target_count(Target::count(123), r, 1.0), 123u);
  EXPECT_EQ(target_count(Target::area_fraction(0.5), r, 1.0), count_for_area_fraction(0.5, r, 1.0));
  EXPECT_THROW(target_count(Target::count(0), r, 1.0), InvalidInput);
  EXPECT_THROW(target_count(Target{Target::Kind::count, 12.5}, r, 1.0), InvalidInput);
  EXPECT_THROW(target_count(Target::area_fraction(0.95), r, 1.0), InvalidInput);
  EXPECT_THROW(target_count(Target::area_fraction(-0.1), r, 1.0), InvalidInput);
  EXPECT_THROW(target_count(Target::relative_radius(1.0), r, 1.0), InvalidInput);
  EXPECT_THROW(target_count(Target::count(20000), r, 1.0), InvalidInput);  // beyond hex density
  const PeriodicBox box;
  Rng rng(1);
  Packing p = sample_mps(box, 0.05, rng);
  TuneOptions inject;
  inject.method = Method::void_injection;
  EXPECT_THROW(tune(p, box, Target::count(p.size() - 1), rng, inject), InvalidInput);
  TuneOptions eject;
  eject.method = Method::sift_ejection;
  EXPECT_THROW(tune(p, box, Target::count(p.size() + 1), rng, eject), InvalidInput);
}

// Every disk's center, radius and flags, sorted: the packing's state whatever the ids.
std::vector<std::tuple<double, double, double, int>> sorted_disks(const Packing& p) {
  std::vector<std::tuple<double, double, double, int>> s;
  for (DiskId id : p.ids()) s.emplace_back(p.center(id).x, p.center(id).y, p.radius(id), p.flags(id));
  std::sort(s.begin(), s.end());
  return s;
}

TEST(UndoLog, RevertRestoresTheExactPacking) {
  const PeriodicBox box;
  Rng rng(8);
  Packing p = sample_mps(box, 0.05, rng);
  auto snapshot = [&] { return sorted_disks(p); };
  const auto before = snapshot();
  detail::UndoLog log(p);
  for (int k = 0; k < 500; ++k) {
    const std::vector<DiskId> ids = p.ids();
    const DiskId id = ids[uniform_index(rng, ids.size())];
    switch (uniform_index(rng, 4)) {
      case 0: log.move(id, box.random_point(rng)); break;
      case 1: log.remove(id); break;
      case 2: log.insert(box.random_point(rng), 0.05, kFrozen); break;
      default: log.set_flags(id, kFixed); break;
    }
  }
  log.revert();
  EXPECT_EQ(snapshot(), before);
}

// An exception in the middle of an operation: its log takes the edits back on the way out.
TEST(UndoLog, AnExceptionTakesTheEditsBack) {
  const PeriodicBox box;
  Rng rng(9);
  Packing p = sample_mps(box, 0.05, rng);
  auto snapshot = [&] { return sorted_disks(p); };
  const auto start = snapshot();
  try {
    detail::UndoLog log(p);
    for (int k = 0; k < 50; ++k) {
      const std::vector<DiskId> ids = p.ids();
      log.move(ids[uniform_index(rng, ids.size())], box.random_point(rng));
      log.remove(ids[uniform_index(rng, ids.size())]);
      log.insert(box.random_point(rng), 0.05);
    }
    throw std::runtime_error("cut short");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(snapshot(), start);
  {  // leaving normally keeps the edits
    detail::UndoLog log(p);
    log.remove(p.ids().front());
  }
  EXPECT_EQ(snapshot().size(), start.size() - 1);
}

// The repeller's choice (paper 2.2, 6.1.2): the largest |c - point| - r(c), not the
// farthest point, so a point a smaller disk reaches can win; the first of equals wins.
TEST(RepellerChoice, TheLargestWeightedDistanceWins) {
  const std::vector<double> dist{1.0, 0.75, 0.25}, radius{0.5, 0.125, 0.125};  // exact in binary
  auto choose = [&](const std::vector<double>& r) {
    return detail::farthest_weighted_index(dist.size(), [&](std::size_t i) { return dist[i]; },
                                           [&](std::size_t i) { return r[i]; });
  };
  EXPECT_EQ(choose(radius), 1u);                 // 0.625 beats 0.5
  EXPECT_EQ(choose({0.125, 0.125, 0.125}), 0u);  // one radius: the farthest
  EXPECT_EQ(choose({0.25, 0.0, 0.0}), 0u);       // 0.75 = 0.75: the first
}

}  // namespace
}  // namespace disktune

namespace disktune {
namespace {

// The names `tune --method` and the Python module take, and a clear refusal of others.
TEST(MethodNames, EveryNameAndNoOther) {
  EXPECT_EQ(method_named("auto"), Method::automatic);
  EXPECT_EQ(method_named("void"), Method::void_injection);
  EXPECT_EQ(method_named("repeller"), Method::repeller_injection);
  EXPECT_EQ(method_named("crystal"), Method::crystal_injection);
  EXPECT_EQ(method_named("grains"), Method::grain_injection);
  EXPECT_EQ(method_named("angle"), Method::angle_injection);
  EXPECT_EQ(method_named("sift"), Method::sift_ejection);
  EXPECT_EQ(method_named("attractor"), Method::attractor_ejection);
  EXPECT_EQ(method_named("crystal-eject"), Method::crystal_ejection);
  for (const char* bad : {"", "Auto", "voids", "crystal_eject"}) {
    try {
      method_named(bad);
      ADD_FAILURE() << bad << " was taken";
    } catch (const InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find("give auto, void, repeller"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace disktune

namespace disktune {
namespace {

// The repeller phases' candidates: the tenth of the free disks with the fewest
// neighbours within twice their radius, ties in the order given; counted here over all
// pairs (nearest periodic images), and in a planar domain no boundary disk among them.
TEST(SparsestFirst, PicksTheTenthWithTheFewestNeighboursByAllPairs) {
  for (const std::uint64_t seed : {1, 2, 3}) {
    const PeriodicBox box(1, 1);
    Rng rng(seed);
    Packing p = sample_mps(box, 0.03, rng);
    tune(p, box, Target::area_fraction(0.7), rng);
    std::vector<DiskId> order = p.ids();
    std::reverse(order.begin(), order.end());                   // any order: ties keep it
    std::vector<std::pair<std::size_t, std::size_t>> expected;  // neighbours, place in order
    for (std::size_t i = 0; i < order.size(); ++i) {
      std::size_t near = 0;
      for (const DiskId q : order) {
        if (q == order[i]) continue;
        Vec2 d = p.center(q) - p.center(order[i]);
        d.x -= std::round(d.x), d.y -= std::round(d.y);
        near += d.x * d.x + d.y * d.y <= 4 * 0.03 * 0.03;
      }
      expected.push_back({near, i});
    }
    std::sort(expected.begin(), expected.end());
    const std::vector<DiskId> got = detail::sparsest_first(p, order);
    ASSERT_EQ(got.size(), order.size() / 10);
    for (std::size_t k = 0; k < got.size(); ++k)
      EXPECT_EQ(got[k], order[expected[k].second]) << "seed " << seed << " k " << k;
  }
  const auto domain = std::make_shared<const PlanarDomain>(
      read_poly(std::string(DISKTUNE_DATA_DIR) + "/domains/gear.poly"));
  Rng rng(4);
  const Packing g = sample_mps(domain, 0.03, rng);
  std::size_t fixed = 0;
  for (const DiskId d : g.ids()) fixed += (g.flags(d) & kFixed) != 0;
  ASSERT_GT(fixed, g.size() / 10);  // enough boundary disks to fill the tenth, were they counted
  for (const DiskId d : detail::sparsest_first(g, g.ids())) EXPECT_FALSE(g.flags(d) & kFixed);
}

// With every disk fixed the sparse-first sweeps have nothing to try; the phase must
// still end (sweeps over all disks, which move nothing, then a stall), not spin.
TEST(SparsestFirst, ARepellerPhaseOverFixedDisksOnlyEnds) {
  const PeriodicBox box(1, 1);
  Rng rng(5);
  Packing p = sample_mps(box, 0.05, rng);
  for (const DiskId d : p.ids()) p.set_flags(d, kFixed);
  const std::size_t n = p.size();
  TuneOptions options;
  options.method = Method::repeller_injection;
  const TuneResult result = tune(p, box, Target::count(n + 10), rng, options);
  EXPECT_FALSE(result.reached);
  EXPECT_EQ(p.size(), n);
}

// Ejection goes round its phases again while a round removes disks: here the second
// phase removes one disk and lets the first remove three more, which the first can only
// do in a second round; a third round removes nothing, and the loop ends short of the goal.
int first_phase_may_remove = 0;
bool second_phase_ran = false;

TEST(EjectionRounds, GoRoundAgainWhileARoundRemovesDisks) {
  const PeriodicBox box;
  Rng rng(6);
  Packing p = sample_mps(box, 0.05, rng);
  const std::size_t n = p.size();
  first_phase_may_remove = 0;
  second_phase_ran = false;
  const detail::PhasePlan<Packing> first{
      Phase::sift_ejection,
      [](Packing& packing, DiskId d, Rng&, std::size_t) -> std::size_t {
        if (first_phase_may_remove == 0) return 0;
        --first_phase_may_remove;
        packing.remove(d);
        return 1;
      },
      nullptr, 2.0};
  const detail::PhasePlan<Packing> second{
      Phase::attractor_ejection,
      [](Packing& packing, DiskId d, Rng&, std::size_t) -> std::size_t {
        if (second_phase_ran) return 0;
        second_phase_ran = true;
        first_phase_may_remove = 3;
        packing.remove(d);
        return 1;
      },
      nullptr, 2.0};
  const TuneResult result = detail::run_phases(p, p, 1.0, n - 10, {first, second}, rng,
                                               TuneOptions{}, std::function<void(const Packing&)>{},
                                               std::chrono::steady_clock::now(), false);
  EXPECT_FALSE(result.reached);
  EXPECT_EQ(p.size(), n - 4);
  EXPECT_EQ(first_phase_may_remove, 0);
}

// A ranked sweep (PhasePlan::rank) tries every live disk once, in the order of the
// ranks as they are when each disk's turn comes: here the first try raises the rank of
// the disk ranked second above all others, and that disk then comes last.
std::vector<double> ranks_now;
std::vector<DiskId> tried_in_order;
DiskId second_ranked = kNoDisk;

TEST(RankedSweep, TriesEachDiskOnceInTheOrderOfItsRankWhenItsTurnComes) {
  const PeriodicBox box;
  Rng rng(4);
  Packing p = sample_mps(box, 0.05, rng);
  ASSERT_GT(p.size(), 100u);
  ranks_now.assign(p.id_bound(), 0);
  for (const DiskId d : p.ids()) ranks_now[d] = uniform01(rng);
  std::vector<DiskId> by_rank = p.ids();
  std::sort(by_rank.begin(), by_rank.end(),
            [](DiskId a, DiskId b) { return ranks_now[a] < ranks_now[b]; });
  second_ranked = by_rank[1];
  tried_in_order.clear();
  detail::PhasePlan<Packing> plan{
      Phase::attractor_ejection,
      [](Packing&, DiskId d, Rng&, std::size_t) -> std::size_t {
        if (tried_in_order.empty())
          ranks_now[second_ranked] = 1 + *std::max_element(ranks_now.begin(), ranks_now.end());
        tried_in_order.push_back(d);
        return 0;  // removes nothing: one sweep, then the phase has stalled
      },
      nullptr, 2.0};
  plan.rank = [](const Packing&, DiskId d) { return ranks_now[d]; };
  const TuneResult result = detail::run_phases(p, p, 1.0, p.size() - 5, {plan}, rng, TuneOptions{},
                                               std::function<void(const Packing&)>{},
                                               std::chrono::steady_clock::now(), false);
  EXPECT_FALSE(result.reached);
  std::vector<DiskId> expected = by_rank;
  expected.erase(expected.begin() + 1);
  expected.push_back(second_ranked);
  EXPECT_EQ(tried_in_order, expected);
}

}  // namespace
}  // namespace disktune
