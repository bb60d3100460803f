// SPDX-License-Identifier: GPL-3.0-or-later
// Relaxation (relax): disks move, none is added or removed, fixed disks stay put, and
// after every sweep the independent oracles find the packing conflict-free and maximal;
// and it does what it is for: the mesh's angles, measured here by plain geometry on a
// brute-force Delaunay triangulation (torus) or on the restricted Delaunay mesh's
// coordinates (surface), come much closer to 60 degrees.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "../src/tuning/relax_at_end.h"
#include "brute_delaunay.h"
#include "disktune/density.h"
#include "disktune/planar_domain.h"
#include "disktune/restricted_delaunay.h"
#include "disktune/sampling.h"
#include "disktune/sizing.h"
#include "disktune/surface_features.h"
#include "disktune/surface_sampling.h"
#include "disktune/surface_sizing.h"
#include "disktune/surface_tuning.h"
#include "disktune/tuning.h"
#include "oracle/mesh_topology.h"
#include "oracle/oracle.h"
#include "planar_checks.h"
#include "surface_checks.h"
#include "test_util.h"

namespace disktune {
namespace {

// The rest length remesh uses: the hexagonal spacing of the packing's own density.
double hex_spacing(double eta) { return 1 / relative_radius_for(eta); }

// The shares of test::angle_shares, on the brute-force periodic Delaunay triangulation.
test::AngleShares torus_angles(const Packing& p, double W, double H, double r) {
  std::vector<test::BrutePoint> pts;
  for (const DiskId id : p.ids()) pts.push_back({p.center(id).x, p.center(id).y});
  const auto tris = test::brute_periodic_delaunay(pts, W, H, 2.2 * r);
  double area = 0;
  std::size_t near = 0, obtuse = 0;
  for (const auto& t : tris) {
    const auto& c = t.corners;
    area += 0.5 * ((c[1].x - c[0].x) * (c[2].y - c[0].y) - (c[1].y - c[0].y) * (c[2].x - c[0].x));
    bool wide = false;
    for (const double a : test::brute_angles_degrees(c)) near += a >= 50 && a <= 70, wide = wide || a > 90;
    obtuse += wide;
  }
  EXPECT_NEAR(area, W * H, 1e-9) << "the brute force missed triangles";
  return {static_cast<double>(near) / (3.0 * tris.size()), static_cast<double>(obtuse) / tris.size()};
}

// Sweep by sweep, and several sweeps with momentum (the oracle after each through the
// callback); momentum should leave more angles near 60 degrees.
TEST(Relaxation, KeepsATorusPackingValidAndMakesItsAnglesCloserTo60) {
  const double W = 1, H = 1, r = 0.05;
  double plain_total = 0, momentum_total = 0;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    for (const bool momentum : {false, true}) {
      const PeriodicBox box(W, H);
      Rng rng(seed);
      Packing p = sample_mps(box, r, rng);
      const std::size_t n = p.size();
      const double spacing = hex_spacing(area_fraction(n, r, W * H));
      const test::AngleShares before = torus_angles(p, W, H, r);
      const auto judge = [&](int sweep) {
        EXPECT_EQ(p.size(), n);
        const auto rep = oracle::check_all(test::box_of(box), r, test::centers_of(p), 1e-6, 3000, seed);
        EXPECT_TRUE(rep.conflict_free() && rep.maximal()) << "seed " << seed << " sweep " << sweep << ": " << rep.summary();
        return rep.conflict_free() && rep.maximal();
      };
      int sweeps = 0;
      if (momentum) {
        relax(p, spacing, 20, rng, [&](int k) { return ++sweeps == k && judge(k); });
      } else {
        for (sweeps = 1; sweeps <= 20; ++sweeps) {
          relax(p, spacing, rng);
          ASSERT_TRUE(judge(sweeps));
        }
        --sweeps;
      }
      ASSERT_EQ(sweeps, 20);
      const test::AngleShares after = torus_angles(p, W, H, r);
      std::printf("[ relax ] torus r %g seed %llu, %zu disks%s: angles in [50,70] %.3f -> %.3f, obtuse %.3f -> %.3f\n",
                  r, static_cast<unsigned long long>(seed), n, momentum ? ", momentum" : "", before.near_60,
                  after.near_60, before.obtuse, after.obtuse);
      EXPECT_GT(after.near_60, before.near_60 + 0.2) << "seed " << seed;
      EXPECT_LT(after.obtuse, before.obtuse / 2) << "seed " << seed;
      (momentum ? momentum_total : plain_total) += after.near_60;
    }
  }
  EXPECT_GT(momentum_total, plain_total);
}

TEST(Relaxation, StopsWhenTheCallbackSaysSoAndRefusesNegativeSweeps) {
  const PeriodicBox box(1, 1);
  Rng rng(1);
  Packing p = sample_mps(box, 0.05, rng);
  int calls = 0;
  relax(p, 1.2, 10, rng, [&](int) { return ++calls < 3; });
  EXPECT_EQ(calls, 3);
  EXPECT_EQ(relax(p, 1.2, 0, rng), 0u);
  EXPECT_THROW(relax(p, 1.2, -1, rng), InvalidInput);
  EXPECT_THROW(relax(p, 0, 5, rng), InvalidInput);
}

// One radius, and a sizing (the feature sizing, smaller near the notch and the holes),
// where a disk's radius changes as it moves.
TEST(Relaxation, KeepsAPlanarDomainsBoundaryDisksAndItsPackingValid) {
  const auto domain =
      std::make_shared<const PlanarDomain>(read_poly(std::string(DISKTUNE_DATA_DIR) + "/domains/notch_and_holes.poly"));
  const auto sizing = std::make_shared<const Sizing>(parse_sizing("auto:0.04", domain));
  for (const bool sized : {false, true}) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      Rng rng(seed);
      Packing p = sized ? sample_mps(domain, sizing, rng) : sample_mps(domain, 0.03, rng);
      const std::size_t n = p.size();
      std::map<DiskId, Vec2> fixed;
      for (const DiskId id : p.ids())
        if (p.flags(id) & kFixed) fixed[id] = p.center(id);
      ASSERT_FALSE(fixed.empty());
      const double spacing = hex_spacing(static_cast<double>(n) / density_unit(p, domain->area()));
      const auto judge = [&](int sweep) {
        EXPECT_EQ(p.size(), n);
        const oracle::PlanarReport rep = test::check_with_oracle(p, *domain);
        EXPECT_TRUE(rep.ok()) << (sized ? "auto:0.04" : "r 0.03") << " seed " << seed << " sweep " << sweep << ": "
                              << rep.summary();
        return rep.ok();
      };
      // Seeds 1 and 2 sweep by sweep, seed 3 with momentum (the oracle after every sweep).
      std::size_t moved = 0;
      if (seed < 3) {
        for (int sweep = 1; sweep <= 10; ++sweep) {
          moved += relax(p, spacing, rng);
          ASSERT_TRUE(judge(sweep));
        }
      } else {
        int sweeps = 0;
        moved = relax(p, spacing, 10, rng, [&](int k) { return ++sweeps == k && judge(k); });
        ASSERT_EQ(sweeps, 10);
      }
      EXPECT_GT(moved, n);  // most disks moved, some several times
      for (const auto& [id, at] : fixed) {
        ASSERT_TRUE(p.alive(id));
        EXPECT_EQ(p.center(id).x, at.x);
        EXPECT_EQ(p.center(id).y, at.y);
      }
    }
  }
}

