// SPDX-License-Identifier: GPL-3.0-or-later
// disktune-surface-bench: on data/surfaces/elephant.off and sphere.off, at constant radii
// giving about 10^4, 10^5 and (sphere only) 10^6 disks, times maximal Poisson-disk
// sampling, the maximality check, tuning to 1.4x and 0.7x the sample's count (automatic
// schedule) and the restricted Delaunay triangulation of the sample, each against CGAL's
// Delaunay_triangulation_3 of the same centers, timed in the same run. Then the growth of
// each time from the smallest to the largest size.
//
//   disktune-surface-bench [--quick] [--tune-budget S] [--rdt-max N]
//     --quick        10^4 disks only
//     --tune-budget  give up a tune after S seconds (default 120; printed as >S)
//     --rdt-max      skip the restricted Delaunay triangulation above N disks (default 200000)
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "delaunay_floor.h"
#include "disktune/errors.h"
#include "disktune/restricted_delaunay.h"
#include "disktune/surface_tuning.h"
#include "disktune/surface_voids.h"

using namespace disktune;

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

struct Row {
  std::size_t disks = 0;
  double r = 0, floor = 0, mps = 0, maximal = 0, up = 0, down = 0, rdt = 0;  // seconds; < 0: not run
  std::string notes;
};

// Tunes a copy of the sample to `factor` times its count; -budget when given up.
double tune_seconds(const SurfacePacking& mps, double factor, double budget, std::string& notes) {
  SurfacePacking packing = mps;
  const auto goal = static_cast<std::size_t>(std::lround(factor * static_cast<double>(mps.size())));
  Rng rng(7);
  TuneOptions options;
  const auto t0 = Clock::now();
  options.on_progress = [&](const Progress&) { return since(t0) <= budget; };  // false: cancel
  try {
    const TuneResult res = tune(packing, Target::count(goal), rng, options);
    if (!res.reached) notes += " x" + std::to_string(factor).substr(0, 3) + " stopped at " + std::to_string(res.count);
    const double seconds = since(t0);
    char check[96];  // the final check's share (tuning.h, TuneResult::check_seconds)
    std::snprintf(check, sizeof check, " x%.1f check %.3f s (%.1f %%)", factor, res.check_seconds,
                  100 * res.check_seconds / seconds);
    notes += check;
    return seconds;
  } catch (const Cancelled&) {
    return -since(t0);
  }
}

std::string cell(double t, double floor) {
  char buf[64];
  if (t == 0) return "        -        ";
  if (t < 0) std::snprintf(buf, sizeof buf, "  >%6.0f         ", -t);
  else std::snprintf(buf, sizeof buf, "%9.3f (%5.1fx)", t, t / floor);
  return buf;
}

