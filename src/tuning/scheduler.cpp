// SPDX-License-Identifier: GPL-3.0-or-later
// The phase scheduler (paper, section 4): sweeps of one operation over all disks in
// random order, moving to the next phase at the area-fraction thresholds or when a
// sweep stops paying, and stopping the moment the count is the target.
#include <chrono>
#include <cmath>
#include <vector>

#include "disktune/boundary.h"
#include "disktune/density.h"
#include "disktune/errors.h"
#include "disktune/tuning.h"
#include "phase_loop.h"
#include "transaction.h"

namespace disktune {
namespace {

// The scheduler for a domain of the given area; `entry` is the packing as tune got it.
TuneResult tune_in(Packing& packing, const Packing& entry, double area, const Target& target, Rng& rng,
                   const TuneOptions& options, std::chrono::steady_clock::time_point t0) {
  const std::size_t goal = target_count(target, packing, area);
  const auto plans = detail::plan_for<Packing>(options, goal < packing.size(), packing.sizing() == nullptr, &angle_inject);
  return detail::run_phases(packing, entry, density_unit(packing, area), goal, plans, rng, options,
                            options.after_operation, t0);
}

}  // namespace

TuneResult tune(Packing& packing, const PeriodicBox& box, const Target& target, Rng& rng,
                const TuneOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  if (packing.empty()) throw InvalidInput("tune: the packing is empty; sample it first");
  return detail::as_transaction(packing, [&](const Packing& entry) {
    return tune_in(packing, entry, box.area(), target, rng, options, t0);
  });
}

TuneResult tune(Packing& packing, const PlanarDomain& domain, const Target& target, Rng& rng,
                const TuneOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  if (packing.empty()) throw InvalidInput("tune: the packing is empty; sample it first");
  if (packing.domain() != &domain) {
    throw InvalidInput("tune: the packing is not restricted to this domain (Packing::set_domain)");
  }
  if (options.method == Method::angle_injection) {
    throw InvalidInput("tune: angle injection triangulates the periodic box; in a planar domain "
                       "use void, repeller or crystal injection");
  }
  // The boundary first, at the spacing of a hexagonal packing of the target's count:
  // r / rho, rho = sqrt(eta 2 sqrt3 / pi) the target's relative radius.
  const double eta = static_cast<double>(target_count(target, packing, domain.area())) /
                     density_unit(packing, domain.area());
  return detail::as_transaction(packing, [&](const Packing& entry) {
    tune_boundary(packing, domain, 1 / relative_radius_for(eta), rng);
    return tune_in(packing, entry, domain.area(), target, rng, options, t0);
  });
}

}  // namespace disktune