// On surfaces with sharp features (fixed disks on the curves): validity after every
// sweep, fixed disks in place, the mesh still of the input's topology, and its angles
// closer to 60 degrees.
TEST(Relaxation, KeepsASurfacePackingValidItsFeaturesFixedAndItsMeshsTopology) {
  // A radius, or a sizing (thickness: smaller where fandisk faces itself closely; the
  // radii vary, and a third of the disks are fixed on its creases: a smaller gain).
  struct Case {
    const char* file;
    const char* spec;
    double gain;    // at least this much more of the angles in [50, 70]
    double obtuse;  // at most this share of the obtuse triangles left
  };
  const Case cases[] = {
      {"fandisk.off", "0.04", 0.15, 0.6}, {"fandisk.off", "auto:0.05", 0.1, 0.75}, {"elephant.off", "0.012", 0.25, 0.3}};
  for (const auto& [file, spec, gain, obtuse] : cases) {
    SurfaceDomain d = *test::surface_file(file);
    d.set_features(detect_features(d, {60, 60, 0}));
    const auto surface = std::make_shared<const SurfaceDomain>(std::move(d));
    const oracle::SurfaceMeshInput input = test::oracle_surface(*surface);
    const oracle::TopologyReport want = oracle::check_topology(
        input.vertices.size(), std::vector<std::array<std::size_t, 3>>(input.triangles.begin(), input.triangles.end()));
    for (std::uint64_t seed = 1; seed <= 2; ++seed) {
      Rng rng(seed);
      SurfacePacking p = sample_mps(surface, parse_surface_sizing(spec, *surface), rng);
      const std::size_t n = p.size();
      std::map<DiskId, Vec3> fixed;
      for (const DiskId id : p.ids())
        if (p.flags(id) & kFixed) fixed[id] = p.center(id);
      ASSERT_FALSE(fixed.empty());
      const test::AngleShares before = test::angle_shares(restricted_delaunay(p));
      const double spacing = hex_spacing(static_cast<double>(n) / density_unit(p));
      const std::string what = std::string(file) + " " + spec;  // (lambdas cannot capture bindings in C++17)
      const auto judge = [&](int sweep) {
        EXPECT_EQ(p.size(), n);
        const auto rep = test::surface_report(p);
        EXPECT_TRUE(rep.ok()) << what << " seed " << seed << " sweep " << sweep << ": " << rep.summary();
        return rep.ok();
      };
      // Seed 1 sweep by sweep, seed 2 with momentum (the oracle after every sweep both ways).
      if (seed == 1) {
        for (int sweep = 1; sweep <= 12; ++sweep) {
          relax(p, spacing, rng);
          ASSERT_TRUE(judge(sweep));
        }
      } else {
        int sweeps = 0;
        relax(
            p, spacing, 12, rng, [&](int k) { return ++sweeps == k && judge(k); },
            3);  // threads, whatever the cores
        ASSERT_EQ(sweeps, 12);
      }
      for (const auto& [id, at] : fixed) {
        ASSERT_TRUE(p.alive(id));
        EXPECT_EQ(squared_norm(p.center(id) - at), 0.0);
      }
      const SurfaceMesh mesh = restricted_delaunay(p);
      std::vector<std::array<std::size_t, 3>> tris;
      for (const auto& t : mesh.triangles) tris.push_back({t[0], t[1], t[2]});
      const oracle::TopologyReport got = oracle::check_topology(mesh.vertices.size(), tris);
      EXPECT_TRUE(got.manifold() && got.genus == want.genus && got.boundary_loops == want.boundary_loops)
          << file << " " << spec << " seed " << seed << ": " << got.summary();
      const test::AngleShares after = test::angle_shares(mesh);
      std::printf("[ relax ] %s %s seed %llu, %zu disks: angles in [50,70] %.3f -> %.3f, obtuse %.3f -> %.3f\n", file,
                  spec, static_cast<unsigned long long>(seed), n, before.near_60, after.near_60, before.obtuse,
                  after.obtuse);
      EXPECT_GT(after.near_60, before.near_60 + gain) << file << " " << spec << " seed " << seed;
      EXPECT_LT(after.obtuse, obtuse * before.obtuse) << file << " " << spec << " seed " << seed;
    }
  }
}

