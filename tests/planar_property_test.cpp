// SPDX-License-Identifier: GPL-3.0-or-later
// Property test of density tuning in the unit periodic box and in every planar domain of
// data/domains: maximal samples from several seeds, each tuned to many targets on both
// sides of its MPS count (fractions of it), with one radius and with a smooth sizing.
// Whatever tune() reaches, the result must be a valid packing as the independent oracles
// judge it (tests/oracle; never the library's own void or conflict code), with every
// disk's own radius, the sizing's radius at its center, and its fixed flag as the
// boundary flag; the count must have moved toward the target and match the result. For
// one seed and two targets (one below, one above) per domain and sizing, the oracle runs
// after every operation that changed the packing and stops the run at the first failure.
// Reaching a target is recorded, not required. A last test per domain and sizing breaks
// a valid packing in several ways, to show the verdict can fail. DISKTUNE_SWEEP=full runs
// ten times the seeds (twice for the every-operation check). Prints one "[figures]" line
// per sweep.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "disktune/packing.h"
#include "disktune/periodic_box.h"
#include "disktune/planar_domain.h"
#include "disktune/sampling.h"
#include "disktune/sizing.h"
#include "disktune/tuning.h"
#include "oracle/oracle.h"
#include "oracle/planar_oracle.h"
#include "planar_checks.h"
#include "sweep_seeds.h"
#include "test_util.h"

namespace disktune {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

using test::full_sweep;

// Targets as fractions of the MPS count, both sides. The far ones may be out of reach
// (the fixed boundary disks, no crystal phases with a sizing): then only validity counts.
constexpr double kFractions[] = {0.65, 0.75, 0.85, 0.95, 1.05, 1.15, 1.3, 1.45};

// The targets checked after every operation: one below the MPS count, one above. Far
// ones, through most phases, where a sample is small; nearer ones for larger samples
// (gear.poly's holes, sides 0.0518, bound its radius: 700 to 1000 disks, where each
// oracle call takes 5 to 9 ms and the far targets take thousands of operations).
constexpr std::size_t kSmallSample = 500;
std::array<double, 2> every_operation_fractions(const Packing& mps) {
  if (mps.size() <= kSmallSample) return {0.75, 1.3};
  return {0.85, 1.15};
}

// Seeds 1..n of the samples; the first `every_operation_seeds()` of them also get the
// every-operation check.
std::vector<std::uint64_t> seeds() { return test::sweep_seeds(2, 20); }
std::size_t every_operation_seeds() { return full_sweep() ? 2 : 1; }

bool checked_every_operation(std::size_t seed_index, const Packing& mps, double fraction) {
  const auto chosen = every_operation_fractions(mps);
  return seed_index < every_operation_seeds() && std::find(chosen.begin(), chosen.end(), fraction) != chosen.end();
}

// Random probes per oracle call: the exact void-corner checks are the real test, probes
// a second opinion; fewer of them after every operation, where calls are many.
constexpr std::size_t kFinalProbes = 20000;
constexpr std::size_t kStepProbes = 300;

// ---------------------------------------------------------------- domains and radii

// Where the packing lives: the unit periodic box (no domain) or a planar domain.
struct Scene {
  std::string name;  // "periodic_box" or the .poly file's name
  std::shared_ptr<const PlanarDomain> domain;
  PeriodicBox box{1, 1};
  oracle::Domain od;  // the domain as the planar oracle sees it
};

// One radius, or a sizing with the radius wanted at each point.
struct Radii {
  double r = 0;
  std::shared_ptr<const Sizing> sizing;
  double at(Vec2 x) const { return sizing ? (*sizing)(x) : r; }
  std::string label() const {
    std::ostringstream s;
    if (sizing) {
      s << "sizing \"" << sizing->description() << "\"";
    } else {
      s << "one radius " << r;
    }
    return s.str();
  }
};

// About this many disks per sample: big enough for every phase to have room, small
// enough for a hundred combinations in seconds.
constexpr double kDisks = 300;
// The MPS area fraction of the open plane is about 0.55.
constexpr double kMpsAreaFraction = 0.55;
constexpr double kPi = 3.14159265358979323846;

double two_digits_down(double r) {
  const double unit = std::pow(10.0, std::floor(std::log10(r)) - 1);
  return std::floor(r / unit) * unit;
}

// Every corner holds a fixed disk, and no corner may lie in another corner's disk: for
// the radius rule `shape` (scaled by s), the largest s that keeps max(r(a), r(b)) below
// the distance of every pair of corners a, b.
double corner_limit(const PlanarDomain& d, const std::function<double(Vec2)>& shape) {
  std::vector<Vec2> corners;
  for (const auto& loop : d.loops()) corners.insert(corners.end(), loop.begin(), loop.end());
  double limit = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < corners.size(); ++i)
    for (std::size_t j = i + 1; j < corners.size(); ++j)
      limit = std::min(limit, distance(corners[i], corners[j]) / std::max(shape(corners[i]), shape(corners[j])));
  return limit;
}