void growth(const char* what, const Row& a, const Row& b, double Row::*t) {
  if (a.*t <= 0 || b.*t <= 0) return;
  const double n = static_cast<double>(b.disks) / a.disks, x = b.*t / a.*t;
  std::printf("  %-9s time x%-8.1f for disks x%.1f  (exponent %.2f)\n", what, x, n, std::log(x) / std::log(n));
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  double budget = 120;
  std::size_t rdt_max = 200000;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--quick")) quick = true;
    else if (!std::strcmp(argv[i], "--tune-budget") && i + 1 < argc) budget = std::atof(argv[++i]);
    else if (!std::strcmp(argv[i], "--rdt-max") && i + 1 < argc) rdt_max = std::strtoul(argv[++i], nullptr, 10);
  }
  struct Case {
    const char* file;
    std::vector<std::size_t> targets;
  };
  const std::vector<Case> cases = {{"elephant.off", {10000, 100000}}, {"sphere.off", {10000, 100000, 1000000}}};

  std::printf("surfaces, constant radius; each time (and its ratio to CGAL Delaunay_triangulation_3 of the sample)\n");
  for (const Case& c : cases) {
    const auto domain = std::make_shared<const SurfaceDomain>(
        read_surface(std::string(DISKTUNE_DATA_DIR) + "/surfaces/" + c.file));
    std::printf("\n%s: %zu triangles, area %.4f\n", c.file, domain->triangles().size(), domain->area());
    std::printf("%8s %9s %9s %17s %17s %17s %17s %17s\n", "disks", "r", "dt3_s", "mps_s", "is_maximal_s",
                "tune_x1.4_s", "tune_x0.7_s", "restricted_dt_s");
    std::vector<Row> rows;
    for (const std::size_t n : c.targets) {
      if (quick && n > 10000) break;
      Row row;
      // r at which a maximal sample (area fraction ~0.55) has about n disks.
      row.r = std::sqrt(0.55 * 4 * domain->area() / (M_PI * static_cast<double>(n)));
      const int reps = n <= 10000 ? 3 : 1;
      std::unique_ptr<SurfacePacking> mps;
      row.mps = 1e300;
      for (int k = 0; k < reps; ++k) {
        Rng rng(static_cast<std::uint64_t>(k) + 1);
        const auto t0 = Clock::now();
        auto p = std::make_unique<SurfacePacking>(sample_mps(domain, SurfaceSizing::constant(row.r), rng));
        row.mps = std::min(row.mps, since(t0));
        mps = std::move(p);
      }
      row.disks = mps->size();
      std::vector<Vec3> centers;
      for (const DiskId id : mps->ids()) centers.push_back(mps->center(id));
      row.floor = bench::delaunay3_seconds(centers, reps == 1 ? 2 : 3);

      row.maximal = 1e300;
      for (int k = 0; k < reps; ++k) {
        const auto t0 = Clock::now();
        if (!is_maximal(*mps)) row.notes += " NOT MAXIMAL";
        row.maximal = std::min(row.maximal, since(t0));
      }
      row.up = tune_seconds(*mps, 1.4, budget, row.notes);
      row.down = tune_seconds(*mps, 0.7, budget, row.notes);
      if (row.disks <= rdt_max) {
        const auto t0 = Clock::now();
        const SurfaceMesh mesh = restricted_delaunay(centers, *domain);
        row.rdt = since(t0);
        row.notes += " rdt " + std::to_string(mesh.triangles.size()) + " triangles";
        // The same points as the packing they are, which sample_mps left maximal: each
        // dual edge searched only within r of its facet (Coverage::maximal).
        const auto t1 = Clock::now();
        const SurfaceMesh cut = restricted_delaunay(*mps, Coverage::maximal);
        const double cut_seconds = since(t1);
        char text[96];
        std::snprintf(text, sizeof text,
                      ", rdt of the maximal packing %.3f s (%.1fx, %zu triangles)", cut_seconds,
                      cut_seconds / row.floor, cut.triangles.size());
        row.notes += text;
      }
      std::printf("%8zu %9.6f %9.3f %s %s %s %s %s %s\n", row.disks, row.r, row.floor,
                  cell(row.mps, row.floor).c_str(), cell(row.maximal, row.floor).c_str(),
                  cell(row.up, row.floor).c_str(), cell(row.down, row.floor).c_str(),
                  cell(row.rdt, row.floor).c_str(), row.notes.c_str());
      std::fflush(stdout);
      rows.push_back(row);
    }
    if (rows.size() < 2) continue;
    const Row &a = rows.front(), &b = rows.back();
    std::printf("growth %zu -> %zu disks (exponent 1 = linear):\n", a.disks, b.disks);
    growth("dt3", a, b, &Row::floor);
    growth("mps", a, b, &Row::mps);
    growth("maximal", a, b, &Row::maximal);
    growth("tune1.4", a, b, &Row::up);
    growth("tune0.7", a, b, &Row::down);
    growth("rdt", a, b, &Row::rdt);
  }
  return 0;
}