// Disks far apart move on separate threads, each seeing what it would see alone: the same
// packing, bit for bit, for any number of threads (more than the cores too, which
// interleaves them more), and valid by the oracle (after every sweep on three threads in
// the test above). One radius and a sizing, features, a boundary, and a long spacing (the
// springs then reach farthest).
TEST(Relaxation, GivesTheSamePackingOnAnyNumberOfThreads) {
  struct Case {
    const char* file;
    const char* spec;
    double spacing;  // 0: the packing's hexagonal spacing
  };
  const Case cases[] = {{"fandisk.off", "0.04", 0},
                        {"fandisk.off", "auto:0.05", 0},
                        {"mesh_with_border.off", "0.35", 0},
                        {"elephant.off", "0.015", 2.5}};
  for (const auto& [file, spec, wide] : cases) {
    SurfaceDomain d = *test::surface_file(file);
    d.set_features(detect_features(d, {60, 60, 0}));
    const auto surface = std::make_shared<const SurfaceDomain>(std::move(d));
    Rng rng(4);
    const SurfacePacking start = sample_mps(surface, parse_surface_sizing(spec, *surface), rng);
    const double spacing =
        wide > 0 ? wide : hex_spacing(static_cast<double>(start.size()) / density_unit(start));
    std::vector<Vec3> one_thread;
    std::size_t one_thread_moved = 0;
    for (const unsigned threads : {1u, 2u, 3u, 7u}) {
      SurfacePacking p = start;
      Rng same(9);
      const std::size_t moved = relax(p, spacing, 6, same, {}, threads);
      std::vector<Vec3> centers;
      for (const DiskId id : p.ids()) centers.push_back(p.center(id));
      ASSERT_EQ(centers.size(), start.size());
      if (threads == 1) {
        one_thread = centers, one_thread_moved = moved;
        EXPECT_GT(moved, start.size()) << file << " " << spec;  // it did move them
        const auto rep = test::surface_report(p);
        EXPECT_TRUE(rep.ok()) << file << " " << spec << ": " << rep.summary();
        continue;
      }
      EXPECT_EQ(moved, one_thread_moved) << file << " " << spec << ", " << threads << " threads";
      std::size_t differ = 0;
      for (std::size_t i = 0; i < centers.size(); ++i)
        differ += centers[i].x != one_thread[i].x || centers[i].y != one_thread[i].y ||
                  centers[i].z != one_thread[i].z;
      EXPECT_EQ(differ, 0u) << file << " " << spec << ", " << threads << " threads";
    }
  }
}