// The radius for about kDisks disks in the domain, below the corner limit (with 1% to
// spare), two significant digits. In gear.poly the corner limit (0.0518, its holes' sides)
// wins, which gives about twice as many disks.
double one_radius_for(const PlanarDomain& d) {
  const double r = std::sqrt(kMpsAreaFraction * d.area() / (kPi / 4 * kDisks));
  return two_digits_down(std::min(r, 0.99 * corner_limit(d, [](Vec2) { return 1.0; })));
}

// A linear ramp across the domain's width, r0 (1 + 0.3 (x - xc) / half width): 0.7 r0 to
// 1.3 r0, a gradation L = 0.3 r0 / half width far below the library's limit 1/2. r0 as
// one_radius_for, and below the corner limit of the ramp.
Sizing ramp_sizing_for(const PlanarDomain& d) {
  const Frame& f = d.frame();
  const double half = f.extent.x / 2, xc = f.origin.x + half;
  const auto shape = [&](Vec2 x) { return 1 + 0.3 * (x.x - xc) / half; };
  const double r0 = two_digits_down(std::min(one_radius_for(d), 0.99 * corner_limit(d, shape)));
  std::ostringstream e;
  e.precision(10);
  e << r0 << "*(1 + 0.3*(x - " << xc << ")/" << half << ")";
  return expression_sizing(e.str());
}

// The unit box: r = 0.05 is about 280 MPS disks. The sizing is periodic (a linear one
// would jump at the seam): 0.7 r to 1.3 r, L = 0.05 * 0.3 * 2 pi ~ 0.094.
constexpr double kBoxRadius = 0.05;
const char* const kBoxSizing = "0.05*(1 + 0.3*sin(2*pi*x)*cos(2*pi*y))";

Scene planar_scene(const std::string& file) {
  Scene s;
  s.name = file;
  s.domain = std::make_shared<const PlanarDomain>(read_poly(std::string(DISKTUNE_DATA_DIR) + "/domains/" + file));
  s.od = test::oracle_domain(*s.domain);
  return s;
}

Radii radii_for(const Scene& s, bool sized) {
  Radii r;
  if (!s.domain) {
    r.r = kBoxRadius;
    if (sized) r.sizing = std::make_shared<const Sizing>(expression_sizing(kBoxSizing));
  } else {
    r.r = one_radius_for(*s.domain);
    if (sized) r.sizing = std::make_shared<const Sizing>(ramp_sizing_for(*s.domain));
  }
  return r;
}

Packing sample(const Scene& s, const Radii& radii, std::uint64_t seed) {
  Rng rng(seed);
  if (s.domain) return radii.sizing ? sample_mps(s.domain, radii.sizing, rng) : sample_mps(s.domain, radii.r, rng);
  return radii.sizing ? sample_mps(s.box, radii.sizing, rng) : sample_mps(s.box, radii.r, rng);
}

TuneResult tune_to(Packing& p, const Scene& s, std::size_t goal, Rng& rng, const TuneOptions& opt) {
  return s.domain ? tune(p, *s.domain, Target::count(goal), rng, opt) : tune(p, s.box, Target::count(goal), rng, opt);
}

// The count at which the library refuses a target: that of the densest (hexagonal)
// packing, area fraction pi / (2 sqrt 3). In a planar domain the boundary disks raise the
// MPS area fraction to 0.62 or more, so 1.45 times the MPS count can lie beyond it; such
// targets are capped at 98% of it (dense, surely out of reach: the packing must stay
// valid all the same).
std::size_t densest_cap(const Scene& s, const Packing& mps) {
  const double area = s.domain ? s.domain->area() : s.box.area();
  return static_cast<std::size_t>(0.98 * kPi / (2 * std::sqrt(3.0)) * density_unit(mps, area));
}

