// SPDX-License-Identifier: GPL-3.0-or-later
// The last line of defence: tune checks the packing it hands back, and a packing that
// fails (a bug) is an InternalError naming the check and the place, with the packing
// put back to a valid state. A bug is simulated by a test hook that lifts disks in the
// middle of the tuning (after_operation gets the packing being tuned); the independent
// oracles judge what is handed back.
#include <gtest/gtest.h>

#include <memory>
#include <string>

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

}  // namespace
}  // namespace disktune
