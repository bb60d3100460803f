// SPDX-License-Identifier: GPL-3.0-or-later
// The phase scheduler (paper, section 4): sweeps of one operation over all disks in
// random order, moving to the next phase at the area-fraction thresholds or when a
// sweep stops paying, and stopping the moment the count is the target.
#include <chrono>
#include <vector>

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
};

std::vector<PhasePlan> plan_for(const TuneOptions& o) {
  const PhasePlan void_phase{Phase::void_injection, &void_inject, nullptr, o.void_until};
  const PhasePlan repeller_phase{Phase::repeller_injection, &repeller_inject, nullptr, o.repeller_until};
  const PhasePlan crystal_phase{Phase::crystal_injection, nullptr, &crystal_inject, 2.0};
  const PhasePlan angle_phase{Phase::angle_injection, nullptr, &angle_inject, 2.0};
  auto alone = [](PhasePlan p) { return p.until = 2.0, std::vector<PhasePlan>{p}; };
  switch (o.method) {
    case Method::automatic: return {void_phase, repeller_phase, crystal_phase};
    case Method::void_injection: return alone(void_phase);
    case Method::repeller_injection: return alone(repeller_phase);
    case Method::crystal_injection: return alone(crystal_phase);
    case Method::angle_injection: return alone(angle_phase);
  }
  return {};
}

}  // namespace

TuneResult tune(Packing& packing, const PeriodicBox& box, const Target& target, Rng& rng,
                const TuneOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  if (packing.empty()) throw InvalidInput("tune: the packing is empty; sample it first");
  const double r = packing.max_radius();
  TuneResult result;
  result.target = target_count(target, r, box.area());
  if (result.target < packing.size()) {
    throw InvalidInput("tune: the target (" + std::to_string(result.target) +
                       " disks) is below the current count (" + std::to_string(packing.size()) +
                       "): that needs disk ejection, which is not implemented yet");
  }
  auto eta = [&] { return area_fraction(packing.size(), r, box.area()); };
  auto report = [&](Phase phase) {
    if (options.on_progress) options.on_progress({packing.size(), eta(), phase});
  };

  // One sweep of a phase: a whole-packing sweep, or its operation on every disk in
  // random order.
  auto run_sweep = [&](const PhasePlan& plan) {
    if (plan.sweep) {
      std::size_t steps = 0;
      plan.sweep(packing, rng, result.target - packing.size(), [&] {
        if (options.after_operation) options.after_operation(packing);
        if (++steps % 256 == 0) report(plan.phase);
      });
      return;
    }
    std::vector<DiskId> order = packing.ids();
    for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[uniform_index(rng, i)]);
    const std::size_t tick = std::max<std::size_t>(order.size() / 64, 1);
    for (std::size_t k = 0; k < order.size() && packing.size() < result.target; ++k) {
      if (!packing.alive(order[k])) continue;
      plan.op(packing, order[k], rng, result.target - packing.size());
      if (options.after_operation) options.after_operation(packing);
      if (k % tick == 0) report(plan.phase);
    }
  };

  for (const PhasePlan& plan : plan_for(options)) {
    if (packing.size() >= result.target) break;
    result.last_phase = plan.phase;
    for (int k = 0; k < options.max_sweeps_per_phase; ++k) {
      if (packing.size() >= result.target || eta() >= plan.until) break;
      const std::size_t before = packing.size();
      run_sweep(plan);
      ++result.sweeps;
      report(plan.phase);
      const double gain = static_cast<double>(packing.size() - before);
      if (gain < std::max(options.min_gain_per_sweep * static_cast<double>(before), 0.5)) break;
    }
  }
  result.count = packing.size();
  result.reached = result.count == result.target;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

}  // namespace disktune
