// SPDX-License-Identifier: GPL-3.0-or-later
// Tuning on a surface: the surface's phases run through the one phase loop.
#include <chrono>
#include <cmath>

#include "disktune/density.h"
#include "disktune/errors.h"
#include "disktune/surface_tuning.h"
#include "phase_loop.h"
#include "transaction.h"

namespace disktune {

double density_unit(const SurfacePacking& packing) {
  const SurfaceDomain& d = packing.domain();
  const SurfaceSizing& sizing = packing.sizing();
  const double pi = 3.14159265358979323846;
  if (sizing.is_constant()) return d.area() / (pi * sizing.max_radius() * sizing.max_radius() / 4);
  // The integral of 4 / (pi r^2) by the edge-midpoint rule on every triangle.
  double sum = 0;
  for (std::size_t t = 0; t < d.triangles().size(); ++t) {
    const auto& tri = d.triangles()[t];
    const Vec3 a = d.vertices()[tri[0]], b = d.vertices()[tri[1]], c = d.vertices()[tri[2]];
    double mean = 0;
    for (const Vec3 m : {(a + b) * 0.5, (b + c) * 0.5, (c + a) * 0.5}) {
      const double r = sizing.radius(d, m, t);
      mean += 4 / (pi * r * r) / 3;
    }
    sum += mean * 0.5 * norm(cross(b - a, c - a));
  }
  return sum;
}

std::size_t target_count(const Target& target, const SurfacePacking& packing) {
  return target_count_for_unit(target, density_unit(packing));
}

TuneResult tune(SurfacePacking& packing, const Target& target, Rng& rng, const TuneOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  if (packing.empty()) throw InvalidInput("tune: the packing is empty; sample the surface first");
  const double unit = density_unit(packing);  // the sizing's alone: it stays as disks change
  const std::size_t goal = target_count_for_unit(target, unit);
  const auto plans = detail::plan_for<SurfacePacking>(options, goal < packing.size(),
                                                      packing.sizing().is_constant(), nullptr, true);
  // The boundary first, at the spacing of a hexagonal packing of the target's count.
  const double eta = static_cast<double>(goal) / unit;
  return detail::as_transaction(packing, [&](const SurfacePacking& entry) {
    respace_surface_boundary(packing, 1 / relative_radius_for(eta), rng);
    if (options.after_surface_operation) options.after_surface_operation(packing);
    return detail::run_phases(packing, entry, unit, goal, plans, rng, options, options.after_surface_operation, t0);
  });
}

}  // namespace disktune