// Maximality::at_end: moves checked for conflicts only, then the voids they opened closed.
// The result passes the oracle, keeps the count and the fixed disks, is the same on any
// number of threads, and meshes as well as checking every move does. At least some of
// the runs must close their voids (a result equal to every_move's, bit for bit, is the
// fall-back's: the test would not reach the closing at all).
TEST(Relaxation, AtTheEndLeavesAValidPackingMeshedAsWellAsCheckingEveryMove) {
  struct Case {
    const char* file;
    const char* spec;
  };
  const Case cases[] = {{"fandisk.off", "0.04"},
                        {"fandisk.off", "auto:0.05"},
                        {"mesh_with_border.off", "0.35"},
                        {"elephant.off", "0.012"},
                        {"eight.off", "0.02"}};
  std::size_t closed = 0, runs = 0;
  for (const auto& [file, spec] : cases) {
    SurfaceDomain d = *test::surface_file(file);
    d.set_features(detect_features(d, {60, 60, 0}));
    const auto surface = std::make_shared<const SurfaceDomain>(std::move(d));
    for (const std::uint64_t seed : {1, 2}) {
      Rng rng(seed);
      const SurfacePacking start = sample_mps(surface, parse_surface_sizing(spec, *surface), rng);
      const double spacing = hex_spacing(static_cast<double>(start.size()) / density_unit(start));
      const std::string what = std::string(file) + " " + spec + " seed " + std::to_string(seed);
      SurfacePacking every = start;
      Rng every_rng(9);
      relax(every, spacing, 12, every_rng, {}, 1, Maximality::every_move);
      std::vector<Vec3> first;
      for (const unsigned threads : {1u, 3u}) {
        SurfacePacking p = start;
        Rng same(9);
        relax(p, spacing, 12, same, {}, threads, Maximality::at_end);
        std::vector<Vec3> centers;
        for (const DiskId id : p.ids()) centers.push_back(p.center(id));
        if (threads > 1) {
          EXPECT_TRUE(centers == first) << what << ": " << threads << " threads differ from one";
          continue;
        }
        first = centers;
        ASSERT_EQ(p.size(), start.size()) << what;
        const auto rep = test::surface_report(p);
        EXPECT_TRUE(rep.ok()) << what << ": " << rep.summary();
        for (const DiskId id : start.ids()) {
          if (!(start.flags(id) & kFixed)) continue;
          EXPECT_EQ(squared_norm(p.center(id) - start.center(id)), 0.0) << what;
        }
        std::size_t same_as_every = 0;  // a disk put in a void may take a new id
        for (const DiskId id : p.ids()) {
          same_as_every += id < every.id_bound() && every.alive(id) &&
                           squared_norm(p.center(id) - every.center(id)) == 0;
        }
        closed += same_as_every < p.size();
        ++runs;
        const test::AngleShares at_end = test::angle_shares(restricted_delaunay(p));
        const test::AngleShares checked = test::angle_shares(restricted_delaunay(every));
        std::printf(
            "[ relax ] %s, %zu disks, 12 sweeps: angles in [50,70] %.3f (every move checked %.3f), "
            "obtuse "
            "%.4f (%.4f)%s\n",
            what.c_str(), p.size(), at_end.near_60, checked.near_60, at_end.obtuse, checked.obtuse,
            same_as_every == p.size() ? ", fell back" : "");
        // Beside an open boundary the moves stay checked: there a closer margin, which
        // moves unchecked there too miss (0.766 / 0.781 against 0.778 / 0.793).
        const double margin = std::string(file) == "mesh_with_border.off" ? 0.005 : 0.02;
        EXPECT_GT(at_end.near_60, checked.near_60 - margin) << what;
        EXPECT_LT(at_end.obtuse, checked.obtuse + 0.01) << what;
      }
    }
  }
  EXPECT_GE(closed, runs - 2) << "most runs should close their voids without falling back";
}

