// SPDX-License-Identifier: GPL-3.0-or-later
// disktune-bench: maximal Poisson-disk sampling of the unit periodic square at about
// 10^4, 10^5 and 10^6 disks, against CGAL's Delaunay triangulation of as many points,
// timed in the same run. Prints each time (best of several runs), the ratio, and the
// growth exponent of the time from the smallest to the largest size.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "delaunay_floor.h"
#include "disktune/density.h"
#include "disktune/sampling.h"

using namespace disktune;

namespace {

struct Row {
  std::size_t disks;
  double mps, delaunay;
  MpsStats stats;  // of the fastest run
};

double mps_seconds(double r, int reps, Row& row) {
  double best = 1e300;
  for (int k = 0; k < reps; ++k) {
    Rng rng(static_cast<std::uint64_t>(k) + 1);
    MpsStats stats;
    const auto t0 = std::chrono::steady_clock::now();
    const Packing p = sample_mps(PeriodicBox(), r, rng, {}, &stats);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (s < best) best = s, row.stats = stats;
    row.disks = p.size();
  }
  return best;
}

double exponent(const Row& a, const Row& b, double Row::*t) {
  return std::log(b.*t / a.*t) / std::log(static_cast<double>(b.disks) / a.disks);
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const std::vector<std::size_t> targets =
      quick ? std::vector<std::size_t>{10000, 100000} : std::vector<std::size_t>{10000, 100000, 1000000};
  std::printf("MPS of the unit periodic square vs CGAL Delaunay_triangulation_2 of as many points\n");
  std::printf("%10s %10s %12s %12s %8s\n", "disks", "r", "mps_s", "delaunay_s", "ratio");
  std::vector<Row> rows;
  for (const std::size_t n : targets) {
    // r for which an MPS (area fraction ~0.547) has about n disks.
    const double r = 2 * std::sqrt(0.547 / (3.14159265358979 * static_cast<double>(n)));
    const int reps = n >= 1000000 ? 3 : 5;
    Row row{};
    row.mps = mps_seconds(r, reps, row);
    row.delaunay = bench::delaunay_seconds(row.disks, reps, 99);
    rows.push_back(row);
    std::printf("%10zu %10.6f %12.4f %12.4f %8.2f\n", row.disks, r, row.mps, row.delaunay,
                row.mps / row.delaunay);
    std::fflush(stdout);
  }
  std::printf("\nwhere the MPS time goes (fastest run), seconds:\n%10s %8s %8s %8s %8s %8s %10s %10s\n",
              "disks", "darts", "prune", "voids", "build", "check", "darts_n", "void_disks");
  for (const Row& row : rows) {
    const MpsStats& s = row.stats;
    std::printf("%10zu %8.3f %8.3f %8.3f %8.3f %8.3f %10zu %10zu\n", row.disks, s.darts_seconds,
                s.prune_seconds, s.voids_seconds, s.build_seconds, s.check_seconds, s.darts, s.void_disks);
  }
  const Row& a = rows.front();
  const Row& b = rows.back();
  std::printf("growth exponent of time, %zu -> %zu disks: mps %.3f, delaunay %.3f (1 = linear)\n",
              a.disks, b.disks, exponent(a, b, &Row::mps), exponent(a, b, &Row::delaunay));
  return 0;
}
