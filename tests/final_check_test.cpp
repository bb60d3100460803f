// SPDX-License-Identifier: GPL-3.0-or-later
// The last line of defence: tune checks the packing it hands back, and a packing that
// fails (a bug) is an InternalError naming the check and the place, with the packing
// put back to a valid state. A bug is simulated by a test hook that lifts disks in the
// middle of the tuning (after_operation gets the packing being tuned); the independent
// oracles judge what is handed back.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "disktune/planar_domain.h"
#include "disktune/sampling.h"
#include "disktune/surface_tuning.h"
#include "disktune/surface_voids.h"
#include "disktune/tuning.h"
#include "disktune/voids.h"
#include "oracle/planar_oracle.h"
#include "planar_checks.h"
#include "surface_checks.h"
#include "test_util.h"

namespace disktune {
namespace {

bool mentions(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Lifts a disk that can move after every 20th operation: the voids it leaves are what a
// buggy operation could leave (later operations repair only their own surroundings).
template <class P>
auto lift_now_and_then(std::size_t& operations) {
  return [&operations](const P& now) {
    if (++operations % 20 != 0) return;
    P& packing = const_cast<P&>(now);  // the packing tune works on, not a const object
    for (const DiskId id : packing.ids())
      if (!(packing.flags(id) & (kFixed | kFrozen))) return packing.remove(id);
  };
}

TEST(FinalCheck, ATuneLeavingAHoleIsAnInternalErrorAndHandsBackTheValidPacking) {
  const PeriodicBox box(1, 1);
  Rng rng(3);
  Packing packing = sample_mps(box, 0.03, rng);
  const Packing sampled = packing;
  TuneOptions options;
  options.method = Method::void_injection;
  std::size_t operations = 0;
  options.after_operation = lift_now_and_then<Packing>(operations);
  const std::string message = test::message_of<InternalError>(
      [&] { tune(packing, box, Target::count(sampled.size() * 5 / 4), rng, options); });
  EXPECT_TRUE(mentions(message, "the packing after the void injection phase failed the final check: not maximal"))
      << message;
  EXPECT_TRUE(mentions(message, "is covered by no disk")) << message;
  EXPECT_TRUE(mentions(message, "bug in disktune")) << message;
  // One phase ran: the packing before it is the sample, passed by the oracle.
  EXPECT_TRUE(mentions(message, "put back as it was before that phase (" + std::to_string(sampled.size()) + " disks)"))
      << message;
  ASSERT_EQ(packing.size(), sampled.size());
  for (const DiskId id : sampled.ids()) EXPECT_EQ(packing.center(id), sampled.center(id));
  const auto report = oracle::check_all(test::box_of(box), 0.03, test::centers_of(packing), 1e-6, 3000, 1);
  EXPECT_TRUE(report.conflict_free() && report.maximal()) << report.summary();
}

TEST(FinalCheck, APlanarTuneLeavingAHoleHandsBackAValidPacking) {
  const auto domain = std::make_shared<const PlanarDomain>(
      read_poly(std::string(DISKTUNE_DATA_DIR) + "/domains/square_with_hole.poly"));
  Rng rng(4);
  Packing packing = sample_mps(domain, 0.04, rng);
  TuneOptions options;
  options.method = Method::void_injection;
  std::size_t operations = 0;
  options.after_operation = lift_now_and_then<Packing>(operations);
  const std::string message = test::message_of<InternalError>(
      [&] { tune(packing, *domain, Target::count(packing.size() * 5 / 4), rng, options); });
  EXPECT_TRUE(mentions(message, "failed the final check: not maximal")) << message;
  oracle::Points centers;
  oracle::PlanarOptions opt;
  for (const DiskId id : packing.ids()) {
    centers.push_back({packing.center(id).x, packing.center(id).y});
    opt.boundary_flags.push_back((packing.flags(id) & kFixed) != 0);
  }
  const auto report = oracle::check_planar(test::oracle_domain(*domain), centers, 0.04, opt);
  EXPECT_TRUE(report.ok()) << report.summary();
}

TEST(FinalCheck, ASurfaceTuneLeavingAHoleHandsBackAValidPacking) {
  const auto domain = test::surface_file("eight.off");
  Rng rng(5);
  SurfacePacking packing = sample_mps(domain, SurfaceSizing::constant(0.05), rng);
  const std::size_t sampled = packing.size();
  TuneOptions options;
  options.method = Method::void_injection;
  std::size_t operations = 0;
  options.after_surface_operation = lift_now_and_then<SurfacePacking>(operations);
  const std::string message =
      test::message_of<InternalError>([&] { tune(packing, Target::count(sampled * 5 / 4), rng, options); });
  EXPECT_TRUE(mentions(message, "failed the final check: not maximal: the point (")) << message;
  EXPECT_TRUE(mentions(message, " of triangle ")) << message;
  EXPECT_TRUE(mentions(message, " is covered by no disk")) << message;
  EXPECT_EQ(packing.size(), sampled);
  EXPECT_SURFACE_OK(packing);
}

// The defect is named the way validate_* names it for an input, and is empty for a
// valid packing.
TEST(FinalCheck, PackingDefectNamesTheCheckAndThePlace) {
  const PeriodicBox box(1, 1);
  Rng rng(6);
  Packing packing = sample_mps(box, 0.05, rng);
  EXPECT_EQ(packing_defect(packing), "");
  packing.remove(packing.ids()[7]);
  EXPECT_TRUE(mentions(packing_defect(packing), "not maximal: the point (")) << packing_defect(packing);

  const auto domain = test::surface_file("sphere.off");
  SurfacePacking on_sphere = sample_mps(domain, SurfaceSizing::constant(0.2), rng);
  EXPECT_EQ(packing_defect(on_sphere), "");
  on_sphere.insert(on_sphere.point(on_sphere.ids()[3]));  // a second disk on one center
  EXPECT_TRUE(mentions(packing_defect(on_sphere), "cover each other's centers (a conflict)"))
      << packing_defect(on_sphere);
}

// The checks search on every core but name what a search in order would: the first disk
// (in id order) with a corner on its circle, the first disk in a conflict, the first
// triangle holding a void point, with defects spread over many chunks of the search.
// Asked ten times each, the answer never changes.
TEST(FinalCheck, TheFirstDefectInOrderIsNamedWhateverTheCores) {
  const PeriodicBox box(1, 1);
  Rng rng(8);
  const double r = 0.01;
  Packing holes = sample_mps(box, r, rng);
  const std::vector<DiskId> ids = holes.ids();
  ASSERT_GT(ids.size(), 5000u);
  for (const std::size_t k : {ids.size() - 3, ids.size() / 2 + 11, ids.size() / 3 + 300, 1500ul})
    holes.remove(ids[k]);
  // In order: the first disk with an uncovered corner on its circle (corners_on_circle),
  // its first corner; the oracle confirms no disk covers that point.
  std::string expected;
  Vec2 expected_at{};
  for (const DiskId id : holes.ids()) {
    std::vector<Corner> corners;
    corners_on_circle(holes, id, corners);
    if (corners.empty()) continue;
    const Vec2 at = box.wrap(corners.front().point);
    for (const DiskId other : holes.ids()) {
      const Vec2 d = box.wrap(holes.center(other) - at + Vec2{0.5, 0.5}) - Vec2{0.5, 0.5};
      ASSERT_GE(std::sqrt(d.x * d.x + d.y * d.y), r * (1 - 1e-9))
          << "disk " << other << " covers the corner";
    }
    expected = "not maximal: the point (", expected_at = at;
    break;
  }
  ASSERT_FALSE(expected.empty());
  const std::string first = packing_defect(holes);
  double hx = 0, hy = 0;
  ASSERT_EQ(std::sscanf(first.c_str(), "not maximal: the point (%lf, %lf)", &hx, &hy), 2) << first;
  EXPECT_EQ(hx, expected_at.x) << first;
  EXPECT_EQ(hy, expected_at.y) << first;
  for (int k = 0; k < 10; ++k) EXPECT_EQ(packing_defect(holes), first);

  // Conflicts: disks put on the centers of disks far apart in id order; the first named
  // is the first id, in id order, with another disk closer than r (brute force).
  Packing crowded = sample_mps(box, r, rng);
  const std::vector<DiskId> before = crowded.ids();
  for (const std::size_t k : {before.size() - 5, before.size() / 2, 1300ul, 700ul})
    crowded.insert(box.wrap(crowded.center(before[k]) + Vec2{0.1 * r, 0}), r);
  DiskId first_in_conflict = kNoDisk;
  for (const DiskId a : crowded.ids()) {
    for (const DiskId b : crowded.ids()) {
      if (a == b) continue;
      const Vec2 d =
          box.wrap(crowded.center(b) - crowded.center(a) + Vec2{0.5, 0.5}) - Vec2{0.5, 0.5};
      if (std::sqrt(d.x * d.x + d.y * d.y) < r * (1 - 1e-9)) first_in_conflict = a;
      if (first_in_conflict != kNoDisk) break;
    }
    if (first_in_conflict != kNoDisk) break;
  }
  ASSERT_NE(first_in_conflict, kNoDisk);
  const std::string conflict = packing_defect(crowded);
  EXPECT_TRUE(mentions(conflict, "cover each other's centers")) << conflict;
  double x = 0, y = 0;  // every digit is printed: the center reads back exactly
  ASSERT_EQ(std::sscanf(conflict.c_str(), "the disks centered at (%lf, %lf)", &x, &y), 2)
      << conflict;
  EXPECT_EQ(x, crowded.center(first_in_conflict).x) << conflict;
  EXPECT_EQ(y, crowded.center(first_in_conflict).y) << conflict;
  for (int k = 0; k < 10; ++k) EXPECT_EQ(packing_defect(crowded), conflict);

  // A surface: the first triangle, in index order, holding a void point.
  const auto elephant = test::surface_file("elephant.off");
  SurfacePacking lifted = sample_mps(elephant, SurfaceSizing::constant(0.01), rng);
  const std::vector<DiskId> on = lifted.ids();
  for (const std::size_t k : {on.size() - 2, on.size() / 2, 900ul}) lifted.remove(on[k]);
  std::size_t first_triangle = elephant->triangles().size();
  for (std::size_t t = 0;
       t < elephant->triangles().size() && first_triangle == elephant->triangles().size(); ++t) {
    std::vector<SurfaceVoidPoint> found;
    void_points_in_triangle(lifted, t, {}, found);
    if (!found.empty()) first_triangle = t;
  }
  ASSERT_LT(first_triangle, elephant->triangles().size());
  const std::string hole = packing_defect(lifted);
  EXPECT_TRUE(mentions(hole, " of triangle " + std::to_string(first_triangle) + " ")) << hole;
  for (int k = 0; k < 10; ++k) EXPECT_EQ(packing_defect(lifted), hole);
}

}  // namespace
}  // namespace disktune