// mesh_with_border at r = 0.35, seed 12: the springs press a free disk against the open
// boundary's fixed disks and leave a sliver of void between them that no checked pull
// can close (each disk near it is held on all sides). Until 2026-12-06 such a run fell
// back to checking every move from the start (twice the time: remesh of
// mesh_with_border at 10^4 vertices, seed 2, 0.84 s against 0.39); now the nearest disk
// is pulled over the sliver unchecked and the void it leaves behind closes among disks
// with room. The packing must pass the oracle, keep its fixed disks and count, and
// differ from what checking every move gives (a fallback would give exactly that).
// Since 2026-12-07 a void two rounds leave open gets a disk of its own first: turned off
// here, to reach the pull.
TEST(Relaxation, AtTheEndPullsADiskOverAVoidHeldOnAllSides) {
  SurfaceDomain d = *test::surface_file("mesh_with_border.off");
  d.set_features(detect_features(d, {60, 60, 0}));
  const auto surface = std::make_shared<const SurfaceDomain>(std::move(d));
  Rng rng(12);
  const SurfacePacking start = sample_mps(surface, SurfaceSizing::constant(0.35), rng);
  const double spacing = hex_spacing(static_cast<double>(start.size()) / density_unit(start));
  SurfacePacking at_end = start, every = start;
  Rng a(9), b(9);
  detail::relax_at_end(at_end, spacing, 30, a, {}, 1, detail::kNeverInject);
  relax(every, spacing, 30, b, {}, 1, Maximality::every_move);
  ASSERT_EQ(at_end.size(), start.size());
  const auto rep = test::surface_report(at_end);
  EXPECT_TRUE(rep.ok()) << rep.summary();
  std::size_t same = 0;
  for (const DiskId id : at_end.ids()) {
    same += squared_norm(at_end.center(id) - every.center(id)) == 0;
    if (start.flags(id) & kFixed) {
      EXPECT_EQ(squared_norm(at_end.center(id) - start.center(id)), 0.0);
    }
  }
  EXPECT_LT(same, at_end.size()) << "the run fell back to checking every move";
}

// Spring lengths of three and four radii jam the disks into rings around voids none of
// them can reach without meeting another: such voids will not close by moves (a disk
// of their own turned off here), and the sweeps run again with every move checked,
// from the same start and random state: every_move's packing, bit for bit, and its
// move count and random state after. Runs that do close their voids must pass the
// oracle all the same; at least one run must fall back.
TEST(Relaxation, AtTheEndFallsBackToCheckingEveryMoveWhereVoidsWillNotClose) {
  const auto surface = test::surface_file("elephant.off");
  std::size_t fell_back = 0;
  for (const std::uint64_t seed : {1, 2}) {
    Rng rng(seed);
    const SurfacePacking start = sample_mps(surface, SurfaceSizing::constant(0.015), rng);
    for (const double spacing : {3.0, 4.0}) {
      SurfacePacking every = start, at_end = start;
      Rng a(9), b(9);
      const std::size_t every_moved = relax(every, spacing, 12, a, {}, 2, Maximality::every_move);
      const std::size_t at_end_moved =
          detail::relax_at_end(at_end, spacing, 12, b, {}, 2, detail::kNeverInject);
      ASSERT_EQ(at_end.size(), every.size());
      const auto rep = test::surface_report(at_end);
      EXPECT_TRUE(rep.ok()) << "seed " << seed << ", spacing " << spacing << ": " << rep.summary();
      std::size_t differ = 0;
      for (const DiskId id : every.ids())
        differ += squared_norm(at_end.center(id) - every.center(id)) > 0;
      if (differ > 0) continue;  // closed
      ++fell_back;
      EXPECT_EQ(at_end_moved, every_moved) << "seed " << seed << ", spacing " << spacing;
      EXPECT_EQ(uniform01(a), uniform01(b))
          << "the fall-back starts from the caller's random state";
    }
  }
  std::printf("[ relax ] spring lengths 3 and 4 r, seeds 1-2: %zu of 4 runs fell back\n",
              fell_back);
  EXPECT_GT(fell_back, 0u)
      << "no run fell back: the test needs a packing whose voids will not close";
}

