// SPDX-License-Identifier: GPL-3.0-or-later
// 1D boundary tuning (paper, section 7) on planar domains and on a surface with an open
// boundary, with one radius and with a sizing, judged by the independent oracles after
// every single step: the whole packing conflict-free and maximal, the boundary disks on
// the boundary covering it, the corner disks where they were.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "disktune/boundary.h"
#include "disktune/planar_domain.h"
#include "disktune/sampling.h"
#include "disktune/sizing.h"
#include "disktune/surface_tuning.h"
#include "oracle/planar_oracle.h"
#include "planar_checks.h"
#include "surface_checks.h"

namespace disktune {
namespace {

constexpr double kPi = 3.14159265358979323846;

// ---- planar ----

struct PlanarCase {
  const char* file;
  bool sized;
};
std::string name(const PlanarCase& c) { return std::string(c.file) + (c.sized ? " (sizing)" : " (one radius)"); }

const PlanarCase kPlanar[] = {{"square_with_hole.poly", false}, {"square_with_hole.poly", true},
                              {"gear.poly", false},             {"gear.poly", true},
                              {"sharp_corners.poly", false},    {"sharp_corners.poly", true}};

std::shared_ptr<const PlanarDomain> poly(const char* file) {
  return std::make_shared<const PlanarDomain>(read_poly(std::string(DISKTUNE_DATA_DIR) + "/domains/" + file));
}

// A radius for about `n` disks, below 0.9 of the closest pair of corners.
double radius_for(const PlanarDomain& d, double n) {
  double r = std::sqrt(0.55 * d.area() / (kPi / 4 * n));
  std::vector<Vec2> corners;
  for (const auto& loop : d.loops()) corners.insert(corners.end(), loop.begin(), loop.end());
  for (std::size_t i = 0; i < corners.size(); ++i)
    for (std::size_t j = i + 1; j < corners.size(); ++j) r = std::min(r, 0.9 * distance(corners[i], corners[j]));
  return r;
}

// A fresh sample: one radius r, or a sizing growing linearly across the domain's
// width from 0.6 r to r (gentle, so no corner lies in another's disk).
Packing planar_sample(const std::shared_ptr<const PlanarDomain>& d, const PlanarCase& c, std::uint64_t seed) {
  Rng rng(seed);
  const double r = radius_for(*d, 300);
  if (!c.sized) return sample_mps(d, r, rng);
  double x0 = 1e300, x1 = -1e300;
  for (const auto& loop : d->loops())
    for (const Vec2 v : loop) x0 = std::min(x0, v.x), x1 = std::max(x1, v.x);
  std::ostringstream e;
  e.precision(17);
  e << r << " * (0.6 + 0.4 * (x - (" << x0 << ")) / " << (x1 - x0) << ")";
  return sample_mps(d, std::make_shared<const Sizing>(expression_sizing(e.str())), rng);
}

// The oracle's verdict; the fixed disks are the boundary disks.
oracle::PlanarReport planar_report(const Packing& p, const PlanarDomain& d, std::size_t probes = 3000) {
  oracle::Points centers;
  std::vector<double> radii;
  oracle::PlanarOptions opt;
  opt.probes = probes;
  for (const DiskId id : p.ids()) {
    centers.push_back({p.center(id).x, p.center(id).y});
    radii.push_back(p.radius(id));
    opt.boundary_flags.push_back((p.flags(id) & kFixed) != 0);
  }
  return oracle::check_planar(test::oracle_domain(d), centers, radii, opt);
}

// Per boundary segment, the fixed disks strictly between its corners (found by plain
// projection, apart from the library's own bookkeeping).
std::vector<long> planar_counts(const Packing& p, const PlanarDomain& d) {
  std::vector<long> out;
  for (const BoundarySegment& s : d.segments()) {
    const Vec2 dir = s.b - s.a;
    const double len = norm(dir);
    long n = 0;
    for (const DiskId id : p.ids()) {
      if (!(p.flags(id) & kFixed)) continue;
      const double t = dot(p.center(id) - s.a, dir) / (len * len);
      const double off = std::abs(cross(dir, p.center(id) - s.a)) / len;
      n += t * len > 1e-7 * p.radius(id) && (1 - t) * len > 1e-7 * p.radius(id) && off < 1e-7 * p.radius(id);
    }
    out.push_back(n);
  }
  return out;
}

// The count a segment should reach at `factor`: round(integral of ds / (factor r)) steps,
// within ceil(L / 2 r_min) .. floor(L / r_max), minus the corner at the end.
template <class RadiusAt>
long curve_goal(double len, double factor, RadiusAt&& r_at, bool closed) {
  double sum = 0, lo_r = 1e300, hi_r = 0;
  for (int k = 0; k < 64; ++k) {
    const double r = r_at((k + 0.5) / 64);
    lo_r = std::min(lo_r, r), hi_r = std::max(hi_r, r);
    sum += len / 64 / (factor * r);
  }
  const double fewest = std::max(std::ceil(len / (2 * lo_r) * (1 - 1e-12)), closed ? 3.0 : 1.0);
  const double most = std::max(std::floor(len / hi_r * (1 + 1e-12)), fewest);
  return static_cast<long>(std::clamp(std::round(sum), fewest, most)) - (closed ? 0 : 1);
}

std::vector<long> planar_goals(const Packing& p, const PlanarDomain& d, double factor) {
  std::vector<long> out;
  for (const BoundarySegment& s : d.segments())
    out.push_back(curve_goal(distance(s.a, s.b), factor, [&](double t) { return p.radius_at(s.a + (s.b - s.a) * t); },
                             false));
  return out;
}

// The disk on each corner: its id and center.
std::vector<std::pair<DiskId, Vec2>> corner_disks(const Packing& p, const PlanarDomain& d) {
  std::vector<std::pair<DiskId, Vec2>> out;
  for (const auto& loop : d.loops())
    for (const Vec2 v : loop)
      for (const DiskId id : p.ids())
        if (p.center(id) == v) out.push_back({id, v});
  return out;
}

void expect_corners_kept(const Packing& p, const std::vector<std::pair<DiskId, Vec2>>& corners) {
  for (const auto& [id, v] : corners) {
    ASSERT_TRUE(p.alive(id));
    EXPECT_TRUE(p.center(id) == v) << "corner disk moved from (" << v.x << ", " << v.y << ")";
    EXPECT_TRUE(p.flags(id) & kFixed);
  }
}

// Single steps at random, the oracle after each: whole packing conflict-free and
// maximal, boundary disks on the boundary with no gap, corner disks where they were.
TEST(BoundaryTuning, PlanarStepsKeepTheInvariants) {
  // Sampling lays the boundary out at most 1.2 r apart, where a 1D injection finds no
  // room on gear's short segments at one radius: the steps must do something somewhere.
  long added = 0, removed = 0;
  for (const PlanarCase& c : kPlanar) {
    SCOPED_TRACE(name(c));
    const auto d = poly(c.file);
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      Packing p = planar_sample(d, c, seed);
      const auto corners = corner_disks(p, *d);
      ASSERT_EQ(corners.size(), d->segments().size());
      Rng rng(100 + seed);
      for (int step = 0; step < 20; ++step) {
        const bool inject = step % 2 == 0;
        const std::size_t before = p.size();
        const long delta = inject ? boundary_inject(p, *d, rng) : boundary_eject(p, *d, rng);
        (delta > 0 ? added : removed) += std::abs(delta);
        EXPECT_TRUE(inject ? delta >= 0 : (delta == 0 || delta == -1));
        const auto report = planar_report(p, *d, 1500);
        ASSERT_TRUE(report.ok() && report.boundary_maximal() && report.on_boundary())
            << "seed " << seed << " step " << step << (inject ? " (injection)" : " (ejection)") << ", " << before
            << " -> " << p.size() << " disks: " << report.summary();
        expect_corners_kept(p, corners);
      }
    }
  }
  EXPECT_GT(added, 0);  // the steps did something
  EXPECT_GT(removed, 0);
}

// tune_boundary moves each segment's count from where it was toward the count of the
// asked spacing, never past it, in both directions; the packing stays valid.
TEST(BoundaryTuning, PlanarCountsMoveTowardTheSpacing) {
  for (const PlanarCase& c : kPlanar) {
    SCOPED_TRACE(name(c));
    const auto d = poly(c.file);
    for (const double factor : {1.05, 1.9}) {
      for (std::uint64_t seed = 1; seed <= 2; ++seed) {
        SCOPED_TRACE("factor " + std::to_string(factor) + " seed " + std::to_string(seed));
        Packing p = planar_sample(d, c, seed);
        const auto corners = corner_disks(p, *d);
        const std::vector<long> before = planar_counts(p, *d), goal = planar_goals(p, *d, factor);
        Rng rng(seed);
        tune_boundary(p, *d, factor, rng);
        const std::vector<long> after = planar_counts(p, *d);
        long miss_before = 0, miss_after = 0;
        for (std::size_t i = 0; i < goal.size(); ++i) {
          EXPECT_GE(after[i], std::min(before[i], goal[i])) << "segment " << i;
          EXPECT_LE(after[i], std::max(before[i], goal[i])) << "segment " << i;
          miss_before += std::abs(before[i] - goal[i]), miss_after += std::abs(after[i] - goal[i]);
        }
        // (gear's segments at 1.05 r: sampling's even layout already holds the goal)
        EXPECT_TRUE(miss_after < miss_before || miss_before == 0) << miss_after << " of " << miss_before;
        // At least three quarters of the way (measured: a seventh of the miss left at
        // worst, on the star's sharp corners at spacing 1.9 r; where a segment keeps one
        // disk more, its count needs steps above 1.9 r).
        EXPECT_LE(miss_after, miss_before / 4) << "from " << miss_before;
        const auto report = planar_report(p, *d, 20000);
        EXPECT_TRUE(report.ok() && report.boundary_maximal() && report.on_boundary()) << report.summary();
        expect_corners_kept(p, corners);
      }
    }
  }
}

TEST(BoundaryTuning, PlanarSameSeedSameResult) {
  const auto d = poly("gear.poly");
  const Packing mps = planar_sample(d, {"gear.poly", true}, 3);
  Packing a = mps, b = mps;
  Rng ra(9), rb(9);
  tune_boundary(a, *d, 1.1, ra);
  tune_boundary(b, *d, 1.1, rb);
  ASSERT_EQ(a.ids(), b.ids());
  for (const DiskId id : a.ids()) EXPECT_TRUE(a.center(id) == b.center(id));
}

// ---- surface ----

double diagonal(const SurfaceDomain& d) { return norm(d.bbox_max() - d.bbox_min()); }

// mesh_with_border.off at one radius, or with radii per vertex growing along x from
// 0.6 r to r.
SurfacePacking surface_sample(const std::shared_ptr<const SurfaceDomain>& d, bool sized, double r, std::uint64_t seed) {
  Rng rng(seed);
  if (!sized) return sample_mps(d, SurfaceSizing::constant(r), rng);
  const double x0 = d->bbox_min().x, dx = d->bbox_max().x - x0;
  std::vector<double> radii;
  for (const Vec3 v : d->vertices()) radii.push_back(r * (0.6 + 0.4 * (v.x - x0) / dx));
  return sample_mps(d, SurfaceSizing::per_vertex(*d, radii), rng);
}

// Per boundary loop, the fixed disks on it (plain distance to its edges).
// Per boundary curve (a loop, or a piece of one between corners), the fixed disks on
// it, an open piece's corner disks left out (found by plain projection).
std::vector<long> surface_counts(const SurfacePacking& p) {
  const SurfaceDomain& d = p.domain();
  std::vector<long> out;
  for (std::size_t c = 0; c < d.first_feature_curve(); ++c) {
    const SurfaceCurve& curve = d.fixed_curves()[c];
    const auto& v = curve.vertices;
    long n = 0;
    for (const DiskId id : p.ids()) {
      if (!(p.flags(id) & kFixed)) continue;
      const double tol = 1e-7 * p.radius(id);
      double best = 1e300;
      for (std::size_t k = 0; k < curve.edge_count(); ++k)
        best = std::min(best, distance_to_segment(p.center(id), d.vertices()[v[k]], d.vertices()[v[(k + 1) % v.size()]]));
      const bool at_end = !curve.closed && (norm(p.center(id) - d.vertices()[v.front()]) < tol ||
                                            norm(p.center(id) - d.vertices()[v.back()]) < tol);
      n += best < tol && !at_end;
    }
    out.push_back(n);
  }
  return out;
}

std::vector<long> surface_goals(const SurfacePacking& p, double factor) {
  const SurfaceDomain& d = p.domain();
  std::vector<long> out;
  for (std::size_t c = 0; c < d.first_feature_curve(); ++c) {
    const SurfaceCurve& curve = d.fixed_curves()[c];
    const auto& v = curve.vertices;
    const std::size_t edges = curve.edge_count();
    std::vector<double> at{0};
    for (std::size_t k = 0; k < edges; ++k) at.push_back(at.back() + norm(d.vertices()[v[(k + 1) % v.size()]] - d.vertices()[v[k]]));
    const double len = at.back();
    out.push_back(curve_goal(len, factor, [&](double u) {
      const std::size_t k = std::min<std::size_t>(std::upper_bound(at.begin(), at.end(), u * len) - at.begin() - 1, edges - 1);
      return p.radius_at(p.index().on_curve(c, k, (u * len - at[k]) / (at[k + 1] - at[k])));
    }, curve.closed));
  }
  return out;
}

TEST(BoundaryTuning, SurfaceStepsKeepTheInvariants) {
  const auto d = test::surface_file("mesh_with_border.off");
  ASSERT_FALSE(d->is_closed());
  for (const bool sized : {false, true}) {
    SCOPED_TRACE(sized ? "per-vertex sizing" : "one radius");
    long added = 0, removed = 0;
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      SurfacePacking p = surface_sample(d, sized, 0.04 * diagonal(*d), seed);
      Rng rng(200 + seed);
      for (int step = 0; step < 16; ++step) {
        const bool inject = step % 2 == 0;
        const long delta = inject ? boundary_inject(p, rng) : boundary_eject(p, rng);
        (delta > 0 ? added : removed) += std::abs(delta);
        const auto report = test::surface_report(p, 2);
        ASSERT_TRUE(report.ok() && report.boundary_ok())
            << "seed " << seed << " step " << step << (inject ? " (injection)" : " (ejection)") << ": "
            << report.summary();
      }
    }
    EXPECT_GT(added, 0);
    EXPECT_GT(removed, 0);
  }
}

