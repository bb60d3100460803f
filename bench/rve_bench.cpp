// SPDX-License-Identifier: GPL-3.0-or-later
// disktune-rve-bench: fiber RVEs at vf 0.70 with a gap of 0.05 D (issue #18's case) in
// the unit cell, 10^3 to 10^5 fibers: the time of make_rve and of the statistics, the
// disorder (global and local psi6) and the spread of the local fiber fraction, against
// CGAL's Delaunay triangulation of as many points, timed in the same run. With --cv,
// unequal fibers of that coefficient of variation (about N of them: the count is the
// fraction's).
//
//   disktune-rve-bench [--vf VF] [--gap-share G] [--cv CV] [--seeds K] [N ...]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "delaunay_floor.h"
#include "disktune/fiber_statistics.h"
#include "disktune/rve.h"

using namespace disktune;

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

int main(int argc, char** argv) {
  double vf = 0.70, gap_share = 0.05, cv = 0;
  int seeds = 2;
  std::vector<std::size_t> counts;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--vf") && i + 1 < argc) {
      vf = std::atof(argv[++i]);
    } else if (!std::strcmp(argv[i], "--gap-share") && i + 1 < argc) {
      gap_share = std::atof(argv[++i]);
    } else if (!std::strcmp(argv[i], "--cv") && i + 1 < argc) {
      cv = std::atof(argv[++i]);
    } else if (!std::strcmp(argv[i], "--seeds") && i + 1 < argc) {
      seeds = std::atoi(argv[++i]);
    } else {
      counts.push_back(std::strtoul(argv[i], nullptr, 10));
    }
  }
  if (counts.empty()) counts = {1000, 10000, 100000};
  std::printf("fiber RVEs in the unit cell, vf %.3f, gap %.3f D, diameter cv %.3f, seeds 1..%d\n", vf, gap_share, cv,
              seeds);
  std::printf("| fibers | seed | MPS | phase | rve s | / Delaunay | stats s | global psi6 | mean local psi6 | local > 0.9 | local vf sd (4 D) |\n");
  std::printf("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n");
  for (const std::size_t n : counts) {
    const double floor_s = bench::delaunay_seconds(n, 3, 1);
    for (int seed = 1; seed <= seeds; ++seed) {
      RveSpec spec;
      spec.diameter = std::sqrt(vf * 4 / (3.14159265358979323846 * static_cast<double>(n)));
      spec.gap = gap_share * spec.diameter;
      if (cv > 0) {
        spec.diameter_cv = cv, spec.fiber_fraction = vf;
      } else {
        spec.fibers = n;
      }
      spec.seed = static_cast<std::uint64_t>(seed);
      auto t0 = std::chrono::steady_clock::now();
      const Rve rve = make_rve(spec);
      const double rve_s = seconds_since(t0);
      t0 = std::chrono::steady_clock::now();
      const FiberStatistics s = fiber_statistics(rve.cell, rve.centers, rve.diameters);
      const double stats_s = seconds_since(t0);
      std::printf("| %zu | %d | %zu | %s%s | %.3f | %.0fx | %.3f | %.4f | %.3f | %.1f %% | %.4f |\n", rve.centers.size(), seed,
                  rve.sample_centers.size(), to_string(rve.tuning.last_phase).c_str(),
                  rve.tuning.reached ? "" : " (NOT reached)", rve_s, rve_s / floor_s, stats_s, s.psi6_global,
                  s.psi6_local_mean, 100 * s.psi6_hexagonal_share,
                  s.local_fraction.size() > 1 ? s.local_fraction[1].fraction.stddev : 0.0);
    }
    std::printf("(CGAL Delaunay of %zu points: %.4f s)\n", n, floor_s);
  }
}
