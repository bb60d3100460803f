// SPDX-License-Identifier: GPL-3.0-or-later
// Sampling and tuning on surfaces, judged by the independent surface oracle.
#include <gtest/gtest.h>

#include <cmath>

#include "disktune/restricted_delaunay.h"
#include "disktune/surface_features.h"
#include "disktune/surface_sizing.h"
#include "disktune/surface_tuning.h"
#include "disktune/surface_voids.h"
#include "surface_checks.h"
#include "test_util.h"

namespace disktune {
namespace {

using test::surface_file;
using test::surface_report;

double diagonal(const SurfaceDomain& d) { return norm(d.bbox_max() - d.bbox_min()); }

struct Case {
  const char* file;
  double r_over_diagonal;
};
// A closed sphere, a closed genus-2 surface, an open surface (a boundary loop), and a
// larger closed genus-3 sculpture.
const Case kCases[] = {
    {"sphere.off", 0.05}, {"eight.off", 0.04}, {"mesh_with_border.off", 0.02}, {"elephant.off", 0.02}};

TEST(SurfaceMps, MaximalAndConflictFreeOnRealSurfaces) {
  for (const Case& c : kCases) {
    const auto domain = surface_file(c.file);
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      Rng rng(seed);
      const SurfacePacking packing =
          sample_mps(domain, SurfaceSizing::constant(c.r_over_diagonal * diagonal(*domain)), rng);
      SCOPED_TRACE(std::string(c.file) + " seed " + std::to_string(seed));
      EXPECT_SURFACE_OK(packing);
      EXPECT_TRUE(is_maximal(packing));
      EXPECT_GT(packing.size(), 50u);
      // An MPS covers about half the area fraction unit (0.5 to 0.6 in the plane).
      const double eta = packing.size() / density_unit(packing);
      EXPECT_GT(eta, 0.4);
      EXPECT_LT(eta, 0.75);
    }
  }
}

TEST(SurfaceMps, OpenBoundaryHasFixedDisksOnIt) {
  const auto domain = surface_file("mesh_with_border.off");
  Rng rng(7);
  const SurfacePacking packing = sample_mps(domain, SurfaceSizing::constant(0.03 * diagonal(*domain)), rng);
  std::size_t fixed = 0;
  for (const DiskId id : packing.ids()) fixed += (packing.flags(id) & kFixed) ? 1 : 0;
  EXPECT_GT(fixed, 10u);
  EXPECT_TRUE(uncovered_curves(packing, true).empty());
  EXPECT_TRUE(surface_report(packing).boundary_ok()) << surface_report(packing).summary();
}

// Long boundary edges, hundreds of radii long: their fixed disks cover them (1D
// maximal) and the sample passes the oracle. (One ball around a whole edge made finding
// a long edge's gaps cost (length / r)^3 grid cells: a 10 x 0.1 plate and a triangle of
// aspect 100 did not finish; docs/surfaces.md.)
TEST(SurfaceMps, LongBoundaryEdges) {
  const std::vector<Vec3> strip{{0, 0, 0}, {10, 0, 0}, {10, 0.1, 0}, {0, 0.1, 0}};
  const std::vector<Vec3> sliver{{0, 0, 0}, {10, 0, 0}, {5, 0.1, 0}};
  const auto plate = std::make_shared<const SurfaceDomain>(strip, std::vector<SurfaceDomain::Triangle>{{0, 1, 2}, {0, 2, 3}});
  const auto thin = std::make_shared<const SurfaceDomain>(sliver, std::vector<SurfaceDomain::Triangle>{{0, 1, 2}});
  // Each fixed disk covers at most 2r of each edge it reaches: of one long edge of the
  // plate (its long edges are 10 r apart), of both sides of the sliver (0.1 = r wide).
  struct Case {
    std::shared_ptr<const SurfaceDomain> domain;
    double r;
    std::size_t least;  // boundary length 20 over the most one disk covers
  };
  // A needle 2000 r long and at most r wide: the exact void search and the sampler's
  // cells follow its width, so it costs its length, not its length squared (#17).
  const std::vector<Vec3> long_needle{{0, 0, 0}, {200, 0, 0}, {200, 0.1, 0}};
  const auto needle = std::make_shared<const SurfaceDomain>(long_needle, std::vector<SurfaceDomain::Triangle>{{0, 1, 2}});
  for (const Case& c : {Case{plate, 0.01, 1000}, Case{thin, 0.1, 50}, Case{needle, 0.1, 1000}}) {
    Rng rng(3);
    const SurfacePacking packing = sample_mps(c.domain, SurfaceSizing::constant(c.r), rng);
    const auto report = surface_report(packing);
    EXPECT_TRUE(report.ok()) << report.summary();
    EXPECT_GE(report.boundary_count, c.least);
  }
}

TEST(SurfaceMps, SameSeedSameSample) {
  const auto domain = surface_file("eight.off");
  Rng a(5), b(5);
  const auto p = sample_mps(domain, SurfaceSizing::constant(0.05 * diagonal(*domain)), a);
  const auto q = sample_mps(domain, SurfaceSizing::constant(0.05 * diagonal(*domain)), b);
  ASSERT_EQ(p.size(), q.size());
  for (const DiskId id : p.ids()) EXPECT_EQ(p.center(id), q.center(id));
}

// MPS, then ejection to 0.62 and injection to 1.4 times its count (the paper reports
// -38 % and +44 % on a surface; docs/surfaces.md has what is reached where), on the
// genus-2 surface and the open one, each result checked by the oracle and meshed (a
// manifold restricted Delaunay mesh of the input's genus). The radii are the largest
// at which the ejection was reached for every seed tried (docs/surfaces.md): with fewer
// disks, curvature and the boundary leave less room. (Until the sampler was made
// unbiased (#15) its MPS held about 3 % more disks, and 0.6 of that count asked for
// the area fraction, about 0.335 on eight.off, that 0.62 of today's does.)
TEST(SurfaceTune, EjectionAndInjectionReachExactCounts) {
  const Case cases[] = {{"eight.off", 0.015}, {"mesh_with_border.off", 0.008}};
  for (const Case& c : cases) {
    const auto domain = surface_file(c.file);
    Rng rng(1);
    const SurfacePacking mps = sample_mps(domain, SurfaceSizing::constant(c.r_over_diagonal * diagonal(*domain)), rng);
    for (const double factor : {0.62, 1.4}) {
      SCOPED_TRACE(std::string(c.file) + " x" + std::to_string(factor));
      SurfacePacking packing = mps;
      const std::size_t goal = static_cast<std::size_t>(std::lround(factor * mps.size()));
      const TuneResult result = tune(packing, Target::count(goal), rng);
      EXPECT_TRUE(result.reached) << result.count << " of " << goal << ", last phase " << to_string(result.last_phase);
      EXPECT_EQ(packing.size(), result.count);
      EXPECT_SURFACE_OK(packing);
      std::vector<Vec3> samples;
      for (const DiskId id : packing.ids()) samples.push_back(packing.center(id));
      const SurfaceMeshCheck check = check_surface_mesh(restricted_delaunay(samples, *domain));
      EXPECT_TRUE(check.manifold) << check.problems;
      EXPECT_EQ(check.genus, domain->genus());
    }
  }
}

// Where the one-ring attractor has stalled, pulling three rings removes more disks,
// each step valid.
TEST(SurfaceTune, WideAttractorRemovesDisksWhereTheAttractorStalled) {
  const auto domain = surface_file("eight.off");
  Rng rng(2);
  SurfacePacking packing = sample_mps(domain, SurfaceSizing::constant(0.03 * diagonal(*domain)), rng);
  auto sweep = [&](std::size_t (*op)(SurfacePacking&, DiskId, Rng&, std::size_t)) {
    std::size_t removed = 0;
    for (const DiskId id : packing.ids()) {
      if (packing.alive(id)) removed += op(packing, id, rng, 1000);
    }
    return removed;
  };
  for (int k = 0; k < 100 && sweep(&attractor_eject) > 0;) ++k;
  const std::size_t stalled = packing.size();
  EXPECT_SURFACE_OK(packing);
  std::size_t removed = 0;
  for (int k = 0; k < 3; ++k) {
    removed += sweep(&wide_attractor_eject);
    EXPECT_SURFACE_OK(packing);
  }
  EXPECT_EQ(packing.size(), stalled - removed);
  EXPECT_GE(removed, stalled / 50) << "from " << stalled;  // one ring: 4 of 395
  std::printf("[figures] eight.off attractor stalled at N=%zu, three wide sweeps removed %zu\n", stalled, removed);
}

// Every single operation leaves the packing conflict-free and maximal.
TEST(SurfaceTune, EachOperationKeepsTheInvariants) {
  const auto domain = surface_file("eight.off");
  using Op = std::size_t (*)(SurfacePacking&, DiskId, Rng&, std::size_t);
  const std::pair<const char*, Op> ops[] = {{"void", &void_inject},
                                            {"repeller", &repeller_inject},
                                            {"sift", &sift_eject},
                                            {"attractor", &attractor_eject},
                                            {"wide attractor", &wide_attractor_eject}};
  for (const auto& [name, op] : ops) {
    Rng rng(3);
    SurfacePacking packing = sample_mps(domain, SurfaceSizing::constant(0.06 * diagonal(*domain)), rng);
    std::size_t changed = 0;
    for (int k = 0; k < 25; ++k) {
      const auto ids = packing.ids();
      const std::size_t before = packing.size();
      op(packing, ids[uniform_index(rng, ids.size())], rng, 3);
      changed += packing.size() != before;
      const auto report = surface_report(packing, 2);
      ASSERT_TRUE(report.ok()) << name << " step " << k << ": " << report.summary();
    }
    EXPECT_GT(changed, 0u) << name << " never changed the count";
  }
}

// Repeller injection with varying radii on an open surface (fixed boundary disks): every
// step judged by the oracle, the boundary disks never moved.
TEST(SurfaceTune, RepellerWithASizingOnAnOpenSurfaceKeepsTheInvariants) {
  const auto domain = surface_file("mesh_with_border.off");
  std::vector<double> radii;  // 0.02 to 0.045 of the diagonal, growing along x
  const double d = diagonal(*domain), x0 = domain->bbox_min().x, dx = domain->bbox_max().x - x0;
  for (const Vec3 v : domain->vertices()) radii.push_back(d * (0.02 + 0.025 * (v.x - x0) / dx));
  Rng rng(12);
  SurfacePacking packing = sample_mps(domain, SurfaceSizing::per_vertex(*domain, radii), rng);
  std::vector<std::pair<DiskId, Vec3>> fixed;
  for (const DiskId id : packing.ids())
    if (packing.flags(id) & kFixed) fixed.push_back({id, packing.center(id)});
  ASSERT_FALSE(fixed.empty());
  const std::size_t start = packing.size();
  for (int k = 0; k < 60; ++k) {
    const auto ids = packing.ids();
    repeller_inject(packing, ids[uniform_index(rng, ids.size())], rng, 3);
    const auto report = surface_report(packing, 2);
    ASSERT_TRUE(report.ok()) << "step " << k << ": " << report.summary();
  }
  EXPECT_GT(packing.size(), start) << "the repeller never injected";
  for (const auto& [id, c] : fixed) {
    ASSERT_TRUE(packing.alive(id));
    EXPECT_EQ(norm(packing.center(id) - c), 0.0);
  }
}

// Between operations of the automatic schedule, both ways, the packing stays valid.
TEST(SurfaceTune, ScheduleKeepsTheInvariantsBetweenOperations) {
  const auto domain = surface_file("mesh_with_border.off");
  for (const double factor : {0.75, 1.3}) {
    Rng rng(8);
    SurfacePacking packing = sample_mps(domain, SurfaceSizing::constant(0.03 * diagonal(*domain)), rng);
    TuneOptions options;
    std::size_t operations = 0;
    options.after_surface_operation = [&](const SurfacePacking& now) {
      if (++operations % 15 != 0) return;
      const auto report = surface_report(now, 2);
      ASSERT_TRUE(report.ok()) << "x" << factor << " operation " << operations << ": " << report.summary();
    };
    const auto goal = static_cast<std::size_t>(std::lround(factor * packing.size()));
    EXPECT_TRUE(tune(packing, Target::count(goal), rng, options).reached) << "x" << factor;
    EXPECT_GT(operations, 15u);
  }
}

TEST(SurfaceTune, VaryingRadiiStayValid) {
  const auto domain = surface_file("eight.off");
  // A linear field along z: radii from 0.025 to 0.05 of the diagonal.
  std::vector<double> radii;
  const double d = diagonal(*domain), z0 = domain->bbox_min().z, dz = domain->bbox_max().z - z0;
  for (const Vec3 v : domain->vertices()) radii.push_back(d * (0.025 + 0.025 * (v.z - z0) / dz));
  Rng rng(2);
  const SurfacePacking mps = sample_mps(domain, SurfaceSizing::per_vertex(*domain, radii), rng);
  EXPECT_SURFACE_OK(mps);
  for (const double factor : {0.7, 1.3}) {
    SurfacePacking packing = mps;
    const auto goal = static_cast<std::size_t>(std::lround(factor * mps.size()));
    const TuneResult result = tune(packing, Target::count(goal), rng);
    EXPECT_TRUE(result.reached) << result.count << " of " << goal;
    EXPECT_SURFACE_OK(packing);
  }
}

// Feature curves sampled with a varying sizing can hold more disks at tune's 1.2 r than
// the sample put on them. A target just above the sample once let the curves' 1D tuning
// pass it, and the injection phases then never stopped (fandisk, thickness sizing:
// 694 disks, target 697, 933 after 13,000 operations). Both ways, every seed: the exact
// count, judged by the oracle.
TEST(SurfaceTune, ATargetNextToTheSampleIsReachedWithFeaturesAndASizing) {
  auto fandisk = std::make_shared<SurfaceDomain>(*surface_file("fandisk.off"));
  fandisk->set_features(detect_features(*fandisk));
  const SurfaceSizing sizing = thickness_sizing(*fandisk, 0.056);
  ASSERT_FALSE(sizing.is_constant());
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    Rng rng(seed);
    const SurfacePacking mps = sample_mps(fandisk, sizing, rng);
    for (const long delta : {3L, -3L}) {
      for (const Method method : {Method::automatic, delta > 0 ? Method::void_injection : Method::sift_ejection}) {
        SCOPED_TRACE("seed " + std::to_string(seed) + ", " + std::to_string(delta) + ", method " +
                     std::to_string(static_cast<int>(method)));
        SurfacePacking packing = mps;
        const auto goal = static_cast<std::size_t>(static_cast<long>(mps.size()) + delta);
        TuneOptions options;
        options.method = method;
        const TuneResult result = tune(packing, Target::count(goal), rng, options);
        EXPECT_TRUE(result.reached) << result.count << " of " << goal;
        EXPECT_EQ(packing.size(), goal);
        EXPECT_SURFACE_OK(packing);
      }
    }
  }
}