// ---------------------------------------------------------------- the oracles' verdict

struct Verdict {
  bool ok = false;
  std::string summary;
};

// The oracle of the scene on every live disk (ids()), each with its own radius and, in a
// planar domain, its fixed flag as the boundary flag. The stored radii are first checked
// against the radius rule at each center, so that the oracle judges the disks the
// packing is meant to have.
Verdict judge(const Scene& s, const Radii& radii, const Packing& p, std::size_t probes, std::uint64_t probe_seed) {
  const oracle::Points centers = test::centers_of(p);
  const std::vector<double> r = test::radii_of(p);
  std::ostringstream wrong;
  std::size_t wrong_count = 0;
  for (std::size_t k = 0; k < centers.size(); ++k) {
    const double want = radii.at({centers[k][0], centers[k][1]});
    if (std::abs(r[k] - want) > 1e-12 * want && ++wrong_count <= 3)
      wrong << "disk at (" << centers[k][0] << ", " << centers[k][1] << ") has radius " << r[k] << ", want " << want
            << "; ";
  }
  Verdict v;
  if (s.domain) {
    oracle::PlanarOptions opt;
    opt.probes = probes;
    opt.seed = probe_seed;
    for (const DiskId id : p.ids()) opt.boundary_flags.push_back((p.flags(id) & kFixed) != 0);
    const oracle::PlanarReport rep = oracle::check_planar(s.od, centers, r, opt);
    v.ok = rep.ok();
    v.summary = rep.summary();
  } else {
    const oracle::Report rep = oracle::check_all(test::box_of(s.box), r, centers, 1e-6, probes, probe_seed);
    v.ok = rep.conflict_free() && rep.maximal();
    v.summary = rep.summary();
  }
  if (wrong_count > 0) {
    v.ok = false;
    v.summary = std::to_string(wrong_count) + " disks with a radius other than the rule's: " + wrong.str() + v.summary;
  }
  return v;
}

// ---------------------------------------------------------------- one combination

// What a sweep of combinations found, for the figures line.
struct Tally {
  std::size_t combinations = 0, reached = 0, oracle_calls = 0, operations = 0;
};

// Thrown from after_operation to stop tune() at the first state the oracle rejects.
struct OracleRejected {
  std::string message;
};

// A snapshot of the packing, to tell whether an operation changed it (the scheduler calls
// the hook after every operation it tried).
std::vector<std::array<double, 4>> state_of(const Packing& p) {
  std::vector<std::array<double, 4>> out;
  for (const DiskId id : p.ids())
    out.push_back({p.center(id).x, p.center(id).y, p.radius(id), static_cast<double>(p.flags(id) & kFixed)});
  return out;
}

// Tunes a copy of `mps` to round(fraction * MPS count) and checks the result: the oracle
// at the end and, with `every_operation`, after every operation that changed the packing.
void run_combination(const Scene& s, const Radii& radii, const Packing& mps, std::uint64_t seed, double fraction,
                     bool every_operation, Tally& tally) {
  const std::size_t wanted = static_cast<std::size_t>(std::lround(fraction * static_cast<double>(mps.size())));
  const std::size_t goal = std::min(wanted, densest_cap(s, mps));
  std::ostringstream name;
  name << s.name << ", " << radii.label() << ", seed " << seed << ", target " << fraction << " x " << mps.size()
       << " = " << goal << (goal < wanted ? " (capped below the densest packing)" : "");
  const std::string what = name.str();
  SCOPED_TRACE(what);

  Packing p = mps;
  Rng rng(1000 * seed + static_cast<std::uint64_t>(std::lround(100 * fraction)));
  TuneOptions opt;
  Phase phase = Phase::none;  // the phase the scheduler last reported
  opt.on_progress = [&](const Progress& progress) { return phase = progress.phase, true; };
  std::size_t operation = 0;  // operations that changed the packing
  std::vector<std::array<double, 4>> last = state_of(p);
  if (every_operation) {
    opt.after_operation = [&](const Packing& q) {
      std::vector<std::array<double, 4>> now = state_of(q);
      if (now == last) return;
      last = std::move(now);
      ++operation;
      ++tally.oracle_calls;
      const Verdict v = judge(s, radii, q, kStepProbes, operation);
      if (!v.ok) {
        std::ostringstream m;
        m << what << ": after operation " << operation << " (phase " << to_string(phase)
          << " as last reported, count " << q.size() << "): " << v.summary;
        throw OracleRejected{m.str()};
      }
    };
  }

  ++tally.combinations;
  TuneResult res;
  try {
    res = tune_to(p, s, goal, rng, opt);
  } catch (const OracleRejected& e) {
    tally.operations += operation;
    ADD_FAILURE() << e.message;
    return;
  }
  tally.reached += res.reached;
  tally.operations += operation;

  EXPECT_EQ(res.target, goal) << what;
  EXPECT_EQ(res.count, p.size()) << what;
  EXPECT_EQ(res.reached, res.count == res.target) << what;
  // Reaching a far target is not promised; getting closer is.
  const auto gap = [goal](std::size_t n) { return n > goal ? n - goal : goal - n; };
  EXPECT_LT(gap(p.size()), gap(mps.size())) << what << ": the count went from " << mps.size() << " to " << p.size()
                                            << " (" << to_string(res.last_phase) << ")";
  if (every_operation) {
    EXPECT_GT(operation, 0u) << what << ": no operation changed the packing";
  }
  ++tally.oracle_calls;
  const Verdict v = judge(s, radii, p, kFinalProbes, seed);
  EXPECT_TRUE(v.ok) << what << ": at the end (count " << p.size() << ", last phase " << to_string(res.last_phase)
                    << "): " << v.summary;
}

