// SPDX-License-Identifier: GPL-3.0-or-later
// disktune-tune-bench: from an MPS of the unit periodic square, the time at which
// disk injection (or ejection, for fractions below the MPS's) first reaches each area
// fraction of a list, against CGAL's Delaunay
// triangulation of as many points, timed in the same run. The phases' path depends on
// the target only through TuneOptions::grains_from_sample (the automatic schedule's
// injection starts with grains at and past it) and otherwise only where it stops, so one
// run to the largest fraction on each side of that threshold times them all; but squeeze
// injection (the automatic schedule's first phase in the box) goes to its target in one
// stage, so below the threshold each fraction gets a run of its own.
//
//   disktune-tune-bench [--radius R] [--method
//   auto|void|repeller|crystal|grains|squeeze|angle|sift|attractor]
//                       [ETA ...]   (ascending for injection, descending for ejection)
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "delaunay_floor.h"
#include "disktune/density.h"
#include "disktune/sampling.h"
#include "disktune/tuning.h"

using namespace disktune;

int main(int argc, char** argv) {
  double r = 0.0025;
  Method method = Method::automatic;
  std::string method_name = "auto";
  std::vector<double> etas;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--radius") && i + 1 < argc) {
      r = std::atof(argv[++i]);
    } else if (!std::strcmp(argv[i], "--method") && i + 1 < argc) {
      method_name = argv[++i];
      method = method_named(method_name);  // throws InvalidInput, listing the names
    } else {
      etas.push_back(std::atof(argv[i]));
    }
  }
  if (etas.empty()) etas = {0.75, 0.80, 0.85, 0.89};

  const PeriodicBox box;
  Rng rng(1);
  auto t0 = std::chrono::steady_clock::now();
  Packing packing = sample_mps(box, r, rng);
  const double mps_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // Fractions below the MPS's mean ejection: then a fraction is reached when the
  // count falls to it.
  const bool eject = etas.back() < area_fraction(packing.size(), r, 1.0);
  std::printf("%s from an MPS of the unit periodic square, r = %g, method %s\n",
              eject ? "ejection" : "injection", r, method_name.c_str());
  std::printf("MPS: %zu disks, eta %.4f, %.3f s\n", packing.size(),
              area_fraction(packing.size(), r, 1.0), mps_s);
  std::printf("%8s %10s %12s %12s %10s  %s\n", "eta", "disks", "tune_s", "delaunay_s", "ratio", "phase");

  TuneOptions options;
  options.method = method;
  // The fractions one run times (above).
  const auto same_path = [&](double a, double b) {
    if (eject) return true;
    if (method == Method::squeeze_injection) return false;
    if (method != Method::automatic) return true;
    return a >= options.grains_from_sample && b >= options.grains_from_sample;
  };
  const Packing mps = packing;
  for (std::size_t first = 0; first < etas.size();) {
    std::size_t last = first;
    while (last + 1 < etas.size() && same_path(etas[first], etas[last + 1])) ++last;
    packing = mps;
    std::size_t next = first;
    t0 = std::chrono::steady_clock::now();
    std::vector<std::pair<double, Progress>> reached;  // time and state at each crossing
    options.on_progress = [&](const Progress& p) {
      auto passed = [&](std::size_t target) {
        return eject ? p.count <= target : p.count >= target;
      };
      while (next <= last && passed(count_for_area_fraction(etas[next], r, 1.0))) {
        reached.push_back(
            {std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), p});
        ++next;
      }
      return true;
    };
    const TuneResult res = tune(packing, box, Target::area_fraction(etas[last]), rng, options);
    options.on_progress({res.count, area_fraction(res.count, r, 1.0), res.last_phase});
    std::printf(
        "final check of the run to %.3f (and the packing kept before each phase): %.3f s of %.3f s "
        "(%.2f %%)\n",
        etas[last], res.check_seconds, res.seconds, 100 * res.check_seconds / res.seconds);
    for (std::size_t k = first; k <= last; ++k) {
      if (k - first >= reached.size()) {
        std::printf("%8.3f %10s %12s %12s %10s  not reached (stopped at eta %.4f)\n", etas[k], "-",
                    "-", "-", "-", area_fraction(res.count, r, 1.0));
        continue;
      }
      const auto& [t, p] = reached[k - first];
      const double dt = bench::delaunay_seconds(p.count, 3, 99);
      std::printf("%8.3f %10zu %12.2f %12.4f %10.1f  %s\n", etas[k], p.count, t, dt, t / dt,
                  to_string(p.phase).c_str());
    }
    first = last + 1;
  }
  return 0;
}