// A center inside a larger disk is allowed (it came first); two disks covering each
// other's centers are not.
TEST(SurfaceValidation, FollowsThePriorDiskRule) {
  const auto domain = surface_file("eight.off");
  std::vector<double> radii;
  const double d = diagonal(*domain), z0 = domain->bbox_min().z, dz = domain->bbox_max().z - z0;
  for (const Vec3 v : domain->vertices()) radii.push_back(d * (0.02 + 0.04 * (v.z - z0) / dz));
  Rng rng(6);
  SurfacePacking packing = sample_mps(domain, SurfaceSizing::per_vertex(*domain, radii), rng);
  std::size_t covered_centers = 0;
  for (const DiskId i : packing.ids())
    for (const DiskId j : packing.ids())
      if (i != j && squared_norm(packing.center(i) - packing.center(j)) < packing.radius(j) * packing.radius(j)) ++covered_centers;
  EXPECT_GT(covered_centers, 0u) << "the case needs centers inside larger disks";
  EXPECT_TRUE(is_conflict_free(packing));
  EXPECT_NO_THROW(validate_packing(packing, "mps"));
  const DiskId a = packing.ids().front();
  packing.insert(packing.point(a));  // a second disk on the same center
  EXPECT_FALSE(is_conflict_free(packing));
  EXPECT_NE(test::message_of([&] { validate_packing(packing, "twice"); }).find("cover each other's centers"),
            std::string::npos);
}