// The combinations of one scene and radius rule: every seed's sample (itself judged by
// the oracle), tuned to every target; `every_operation` selects which half of the
// combinations this call runs (those checked after every operation, or the others).
Tally run_sweep(const Scene& s, const Radii& radii, bool every_operation) {
  Tally tally;
  const std::vector<std::uint64_t> all = seeds();
  for (std::size_t k = 0; k < all.size(); ++k) {
    if (every_operation && k >= every_operation_seeds()) break;
    const Packing mps = sample(s, radii, all[k]);
    ++tally.oracle_calls;
    const Verdict v = judge(s, radii, mps, kFinalProbes, all[k]);
    EXPECT_TRUE(v.ok) << s.name << ", " << radii.label() << ", seed " << all[k] << ": the MPS sample: " << v.summary;
    if (!v.ok) continue;  // tuning from an invalid start proves nothing
    for (const double fraction : kFractions) {
      if (checked_every_operation(k, mps, fraction) != every_operation) continue;
      run_combination(s, radii, mps, all[k], fraction, every_operation, tally);
      if (::testing::Test::HasFatalFailure()) return tally;
    }
  }
  return tally;
}

// The verdict must be able to fail. A sample tuned to 90% of its count (so that its ids
// have gaps) passes; each of these breaks it: the largest free disk removed (no other
// disk covers its center: a void), a free neighbour moved a quarter of the way onto it
// (a conflict), in a planar domain that disk flagged fixed (a boundary disk off the
// boundary), and a radius rule 1% larger than the disks'.
void expect_judge_rejects_broken_packings(const Scene& s, const Radii& radii) {
  Packing p = sample(s, radii, 1);
  Rng rng(7);
  tune_to(p, s, p.size() * 9 / 10, rng, {});
  const Verdict good = judge(s, radii, p, kStepProbes, 1);
  ASSERT_TRUE(good.ok) << good.summary;

  DiskId big = kNoDisk;
  for (const DiskId id : p.ids())
    if (!(p.flags(id) & kFixed) && (big == kNoDisk || p.radius(id) > p.radius(big))) big = id;
  ASSERT_NE(big, kNoDisk);
  const Vec2 c = p.center(big);
  {
    Packing q = p;
    q.remove(big);
    EXPECT_FALSE(judge(s, radii, q, kStepProbes, 1).ok) << "a disk removed";
  }
  {
    // Its nearest free neighbour (the image nearest c in the box); a quarter of their
    // distance is at most 2 r_max / 4 < r_min for radii within a factor 1.3 / 0.7.
    Neighbor near{kNoDisk, c, std::numeric_limits<double>::infinity(), 0};
    p.for_each_near(c, 2 * p.max_radius(), [&](const Neighbor& n) {
      if (n.id != big && !(p.flags(n.id) & kFixed) && n.d2 < near.d2) near = n;
    });
    ASSERT_NE(near.id, kNoDisk);
    const Vec2 onto = c + (near.image - c) * 0.25;
    ASSERT_TRUE(p.inside(onto));
    Packing q = p;
    q.move(near.id, s.domain ? onto : s.box.wrap(onto));
    EXPECT_FALSE(judge(s, radii, q, kStepProbes, 1).ok) << "a disk moved onto another";
  }
  if (s.domain) {
    Packing q = p;
    q.set_flags(big, q.flags(big) | kFixed);
    EXPECT_FALSE(judge(s, radii, q, kStepProbes, 1).ok) << "an interior disk flagged as a boundary disk";
  }
  Radii larger = radii;
  larger.r *= 1.01;
  if (radii.sizing) {
    const auto rule = radii.sizing;
    larger.sizing = std::make_shared<const Sizing>([rule](Vec2 x) { return 1.01 * (*rule)(x); }, "1.01 r(x)");
  }
  EXPECT_FALSE(judge(s, larger, p, kStepProbes, 1).ok) << "radii other than the rule's";
}

