// SPDX-License-Identifier: GPL-3.0-or-later
// The surface ejection's shortcuts against the searches they stand for
// (docs/tuning.md, "Fewer void scans in surface ejection"): sifting's pair test from
// q's center against the test on a fresh scan of q's own void, and an attractor pull
// (nearest positions only, no scan of where q was) against the nearest of all covering
// positions, with one radius and with radii that vary, the packing then checked by the
// independent oracle on every sixteenth.
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "../src/tuning/space.h"
#include "disktune/surface_features.h"
#include "disktune/surface_sampling.h"
#include "disktune/surface_sizing.h"
#include "surface_checks.h"

namespace disktune {
namespace {

using S = detail::Space<SurfacePacking>;

double diagonal(const SurfaceDomain& d) { return norm(d.bbox_max() - d.bbox_min()); }

// A maximal sample of a surface of the test data, fandisk with its creases as patches;
// with `spec`, radii that vary (parse_surface_sizing) instead of share * diagonal.
SurfacePacking sample_of(const std::string& file, double share, std::uint64_t seed,
                         const char* spec = nullptr) {
  SurfaceDomain d = *test::surface_file(file);
  if (file == "fandisk.off") d.set_features(detect_features(d, {60, 60, 0}));
  const auto surface = std::make_shared<const SurfaceDomain>(std::move(d));
  Rng rng(seed);
  return sample_mps(surface,
                    spec ? parse_surface_sizing(spec, *surface)
                         : SurfaceSizing::constant(share * diagonal(*surface)),
                    rng);
}

std::vector<SurfaceVoidPoint> own_void(const SurfacePacking& packing, DiskId p) {
  return detail::voids_near(packing, packing.center(p), detail::void_reach(packing.radius(p)), {p});
}

TEST(EjectionShortcuts, SiftingsPairTestFromTheCenterAgreesWithTheScan) {
  std::size_t decided_early = 0, pairs = 0;
  for (const auto& [file, share] : {std::pair{"eight.off", 0.03}, {"fandisk.off", 0.02}}) {
    const SurfacePacking packing = sample_of(file, share, 5);
    Rng rng(1);
    const double span2 = detail::hold_span(packing) * detail::hold_span(packing);
    for (const DiskId p : packing.ids()) {
      const auto own = own_void(packing, p);
      for (const auto& q :
           S::mobile_neighbors(packing, packing.center(p), packing.radius(p), p, rng)) {
        const bool scanned = detail::wider_than_one_disk(packing, own, own_void(packing, q.id));
        ASSERT_EQ(S::pair_too_wide(packing, own, q), scanned)
            << file << " disks " << p << ", " << q.id;
        bool far = false;  // the case the center decides
        for (const auto& v : own) far = far || squared_norm(v.at.p - q.image) > span2;
        decided_early += far;
        ++pairs;
      }
    }
  }
  // The shortcut is asked often enough to be tested (a fifth of the pairs or more).
  std::printf("[ sift ] %zu of %zu pairs decided from q's center\n", decided_early, pairs);
  EXPECT_GT(decided_early * 5, pairs) << decided_early << " of " << pairs;
}

TEST(EjectionShortcuts, APullGoesToTheNearestCoveringPositionAndKeepsThePackingMaximal) {
  std::size_t moved = 0, stayed = 0;
  struct Case {
    const char* file;
    double share;
    const char* spec;  // radii that vary, or none
  };
  for (const auto& [file, share, spec] :
       {Case{"eight.off", 0.03, nullptr}, Case{"fandisk.off", 0.02, nullptr},
        Case{"fandisk.off", 0, "auto:0.05"}}) {
    const SurfacePacking start = sample_of(file, share, 6, spec);
    Rng rng(2);
    const std::vector<DiskId> ids = start.ids();
    for (std::size_t k = 0; k < ids.size(); k += 7) {
      const DiskId p = ids[k];
      if (start.flags(p) & kFixed) continue;
      const Vec3 to = start.center(p);
      for (const auto& q : S::mobile_neighbors(start, to, start.radius(p), p, rng)) {
        // The nearest of every covering position that meets no disk but p, nearer than q.
        const Vec3 cq = start.center(q.id);
        const auto spots = detail::covering_positions(start, own_void(start, q.id), cq,
                                                      2 * q.radius, q.id, p, &to);
        const SurfacePoint* best = nullptr;
        double best2 = squared_norm(cq - to) * (1 - 1e-9);
        for (const SurfacePoint& s : spots)
          if (squared_norm(s.p - to) < best2) best = &s, best2 = squared_norm(s.p - to);
        SurfacePacking packing = start;
        detail::SurfaceUndoLog log(packing);
        detail::pull_toward(log, packing, q.id, to, p);
        const std::string what =
            std::string(file) + " disk " + std::to_string(q.id) + " toward " + std::to_string(p);
        if (packing.center(q.id) == cq) {
          ++stayed;
          // Nowhere to go, or the place found leaves a void (the check refused it).
          if (best) {
            SurfacePacking there = start;
            there.move(q.id, *best);
            EXPECT_FALSE(detail::void_free_near(there, best->p, q.radius)) << what;
          }
          continue;
        }
        ++moved;
        ASSERT_NE(best, nullptr) << what;
        // The same point up to rounding (the two arrangements make it from other circles).
        EXPECT_LE(norm(packing.center(q.id) - best->p), 1e-9 * q.radius) << what;
        if (moved % 16 != 1) continue;  // the oracle on every sixteenth pull
        // Maximal, and q may enter p's disk only (the attractor then removes or moves p).
        const auto rep = test::surface_report(packing);
        EXPECT_TRUE(rep.on_surface() && rep.maximal()) << what << ": " << rep.summary();
        const std::vector<DiskId> now = packing.ids();
        for (const auto& c : rep.conflicts) {
          const DiskId a = now[c.i], b = now[c.j];
          EXPECT_TRUE((a == p && b == q.id) || (a == q.id && b == p))
              << what << ": " << rep.summary();
        }
      }
    }
  }
  std::printf("[ pull ] %zu pulls moved their disk, %zu left it\n", moved, stayed);
  EXPECT_GT(moved, 50u);
}

}  // namespace
}  // namespace disktune