TEST(SurfaceTune, RefusesAngleInjectionAndCrystalsWithASizing) {
  const auto domain = surface_file("sphere.off");
  Rng rng(1);
  SurfacePacking packing = sample_mps(domain, SurfaceSizing::constant(0.1), rng);
  TuneOptions options;
  options.method = Method::angle_injection;
  EXPECT_NE(test::message_of([&] { tune(packing, Target::count(packing.size() + 5), rng, options); }).find("angle"),
            std::string::npos);
  SurfacePacking sized = sample_mps(
      domain, SurfaceSizing::per_vertex(*domain, std::vector<double>(domain->vertices().size(), 0.1)), rng);
  EXPECT_NE(test::message_of([&] { crystal_eject(sized, rng, 5); }).find("one radius"), std::string::npos);
}

// Crystal growth alone, both ways, keeps the invariants after every kept step.
TEST(SurfaceTune, CrystalStepsKeepTheInvariants) {
  const auto domain = surface_file("sphere.off");
  for (const bool inject : {true, false}) {
    Rng rng(4);
    SurfacePacking packing = sample_mps(domain, SurfaceSizing::constant(0.08), rng);
    const std::size_t start = packing.size();
    int steps = 0;
    auto check = [&] {
      if (++steps % 10 != 0) return;
      const auto report = surface_report(packing, 2);
      ASSERT_TRUE(report.ok()) << (inject ? "inject" : "eject") << " step " << steps << ": " << report.summary();
    };
    const std::size_t changed = inject ? crystal_inject(packing, rng, 40, check) : crystal_eject(packing, rng, 40, check);
    EXPECT_GT(changed, 0u);
    EXPECT_EQ(packing.size(), inject ? start + changed : start - changed);
    EXPECT_SURFACE_OK(packing);
  }
}

