// SPDX-License-Identifier: GPL-3.0-or-later
// Tuning on a surface: the surface's phases run through the one phase loop.
#include <chrono>
#include <cmath>

#include "disktune/density.h"
#include "disktune/errors.h"
#include "disktune/surface_tuning.h"
#include "own_voids.h"
#include "phase_loop.h"
#include "surface_tune.h"
#include "transaction.h"

namespace disktune {

std::size_t target_count(const Target& target, const SurfacePacking& packing) {
  return target_count_for_unit(target, density_unit(packing));
}

TuneResult tune(SurfacePacking& packing, const Target& target, Rng& rng, const TuneOptions& options) {
  return detail::tune_surface(packing, target, rng, options, true);
}

TuneResult detail::tune_surface(SurfacePacking& packing, const Target& target, Rng& rng,
                                const TuneOptions& options, bool final_check) {
  const auto t0 = std::chrono::steady_clock::now();
  if (packing.empty()) throw InvalidInput("tune: the packing is empty; sample the surface first");
  const double unit = density_unit(packing);  // the sizing's alone: it stays as disks change
  const std::size_t goal = target_count_for_unit(target, unit);
  const auto plans = detail::plan_for<SurfacePacking>(options, goal < packing.size(),
                                                      packing.sizing().is_constant(), nullptr, true);
  // The boundary and feature curves first, at the spacing of a hexagonal packing of the
  // target's count (feature curves at 1.2 r whatever the target, which can add disks
  // while ejecting). Where that takes the count past the target (the feature curves'
  // 1.2 r can hold more disks than the sample laid out where a sizing varies along
  // them), the curves stay as sampled: past it, the injection phases once ran on
  // without end.
  const double eta = static_cast<double>(goal) / unit;
  const detail::BoundaryBudget budget(packing.size(), goal);
  return detail::as_transaction(packing, [&](const SurfacePacking& entry) {
    respace_surface_boundary(packing, 1 / relative_radius_for(eta), rng);
    if (budget.passed(packing.size(), goal)) packing = entry;
    if (options.after_surface_operation) options.after_surface_operation(packing);
    const detail::OwnVoidCache own_void_cache(
        packing);  // the phases ask the same voids again and again
    return detail::run_phases(packing, entry, unit, goal, plans, rng, options,
                              options.after_surface_operation, t0, final_check);
  });
}

}  // namespace disktune
