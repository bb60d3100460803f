// SPDX-License-Identifier: GPL-3.0-or-later
// The phase scheduler (paper, section 4): sweeps of one operation over all disks in
// random order, moving to the next phase at the area-fraction thresholds or when a
// sweep stops paying, and stopping the moment the count is the target.
#include <algorithm>
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

// The boundary's count moved by what is missing, in one sweep, for a domain whose disks
// are mostly on the boundary (a thin one), where the interior phases stall. Kept only
// when the count moved toward the goal without passing it: a boundary disk less can
// make room for two inside.
template <int kSign>
std::size_t boundary_sweep(Packing& packing, Rng& rng, std::size_t missing, const std::function<void()>& done) {
  const Packing before = packing;
  boundary_tune_by(packing, *packing.domain(), kSign * static_cast<long>(missing), rng);
  const long moved = kSign * (static_cast<long>(packing.size()) - static_cast<long>(before.size()));
  const bool kept = moved >= 0 && moved <= static_cast<long>(missing);
  if (!kept) packing = before;
  done();
  return kept ? static_cast<std::size_t>(moved) : 0;
}

bool mostly_boundary(const Packing& packing) {
  std::size_t fixed = 0;
  for (const DiskId id : packing.ids()) fixed += (packing.flags(id) & kFixed) != 0;
  return 2 * fixed > packing.size();
}

// The scheduler for a domain of the given area; `entry` is the packing as tune got it.
TuneResult tune_in(Packing& packing, const Packing& entry, double area, const Target& target, Rng& rng,
                   const TuneOptions& options, std::chrono::steady_clock::time_point t0) {
  const std::size_t goal = target_count(target, packing, area);
  const bool eject = goal < packing.size();
  const double unit = density_unit(packing, area);
  const bool box_one_radius = !packing.domain() && packing.sizing() == nullptr;
  auto plans = detail::plan_for<Packing>(options, eject, packing.sizing() == nullptr, &angle_inject,
                                         false, static_cast<double>(goal) / unit,
                                         box_one_radius ? &squeeze_inject : nullptr);
  if (packing.domain() && options.method == Method::automatic && mostly_boundary(packing)) {
    plans.push_back({eject ? Phase::boundary_ejection : Phase::boundary_injection, nullptr,
                     eject ? &boundary_sweep<-1> : &boundary_sweep<1>, 2.0});
  }
  return detail::run_phases(packing, entry, unit, goal, plans, rng, options,
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
  if (options.method == Method::squeeze_injection) {
    throw InvalidInput(
        "tune: squeeze injection moves disks through the seams of a periodic box; "
        "in a planar domain use void, repeller or crystal injection");
  }
  if (options.method == Method::angle_injection) {
    throw InvalidInput("tune: angle injection triangulates the periodic box; in a planar domain "
                       "use void, repeller or crystal injection");
  }
  // The boundary first, at the spacing of a hexagonal packing of the target's count:
  // r / rho, rho = sqrt(eta 2 sqrt3 / pi) the target's relative radius; but no step over
  // kLongestTunedStep r, so no interior disk encroaches on the boundary.
  const std::size_t goal = target_count(target, packing, domain.area());
  const double eta = static_cast<double>(goal) / density_unit(packing, domain.area());
  const detail::BoundaryBudget budget(packing.size(), goal);
  boundary_loops(packing, domain);  // flags the boundary disks (a packing read from a file) before `entry` is kept
  return detail::as_transaction(packing, [&](const Packing& entry) {
    tune_boundary(packing, domain, 1 / relative_radius_for(eta), rng, budget.change, budget.missing,
                  kLongestTunedStep);
    if (budget.passed(packing.size(), goal)) packing = entry;
    return tune_in(packing, entry, domain.area(), target, rng, options, t0);
  });
}

}  // namespace disktune