void print_figures(const std::string& kind, const Scene& s, const Radii& radii, const Tally& t, double seconds) {
  std::printf("[figures] %s %s %s: %zu combinations, %zu reached, %zu oracle calls, %zu operations checked, %.1f s\n",
              kind.c_str(), s.name.c_str(), radii.label().c_str(), t.combinations, t.reached, t.oracle_calls,
              t.operations, seconds);
  std::fflush(stdout);
}

// ---------------------------------------------------------------- planar domains

struct PlanarCase {
  std::string file;  // a .poly file in data/domains
  bool sized;
};
void PrintTo(const PlanarCase& c, std::ostream* os) { *os << c.file << (c.sized ? " sized" : " one radius"); }

// Every .poly file in data/domains, so that a new domain is tested without edits here.
std::vector<PlanarCase> planar_cases() {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(std::string(DISKTUNE_DATA_DIR) + "/domains"))
    if (e.path().extension() == ".poly") files.push_back(e.path().filename().string());
  std::sort(files.begin(), files.end());
  std::vector<PlanarCase> out;
  for (const auto& f : files)
    for (const bool sized : {false, true}) out.push_back({f, sized});
  return out;
}

class PlanarProperty : public ::testing::TestWithParam<PlanarCase> {
 protected:
  void SetUp() override {
    scene_ = planar_scene(GetParam().file);
    radii_ = radii_for(scene_, GetParam().sized);
  }
  void run(bool every_operation) {
    const auto t0 = Clock::now();
    const Tally t = run_sweep(scene_, radii_, every_operation);
    print_figures(every_operation ? "planar every-operation" : "planar sweep", scene_, radii_, t, seconds_since(t0));
  }
  Scene scene_;
  Radii radii_;
};

TEST_P(PlanarProperty, TargetsOnBothSidesPassTheOracle) { run(false); }
TEST_P(PlanarProperty, OracleAfterEveryOperation) { run(true); }
TEST_P(PlanarProperty, JudgeRejectsBrokenPackings) { expect_judge_rejects_broken_packings(scene_, radii_); }

INSTANTIATE_TEST_SUITE_P(, PlanarProperty, ::testing::ValuesIn(planar_cases()),
                         [](const ::testing::TestParamInfo<PlanarCase>& info) {
                           std::string name = std::filesystem::path(info.param.file).stem().string();
                           return name + (info.param.sized ? "_sized" : "_one_radius");
                         });

// ---------------------------------------------------------------- periodic box

class PeriodicProperty : public ::testing::TestWithParam<bool> {
 protected:
  void SetUp() override {
    scene_.name = "periodic_box";
    radii_ = radii_for(scene_, GetParam());
  }
  void run(bool every_operation) {
    const auto t0 = Clock::now();
    const Tally t = run_sweep(scene_, radii_, every_operation);
    print_figures(every_operation ? "periodic every-operation" : "periodic sweep", scene_, radii_, t,
                  seconds_since(t0));
  }
  Scene scene_;
  Radii radii_;
};

TEST_P(PeriodicProperty, TargetsOnBothSidesPassTheOracle) { run(false); }
TEST_P(PeriodicProperty, OracleAfterEveryOperation) { run(true); }
TEST_P(PeriodicProperty, JudgeRejectsBrokenPackings) { expect_judge_rejects_broken_packings(scene_, radii_); }

INSTANTIATE_TEST_SUITE_P(, PeriodicProperty, ::testing::Bool(), [](const ::testing::TestParamInfo<bool>& info) {
  return std::string(info.param ? "sized" : "one_radius");
});

}  // namespace
}  // namespace disktune