TEST(BoundaryTuning, SurfaceCountsMoveTowardTheSpacing) {
  const auto d = test::surface_file("mesh_with_border.off");
  for (const bool sized : {false, true}) {
    for (const double factor : {1.05, 1.9}) {
      for (std::uint64_t seed = 1; seed <= 2; ++seed) {
        SCOPED_TRACE(std::string(sized ? "per-vertex sizing" : "one radius") + " factor " + std::to_string(factor) +
                     " seed " + std::to_string(seed));
        SurfacePacking p = surface_sample(d, sized, 0.03 * diagonal(*d), seed);
        const std::vector<long> before = surface_counts(p), goal = surface_goals(p, factor);
        Rng rng(seed);
        respace_surface_boundary(p, factor, rng);
        const std::vector<long> after = surface_counts(p);
        for (std::size_t l = 0; l < goal.size(); ++l) {
          EXPECT_GE(after[l], std::min(before[l], goal[l])) << "curve " << l;
          EXPECT_LE(after[l], std::max(before[l], goal[l])) << "curve " << l;
          if (before[l] != goal[l]) {
            EXPECT_LT(std::abs(after[l] - goal[l]), std::abs(before[l] - goal[l])) << "curve " << l;
          }
        }
        EXPECT_SURFACE_OK(p);
      }
    }
  }
}