// The same jammed rings with Maximality::at_end as relax runs it: a void that two rounds
// of pulls leave open gets a disk of its own, and a disk near it is ejected, so no run
// falls back. Each keeps its count and fixed disks, passes the oracle, is the same on
// one and three threads and differs from every_move's packing; in some, disks were
// exchanged (a disk of the start gone). mesh_with_border's run is the one whose sliver
// beside the boundary no checked pull closes (above).
TEST(Relaxation, AtTheEndGivesAVoidNoMoveClosesADiskOfItsOwn) {
  struct Case {
    const char* file;
    double r;
    std::uint64_t seed;
    double spacing;  // 0: a hexagonal packing's
    int sweeps;
  };
  const Case cases[] = {{"elephant.off", 0.015, 1, 3.0, 12},
                        {"elephant.off", 0.015, 1, 4.0, 12},
                        {"elephant.off", 0.015, 2, 3.0, 12},
                        {"elephant.off", 0.015, 2, 4.0, 12},
                        {"mesh_with_border.off", 0.35, 12, 0, 30}};
  std::size_t exchanged_runs = 0;
  for (const Case& c : cases) {
    SurfaceDomain d = *test::surface_file(c.file);
    d.set_features(detect_features(d, {60, 60, 0}));
    const auto surface = std::make_shared<const SurfaceDomain>(std::move(d));
    Rng rng(c.seed);
    const SurfacePacking start = sample_mps(surface, SurfaceSizing::constant(c.r), rng);
    const double spacing =
        c.spacing > 0 ? c.spacing
                      : hex_spacing(static_cast<double>(start.size()) / density_unit(start));
    const std::string what = std::string(c.file) + " seed " + std::to_string(c.seed) +
                             ", spacing " + std::to_string(spacing);
    SurfacePacking every = start;
    Rng b(9);
    relax(every, spacing, c.sweeps, b, {}, 1, Maximality::every_move);
    std::vector<Vec3> first;
    for (const unsigned threads : {1u, 3u}) {
      SurfacePacking at_end = start;
      Rng a(9);
      relax(at_end, spacing, c.sweeps, a, {}, threads, Maximality::at_end);
      std::vector<Vec3> centers;
      for (const DiskId id : at_end.ids()) centers.push_back(at_end.center(id));
      if (threads > 1) {
        EXPECT_TRUE(centers == first) << what << ": " << threads << " threads differ from one";
        continue;
      }
      first = centers;
      ASSERT_EQ(at_end.size(), start.size()) << what;
      const auto rep = test::surface_report(at_end);
      EXPECT_TRUE(rep.ok()) << what << ": " << rep.summary();
      std::size_t gone = 0, same_as_every = 0;
      for (const DiskId id : start.ids()) {
        gone += !at_end.alive(id);
        if (start.flags(id) & kFixed) {
          ASSERT_TRUE(at_end.alive(id)) << what;
          EXPECT_EQ(squared_norm(at_end.center(id) - start.center(id)), 0.0) << what;
        }
        same_as_every += at_end.alive(id) && every.alive(id) &&
                         squared_norm(at_end.center(id) - every.center(id)) == 0;
      }
      EXPECT_LT(same_as_every, start.size()) << what << ": fell back to checking every move";
      exchanged_runs += gone > 0;
      std::printf("[ relax ] %s: %zu disks of %zu exchanged\n", what.c_str(), gone, start.size());
    }
  }
  EXPECT_GT(exchanged_runs, 0u) << "no run put a disk in a void: the test does not reach it";
}

