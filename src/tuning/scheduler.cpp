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

using Operation = std::size_t (*)(Packing&, DiskId, Rng&, std::size_t);

// A phase: sweeps of a per-disk operation, or (op == nullptr) one crystal growth.
struct PhasePlan {
  Phase phase;
  Operation op;
  double until;  // area fraction at which the automatic schedule moves on (>= 1: never)
};

std::vector<PhasePlan> plan_for(const TuneOptions& o) {
  const PhasePlan void_phase{Phase::void_injection, &void_inject, o.void_until};
  const PhasePlan repeller_phase{Phase::repeller_injection, &repeller_inject, o.repeller_until};
  const PhasePlan crystal_phase{Phase::crystal_injection, nullptr, 2.0};
  switch (o.method) {
    case Method::automatic: return {void_phase, repeller_phase, crystal_phase};
    case Method::void_injection: return {{void_phase.phase, void_phase.op, 2.0}};
    case Method::repeller_injection: return {{repeller_phase.phase, repeller_phase.op, 2.0}};
    case Method::crystal_injection: return {crystal_phase};
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

  for (const PhasePlan& plan : plan_for(options)) {
    if (packing.size() >= result.target) break;
    result.last_phase = plan.phase;
    if (!plan.op) {
      std::size_t steps = 0;
      crystal_inject(packing, rng, result.target - packing.size(), [&] {
        if (options.after_operation) options.after_operation(packing);
        if (++steps % 256 == 0) report(plan.phase);
      });
      ++result.sweeps;
      report(plan.phase);
      continue;
    }
    for (int sweep = 0; sweep < options.max_sweeps_per_phase; ++sweep) {
      if (packing.size() >= result.target || eta() >= plan.until) break;
      const std::size_t before = packing.size();
      std::vector<DiskId> order = packing.ids();
      for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[uniform_index(rng, i)]);
      const std::size_t tick = std::max<std::size_t>(order.size() / 64, 1);
      for (std::size_t k = 0; k < order.size() && packing.size() < result.target; ++k) {
        if (!packing.alive(order[k])) continue;
        plan.op(packing, order[k], rng, result.target - packing.size());
        if (options.after_operation) options.after_operation(packing);
        if (k % tick == 0) report(plan.phase);
      }
      ++result.sweeps;
      report(plan.phase);
      const double gain = static_cast<double>(packing.size() - before);
      if (gain < options.min_gain_per_sweep * static_cast<double>(before)) break;
    }
  }
  result.count = packing.size();
  result.reached = result.count == result.target;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

}  // namespace disktune