// Grain injection on a surface (a grain per 40 disks: a dozen nuclei on the sphere), the
// oracle after every step it commits, the count never past the target.
TEST(SurfaceTune, GrainStepsKeepTheInvariants) {
  const auto domain = surface_file("sphere.off");
  Rng rng(5);
  SurfacePacking packing = sample_mps(domain, SurfaceSizing::constant(0.08), rng);
  const std::size_t start = packing.size();
  int steps = 0;
  auto check = [&] {
    ++steps;
    const auto report = surface_report(packing, 2);
    ASSERT_TRUE(report.ok()) << "step " << steps << ": " << report.summary();
  };
  const std::size_t added = grain_inject(packing, rng, 120, check, 40);
  EXPECT_GT(added, 0u);
  EXPECT_LE(added, 120u);
  EXPECT_GT(steps, 5);
  EXPECT_EQ(packing.size(), start + added);
  EXPECT_SURFACE_OK(packing);
}

// The resampled surface: the restricted Delaunay mesh of a tuned packing is a manifold
// with the input's genus, close to it.
TEST(SurfaceTune, TunedPackingsMeshTheSurface) {
  const auto domain = surface_file("eight.off");
  const double r = 0.03 * diagonal(*domain);
  Rng rng(9);
  const SurfacePacking mps = sample_mps(domain, SurfaceSizing::constant(r), rng);
  for (const double factor : {0.7, 1.0, 1.4}) {
    SCOPED_TRACE("x" + std::to_string(factor));
    SurfacePacking packing = mps;
    if (factor != 1.0) tune(packing, Target::count(static_cast<std::size_t>(std::lround(factor * mps.size()))), rng);
    std::vector<Vec3> samples;
    for (const DiskId id : packing.ids()) samples.push_back(packing.center(id));
    const SurfaceMesh mesh = restricted_delaunay(samples, *domain);
    const SurfaceMeshCheck check = check_surface_mesh(mesh);
    EXPECT_TRUE(check.manifold) << check.problems;
    EXPECT_EQ(check.genus, domain->genus());
    EXPECT_EQ(check.components, 1u);
    EXPECT_LT(hausdorff_distance(mesh, *domain, 20000, 1), 0.5 * r);
  }
}

}  // namespace
}  // namespace disktune