// After relaxation about one triangle in a hundred is obtuse; moving the vertex of each
// obtuse angle out of the circle over the opposite edge leaves far fewer, keeps the
// packing valid (oracle), the fixed disks and the mesh's topology, and the share of
// angles near 60 degrees.
TEST(Relaxation, OpeningObtuseAnglesLeavesFewerObtuseTrianglesAndAValidPacking) {
  const std::pair<const char*, double> cases[] = {{"eight.off", 0.02}, {"elephant.off", 0.012}};
  for (const auto& [file, r] : cases) {
    SurfaceDomain d = *test::surface_file(file);
    d.set_features(detect_features(d, {60, 60, 0}));
    const auto surface = std::make_shared<const SurfaceDomain>(std::move(d));
    Rng rng(3);
    SurfacePacking p = sample_mps(surface, SurfaceSizing::constant(r), rng);
    const std::size_t n = p.size();
    const double spacing = hex_spacing(static_cast<double>(n) / density_unit(p));
    for (int sweep = 0; sweep < 20; ++sweep) relax(p, spacing, rng);
    std::map<DiskId, Vec3> fixed;
    for (const DiskId id : p.ids())
      if (p.flags(id) & kFixed) fixed[id] = p.center(id);
    const SurfaceMesh mesh = restricted_delaunay(p);
    const test::AngleShares before = test::angle_shares(mesh);
    EXPECT_GT(open_obtuse_angles(p, mesh), 0u) << file;
    ASSERT_EQ(p.size(), n);
    const auto rep = test::surface_report(p);
    ASSERT_TRUE(rep.ok()) << file << ": " << rep.summary();
    for (const auto& [id, at] : fixed) EXPECT_EQ(squared_norm(p.center(id) - at), 0.0);
    const SurfaceMesh opened = restricted_delaunay(p);
    std::vector<std::array<std::size_t, 3>> tris;
    for (const auto& t : opened.triangles) tris.push_back({t[0], t[1], t[2]});
    const oracle::TopologyReport got = oracle::check_topology(opened.vertices.size(), tris);
    EXPECT_TRUE(got.manifold() && got.genus == surface->genus()) << file << ": " << got.summary();
    const test::AngleShares after = test::angle_shares(opened);
    std::printf("[ relax ] %s r %g, %zu disks, 20 sweeps, then obtuse angles opened: obtuse %.4f -> %.4f, angles in "
                "[50,70] %.3f -> %.3f\n",
                file, r, n, before.obtuse, after.obtuse, before.near_60, after.near_60);
    EXPECT_LT(after.obtuse, 0.6 * before.obtuse) << file;
    EXPECT_GT(after.near_60, before.near_60 - 0.01) << file;
    SurfaceMesh wrong = opened;
    wrong.vertices.pop_back();
    EXPECT_THROW(open_obtuse_angles(p, wrong), InvalidInput);
  }
}

// An obtuse angle at a fixed disk (a feature curve's) cannot be opened by moving that
// disk: one of the other two moves toward the far side instead.
TEST(Relaxation, ObtuseAnglesAtFixedDisksAreOpenedByTheirNeighbours) {
  SurfaceDomain d = *test::surface_file("fandisk.off");
  d.set_features(detect_features(d, {60, 60, 0}));
  const auto surface = std::make_shared<const SurfaceDomain>(std::move(d));
  for (const std::uint64_t seed : {1, 2}) {
    Rng rng(seed);
    SurfacePacking p = sample_mps(surface, SurfaceSizing::constant(0.03), rng);
    const double spacing = hex_spacing(static_cast<double>(p.size()) / density_unit(p));
    for (int sweep = 0; sweep < 15; ++sweep) relax(p, spacing, rng);
    std::map<DiskId, Vec3> fixed;
    for (const DiskId id : p.ids())
      if (p.flags(id) & kFixed) fixed[id] = p.center(id);
    // Obtuse angles whose vertex is a fixed disk, by plain geometry on the mesh.
    const auto obtuse_at_fixed = [&](const SurfaceMesh& m) {
      const std::vector<DiskId> ids = p.ids();
      std::size_t n = 0;
      for (const auto& t : m.triangles)
        for (int k = 0; k < 3; ++k) {
          const Vec3 v = m.vertices[t[k]], a = m.vertices[t[(k + 1) % 3]], b = m.vertices[t[(k + 2) % 3]];
          n += fixed.count(ids[t[k]]) && dot(a - v, b - v) < 0;
        }
      return n;
    };
    const SurfaceMesh mesh = restricted_delaunay(p);
    const std::size_t before = obtuse_at_fixed(mesh);
    open_obtuse_angles(p, mesh);
    const auto rep = test::surface_report(p);
    ASSERT_TRUE(rep.ok()) << "seed " << seed << ": " << rep.summary();
    for (const auto& [id, at] : fixed) EXPECT_EQ(squared_norm(p.center(id) - at), 0.0);
    const std::size_t after = obtuse_at_fixed(restricted_delaunay(p));
    std::printf("[ relax ] fandisk r 0.03 seed %llu: obtuse angles at fixed disks %zu -> %zu\n",
                static_cast<unsigned long long>(seed), before, after);
    // Measured: 96 -> 82 and 91 -> 77; moving only the vertex, 96 -> 95 and 91 -> 91.
    EXPECT_GT(before, 10u);
    EXPECT_LT(after, 0.9 * static_cast<double>(before));
  }
}