// tune() with a sizing used to skip the boundary; now it tunes it, and still reaches
// its target with the oracle satisfied.
TEST(BoundaryTuning, SurfaceTuneWithASizingMovesTheBoundary) {
  const auto d = test::surface_file("mesh_with_border.off");
  const SurfacePacking mps = surface_sample(d, true, 0.03 * diagonal(*d), 5);
  auto fixed_centers = [](const SurfacePacking& p) {
    std::vector<std::array<double, 3>> out;
    for (const DiskId id : p.ids())
      if (p.flags(id) & kFixed) out.push_back({p.center(id).x, p.center(id).y, p.center(id).z});
    std::sort(out.begin(), out.end());
    return out;
  };
  for (const double factor : {0.7, 1.3}) {
    SCOPED_TRACE("x" + std::to_string(factor));
    SurfacePacking p = mps;
    Rng rng(7);
    const auto goal = static_cast<std::size_t>(std::lround(factor * mps.size()));
    const TuneResult result = tune(p, Target::count(goal), rng);
    EXPECT_TRUE(result.reached) << result.count << " of " << goal;
    EXPECT_EQ(p.size(), goal);
    EXPECT_NE(fixed_centers(p), fixed_centers(mps));
    const auto report = test::surface_report(p);
    EXPECT_TRUE(report.ok() && report.boundary_ok()) << report.summary();
  }
}

TEST(BoundaryTuning, ClosedSurfaceHasNothingToTune) {
  const auto d = test::surface_file("sphere.off");
  SurfacePacking p = surface_sample(d, true, 0.08 * diagonal(*d), 1);
  const std::vector<DiskId> ids = p.ids();
  Rng rng(1);
  respace_surface_boundary(p, 1.2, rng);
  EXPECT_EQ(boundary_inject(p, rng), 0);
  EXPECT_EQ(boundary_eject(p, rng), 0);
  EXPECT_EQ(p.ids(), ids);
}

}  // namespace
}  // namespace disktune
