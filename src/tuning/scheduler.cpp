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

namespace disktune {
namespace {

// A per-disk operation, applied to every disk in random order in one sweep.
using Operation = std::size_t (*)(Packing&, DiskId, Rng&, std::size_t);
// A whole sweep at once (crystal growth, angle injection).
using Sweep = std::size_t (*)(Packing&, Rng&, std::size_t, const std::function<void()>&);

struct PhasePlan {
  Phase phase;
  Operation op;  // one of op and sweep
  Sweep sweep;
  double until;  // area fraction at which the automatic schedule moves on (>= 1: never)
  bool thaw = false;  // unfreeze the crystal first, so its disks can move again
};

// The phases for a method, in order. Injection phases move on at their area fraction
// (automatic schedule) or when they stall; ejection phases when they stall.
std::vector<PhasePlan> plan_for(const TuneOptions& o, bool eject, bool one_radius) {
  const PhasePlan void_phase{Phase::void_injection, &void_inject, nullptr, o.void_until};
  const PhasePlan repeller_phase{Phase::repeller_injection, &repeller_inject, nullptr, o.repeller_until};
  const PhasePlan crystal_phase{Phase::crystal_injection, nullptr, &crystal_inject, 2.0};
  const PhasePlan angle_phase{Phase::angle_injection, nullptr, &angle_inject, 2.0};
  const PhasePlan sift_phase{Phase::sift_ejection, &sift_eject, nullptr, 2.0};
  const PhasePlan attractor_phase{Phase::attractor_ejection, &attractor_eject, nullptr, 2.0};
  const PhasePlan crystal_eject_phase{Phase::crystal_ejection, nullptr, &crystal_eject, 2.0};
  auto alone = [](PhasePlan p) { return p.until = 2.0, std::vector<PhasePlan>{p}; };
  // Crystal steps near the exact target can all overshoot (the voids a step refills need
  // more disks than are left to add); repeller injection then adds the last few.
  PhasePlan finish = repeller_phase;
  finish.until = 2.0;
  finish.thaw = true;
  const bool ejects = o.method == Method::sift_ejection || o.method == Method::attractor_ejection ||
                      o.method == Method::crystal_ejection;
  if (o.method != Method::automatic && ejects != eject) {
    throw InvalidInput(eject ? "tune: the target is below the current count, but the method adds "
                               "disks; use an ejection method (or automatic)"
                             : "tune: the target is above the current count, but the method removes "
                               "disks; use an injection method (or automatic)");
  }
  switch (o.method) {
    case Method::automatic:  // no crystal growth for varying radii (paper, 6)
      if (eject) return one_radius ? std::vector<PhasePlan>{sift_phase, attractor_phase, crystal_eject_phase}
                                   : std::vector<PhasePlan>{sift_phase, attractor_phase};
      // Without crystal growth the repeller phase is the last: it runs until it stalls.
      return one_radius ? std::vector<PhasePlan>{void_phase, repeller_phase, crystal_phase, finish}
                        : std::vector<PhasePlan>{void_phase, finish};
    case Method::void_injection: return alone(void_phase);
    case Method::repeller_injection: return alone(repeller_phase);
    case Method::crystal_injection: return {crystal_phase, finish};
    case Method::angle_injection: return alone(angle_phase);
    case Method::sift_ejection: return alone(sift_phase);
    case Method::attractor_ejection: return alone(attractor_phase);
    case Method::crystal_ejection: return alone(crystal_eject_phase);
  }
  return {};
}

// The scheduler for a domain of the given area.
TuneResult tune_in(Packing& packing, double area, const Target& target, Rng& rng,
                   const TuneOptions& options, std::chrono::steady_clock::time_point t0) {
  TuneResult result;
  const double unit = density_unit(packing, area);
  result.target = target_count(target, packing, area);
  const bool eject = result.target < packing.size();
  // Disks still to add or remove: what each operation may change at most.
  auto missing = [&] {
    return eject ? packing.size() - result.target : result.target - packing.size();
  };
  auto eta = [&] { return static_cast<double>(packing.size()) / unit; };
  auto report = [&](Phase phase) {
    if (options.on_progress) options.on_progress({packing.size(), eta(), phase});
  };

  // One sweep of a phase: a whole-packing sweep, or its operation on every disk in
  // random order.
  auto run_sweep = [&](const PhasePlan& plan) {
    if (plan.sweep) {
      std::size_t steps = 0;
      plan.sweep(packing, rng, missing(), [&] {
        if (options.after_operation) options.after_operation(packing);
        if (++steps % 256 == 0) report(plan.phase);
      });
      return;
    }
    std::vector<DiskId> order = packing.ids();
    for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[uniform_index(rng, i)]);
    const std::size_t tick = std::max<std::size_t>(order.size() / 64, 1);
    for (std::size_t k = 0; k < order.size() && missing() > 0; ++k) {
      if (!packing.alive(order[k])) continue;
      plan.op(packing, order[k], rng, missing());
      if (options.after_operation) options.after_operation(packing);
      if (k % tick == 0) report(plan.phase);
    }
  };

  for (const PhasePlan& plan : plan_for(options, eject, packing.sizing() == nullptr)) {
    if (missing() == 0) break;
    result.last_phase = plan.phase;
    if (plan.thaw) {
      for (const DiskId id : packing.ids()) packing.set_flags(id, packing.flags(id) & ~kFrozen);
    }
    for (int k = 0; k < options.max_sweeps_per_phase; ++k) {
      if (missing() == 0 || (!eject && eta() >= plan.until)) break;
      const std::size_t before = packing.size();
      run_sweep(plan);
      ++result.sweeps;
      report(plan.phase);
      const double gain = std::abs(static_cast<double>(packing.size()) - static_cast<double>(before));
      if (gain < std::max(options.min_gain_per_sweep * static_cast<double>(before), 0.5)) break;
    }
  }
  result.count = packing.size();
  result.reached = result.count == result.target;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

}  // namespace

TuneResult tune(Packing& packing, const PeriodicBox& box, const Target& target, Rng& rng,
                const TuneOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  if (packing.empty()) throw InvalidInput("tune: the packing is empty; sample it first");
  return tune_in(packing, box.area(), target, rng, options, t0);
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
  tune_boundary(packing, domain, 1 / std::sqrt(eta * 2 * std::sqrt(3.0) / 3.14159265358979323846), rng);
  return tune_in(packing, domain.area(), target, rng, options, t0);
}

}  // namespace disktune