// open_sharp_angles: after it the packing passes the oracle with its count and fixed
// disks, and the new mesh has fewer angles below the threshold (counted here by plain
// geometry) and none below the old smallest; and fixed disks at a sharp angle make one of
// the other two move (fandisk's creases).
TEST(Relaxation, OpeningSharpAnglesLeavesFewerSharpAnglesAndAValidPacking) {
  const std::pair<const char*, double> cases[] = {
      {"eight.off", 0.02}, {"elephant.off", 0.012}, {"fandisk.off", 0.03}};
  constexpr double kSharp = 40;
  const auto sharp = [&](const SurfaceMesh& m, double& smallest) {
    std::size_t n = 0;
    smallest = 180;
    for (const auto& t : m.triangles)
      for (int k = 0; k < 3; ++k) {
        const Vec3 v = m.vertices[t[k]], a = m.vertices[t[(k + 1) % 3]] - v,
                   b = m.vertices[t[(k + 2) % 3]] - v;
        const double degrees =
            std::acos(dot(a, b) / (norm(a) * norm(b))) * 180 / 3.14159265358979323846;
        smallest = std::min(smallest, degrees);
        n += degrees < kSharp;
      }
    return n;
  };
  for (const auto& [file, r] : cases) {
    SurfaceDomain d = *test::surface_file(file);
    d.set_features(detect_features(d, {60, 60, 0}));
    const auto surface = std::make_shared<const SurfaceDomain>(std::move(d));
    Rng rng(4);
    SurfacePacking p = sample_mps(surface, SurfaceSizing::constant(r), rng);
    const std::size_t n = p.size();
    const double spacing = hex_spacing(static_cast<double>(n) / density_unit(p));
    for (int sweep = 0; sweep < 15; ++sweep) relax(p, spacing, rng);
    std::map<DiskId, Vec3> fixed;
    for (const DiskId id : p.ids())
      if (p.flags(id) & kFixed) fixed[id] = p.center(id);
    const SurfaceMesh mesh = restricted_delaunay(p);
    double smallest_before = 0, smallest_after = 0;
    const std::size_t before = sharp(mesh, smallest_before);
    EXPECT_GT(open_sharp_angles(p, mesh, kSharp), 0u) << file;
    ASSERT_EQ(p.size(), n);
    const auto rep = test::surface_report(p);
    ASSERT_TRUE(rep.ok()) << file << ": " << rep.summary();
    for (const auto& [id, at] : fixed) EXPECT_EQ(squared_norm(p.center(id) - at), 0.0) << file;
    const std::size_t after = sharp(restricted_delaunay(p), smallest_after);
    std::printf(
        "[ relax ] %s r %g, %zu disks, 15 sweeps, then sharp angles opened: angles below %g "
        "degrees %zu -> %zu, "
        "smallest %.2f -> %.2f\n",
        file, r, n, kSharp, before, after, smallest_before, smallest_after);
    // Measured (one pass): eight 16 -> 13, elephant 198 -> 114, fandisk 258 -> 160.
    EXPECT_GT(before, 10u) << file;
    EXPECT_LT(static_cast<double>(after), 0.9 * static_cast<double>(before)) << file;
    EXPECT_GE(smallest_after, smallest_before) << file;
    SurfaceMesh wrong = mesh;
    wrong.vertices.pop_back();
    EXPECT_THROW(open_sharp_angles(p, wrong, kSharp), InvalidInput);
    EXPECT_THROW(open_sharp_angles(p, restricted_delaunay(p), 60), InvalidInput);
    EXPECT_THROW(open_sharp_angles(p, restricted_delaunay(p), 0), InvalidInput);
  }
}

TEST(Relaxation, RefusesASpacingThatIsNotPositive) {
  const PeriodicBox box(1, 1);
  Rng rng(1);
  Packing p = sample_mps(box, 0.1, rng);
  EXPECT_THROW(relax(p, 0, rng), InvalidInput);
  EXPECT_THROW(relax(p, -1, rng), InvalidInput);
  EXPECT_THROW(relax(p, std::nan(""), rng), InvalidInput);
}

}  // namespace
}  // namespace disktune
