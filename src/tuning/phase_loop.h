// SPDX-License-Identifier: GPL-3.0-or-later
// The phase loop of the scheduler (paper, section 4), for any kind of packing (planar
// and surface): sweeps of one operation over all disks in random order, moving to the
// next phase at the area-fraction thresholds or when a sweep stops paying, and
// stopping the moment the count is the target.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <optional>
#include <queue>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include "../geometry/threads.h"
#include "../voids/final_check.h"
#include "disktune/boundary.h"
#include "disktune/errors.h"
#include "disktune/surface_tuning.h"
#include "disktune/tuning.h"
#include "space.h"
#include "tile_order.h"

namespace disktune::detail {

/// What the boundary step before the phases may do: move the count only toward `goal`,
/// by at most the disks missing.
struct BoundaryBudget {
  BoundaryChange change;
  std::size_t missing;

  BoundaryBudget(std::size_t count, std::size_t goal)
      : change(goal > count   ? BoundaryChange::only_more
               : goal < count ? BoundaryChange::only_fewer
                              : BoundaryChange::any),
        missing(goal > count ? goal - count : count - goal) {}
  /// Whether `count` went past `goal` (or off it, when it was there): interior disks a
  /// moved boundary disk displaces are refilled, so the step can overshoot; then the
  /// boundary must stay as it was, as the phases go one way only.
  bool passed(std::size_t count, std::size_t goal) const {
    return change == BoundaryChange::only_more ? count > goal : change == BoundaryChange::only_fewer ? count < goal
                                                                                                       : count != goal;
  }
};

template <class P>
struct PhasePlan {
  Phase phase;
  // A per-disk operation, applied to every disk in random order in one sweep...
  std::size_t (*op)(P&, DiskId, Rng&, std::size_t);
  // ...or a whole sweep at once (crystal growth, angle injection).
  std::size_t (*sweep)(P&, Rng&, std::size_t, const std::function<void()>&);
  double until;       // area fraction at which the automatic schedule moves on (>= 1: never)
  bool thaw = false;  // unfreeze the crystal first, so its disks can move again
  // Each sweep tries only the sparsest tenth of the disks (sparsest_first), not all.
  bool sparsest = false;
  // A sweep's worth of tries adding or removing fewer disks than this fraction of them
  // ends the phase (at least TuneOptions::min_gain_per_sweep): for phases whose tail
  // the next phase does faster. With `judge_parts`, so does each sixteenth of a sweep
  // (of at least 256 tries) but the last, at once, as soon as it is done (the last one
  // is left to the whole sweep's judgement): that comes a slow sweep late.
  double min_gain = 0;
  bool judge_parts = false;
  // Where set, a sweep tries the disks in the order of this rank, smallest first
  // (ranked_sweep), not at random; its sweeps are judged whole (not judge_parts).
  double (*rank)(const P&, DiskId) = nullptr;
  // ...or a whole sweep that also calls its last argument while a long stage runs (squeeze
  // injection: seconds at 10^6 disks), where tune reports progress and may be cancelled.
  std::size_t (*polled_sweep)(P&, Rng&, std::size_t, const std::function<void()>&,
                              const std::function<void()>&) = nullptr;
};

/// How wide the void lifting disk p would leave is: the largest distance between two of
/// its void points (0: none). The attractor removes p far more often where it is small:
/// on the elephant at 10^4 disks after sifting, 29 % of the tries in the tenth with the
/// smallest, 3 % in the tenth with the largest (docs/tuning.md).
template <class P>
double own_void_width(const P& packing, DiskId p) {
  using S = Space<P>;
  const auto voids = S::voids_in(packing, packing.center(p), S::void_reach(packing.radius(p)), {p});
  double widest = 0;
  for (std::size_t i = 0; i < voids.size(); ++i)
    for (std::size_t j = i + 1; j < voids.size(); ++j)
      widest = std::max(widest, squared_norm(S::location(S::point_of(voids[i])) -
                                             S::location(S::point_of(voids[j]))));
  return std::sqrt(widest);
}

/// The disks a sparse-first sweep tries: the tenth (at least one) with the fewest
/// neighbours within twice their radius, ties in the random order given. Repeller
/// injection opens a gap where the disks around the repeller have room to move: from
/// eta 0.75 to 0.79 (unit box, r = 0.01, three seeds) the sparsest tenth took 31-33
/// thousand tries, sweeps over all disks in random order 134-163 thousand, with the same
/// disorder (docs/tuning.md). Void injection is the other way round (it needs every
/// disk shaken: the sparsest tenth stalled at 0.71), so only the repeller phases use it,
/// and go on over all disks once it stops paying (run_phases).
template <class P>
std::vector<DiskId> sparsest_first(const P& packing, const std::vector<DiskId>& order) {
  using S = Space<P>;
  // Counted on every core (the counts only read the packing).
  constexpr std::size_t kChunk = 256;
  std::vector<std::size_t> near(order.size(), 0);
  parallel_for((order.size() + kChunk - 1) / kChunk, thread_count(0),
               [&](std::size_t chunk, unsigned) {
                 for (std::size_t k = chunk * kChunk;
                      k < std::min(order.size(), (chunk + 1) * kChunk); ++k) {
                   const DiskId d = order[k];
                   if (packing.flags(d) & kFixed) continue;  // not ranked (below)
                   S::for_each_near(packing, packing.center(d), 2 * packing.radius(d),
                                    [&](const auto& q) { near[k] += q.id != d; });
                 }
               });
  std::vector<std::pair<std::size_t, DiskId>> ranked;
  ranked.reserve(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    if (packing.flags(order[k]) & kFixed)
      continue;  // a boundary disk: its neighbours are few anyway
    ranked.push_back({near[k], order[k]});
  }
  const std::size_t keep = std::max<std::size_t>(1, ranked.size() / 10);
  std::stable_sort(ranked.begin(), ranked.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<DiskId> out;
  out.reserve(keep);
  for (std::size_t i = 0; i < keep && i < ranked.size(); ++i) out.push_back(ranked[i].second);
  return out;
}

/// Throws InvalidInput when a single method's direction (adding or removing disks)
/// disagrees with the target's.
inline void check_direction(Method method, bool eject) {
  const bool ejects = method == Method::sift_ejection || method == Method::attractor_ejection ||
                      method == Method::crystal_ejection;
  if (method != Method::automatic && ejects != eject) {
    throw InvalidInput(eject ? "tune: the target is below the current count, but the method adds "
                               "disks; use an ejection method (or automatic)"
                             : "tune: the target is above the current count, but the method removes "
                               "disks; use an injection method (or automatic)");
  }
}

/// The phases for a method, in order. Injection phases move on at their area fraction
/// (automatic schedule) or when they stall; ejection phases when they stall. No crystal
/// growth for varying radii (paper, 6); `angle` is null where angle injection is not
/// defined (surfaces), and asking for it then throws InvalidInput. Past the repeller the
/// automatic schedule grows many grains (grain_inject: no common orientation), and one
/// crystal only where their boundaries stall it; for a `target_eta` at or past
/// TuneOptions::grains_from_sample the grains start from the packing as given. On a `curved`
/// surface a lattice cannot close, so the crystal phases do less: injection goes from void
/// injection straight to the crystal (which barely grows in the dense random packing
/// repeller injection leaves, and the repeller phase is the slow one), and ejection runs
/// the wide attractor before the crystal (after it, the crystal removes nothing; before
/// it, its frozen lattice leaves the wide attractor less room). `squeeze` is null where
/// squeeze injection is not defined (all but the periodic box); where it is, it replaces
/// void and repeller injection in the automatic schedule.
template <class P>
std::vector<PhasePlan<P>> plan_for(const TuneOptions& o, bool eject, bool one_radius,
                                   std::size_t (*angle)(P&, Rng&, std::size_t,
                                                        const std::function<void()>&),
                                   bool curved = false, double target_eta = 0,
                                   std::size_t (*squeeze)(P&, Rng&, std::size_t,
                                                          const std::function<void()>&,
                                                          const std::function<void()>&) = nullptr) {
  using Plan = PhasePlan<P>;
  const Plan void_phase{Phase::void_injection, &void_inject, nullptr, o.void_until};
  const Plan repeller_phase{
      Phase::repeller_injection, &repeller_inject, nullptr, o.repeller_until, false, true};
  const Plan crystal_phase{Phase::crystal_injection, nullptr, &crystal_inject, 2.0};
  // Many grains at orientations spread evenly, then, where their boundaries leave the target
  // out of reach (near eta 0.86), one crystal grown through them, thawed.
  const Plan grain_phase{
      Phase::grain_injection, nullptr,
      +[](P& packing, Rng& rng, std::size_t max_added, const std::function<void()>& after_step) {
        return grain_inject(packing, rng, max_added, after_step);
      },
      2.0};
  Plan crystal_after_grains = crystal_phase;
  crystal_after_grains.thaw = true;
  const Plan angle_phase{Phase::angle_injection, nullptr, angle, 2.0};
  Plan squeeze_phase{Phase::squeeze_injection, nullptr, nullptr, o.squeeze_until};
  squeeze_phase.polled_sweep = squeeze;
  const Plan sift_phase{Phase::sift_ejection, &sift_eject, nullptr, 2.0};
  const Plan attractor_phase{Phase::attractor_ejection, &attractor_eject, nullptr, 2.0};
  // Three rings of neighbours where one ring has stalled, the crystal (if it ran
  // first) thawed so that its disks can make room too.
  const Plan wide_attractor_phase{Phase::attractor_ejection, &wide_attractor_eject, nullptr, 2.0, true};
  const Plan crystal_eject_phase{Phase::crystal_ejection, nullptr, &crystal_eject, 2.0};
  // On a curved surface the phases after void injection and sifting do their tails'
  // work faster. Void injection hands over at the first sixteenth of a sweep adding
  // under 2 % of its tries: on the elephant at 10^5 disks (one core) its sweeps from
  // eta 0.70 added 2,600 down to 200 disks at 1.2 s each, the crystal after it 6,000 a
  // second (tune to 1.4x 23.6 -> 4.8 s). Both attractors try the disks with the
  // narrowest own void first (own_void_width), and sifting hands over to them at the
  // first sixteenth of a sweep removing under 3 % of its tries (what it leaves, the
  // ejection rounds come back for): the elephant's tune to 0.7x at 10^5 13.0 -> 7.9 s
  // (11.6 s with the ranking alone; with the cut at 0.3 % or 1 %, 9.1 and 8.5 s; at
  // 10 %, 7.8 s, but eight.off to 0.62x then took 7.8 and 10.6 s where 3 % takes 8.4
  // and 8.6; docs/tuning.md).
  Plan quick_void_phase = void_phase, quick_sift_phase = sift_phase;
  quick_void_phase.until = o.surface_void_until;
  quick_void_phase.min_gain = 0.02;
  quick_void_phase.judge_parts = true;
  quick_sift_phase.min_gain = 3e-2;
  quick_sift_phase.judge_parts = true;
  Plan ranked_attractor_phase = attractor_phase, ranked_wide_attractor_phase = wide_attractor_phase;
  ranked_attractor_phase.rank = ranked_wide_attractor_phase.rank = &own_void_width<P>;
  auto alone = [](Plan p) { return p.until = 2.0, std::vector<Plan>{p}; };
  // Crystal steps near the exact target can all overshoot (the voids a step refills need
  // more disks than are left to add); repeller injection then adds the last few.
  Plan finish = repeller_phase;
  finish.until = 2.0;
  finish.thaw = true;
  check_direction(o.method, eject);
  switch (o.method) {
    case Method::automatic:
      if (eject) {
        if (!one_radius) return {sift_phase, attractor_phase, wide_attractor_phase};
        return curved ? std::vector<Plan>{quick_sift_phase, ranked_attractor_phase,
                                          ranked_wide_attractor_phase, crystal_eject_phase}
                      : std::vector<Plan>{sift_phase, attractor_phase, crystal_eject_phase,
                                          wide_attractor_phase};
      }
      // Without crystal growth the repeller phase is the last: it runs until it stalls.
      if (!one_radius) return {void_phase, finish};
      if (curved) return {quick_void_phase, crystal_phase, finish};
      if (target_eta >= o.grains_from_sample) return {grain_phase, crystal_after_grains, finish};
      if (squeeze) return {squeeze_phase, grain_phase, crystal_after_grains, finish};
      return {void_phase, repeller_phase, grain_phase, crystal_after_grains, finish};
    case Method::void_injection: return alone(void_phase);
    case Method::repeller_injection: return alone(repeller_phase);
    case Method::crystal_injection: return {crystal_phase, finish};
    case Method::grain_injection:
      return {grain_phase, crystal_after_grains, finish};
    case Method::squeeze_injection: {
      if (!squeeze) {
        throw InvalidInput(
            "tune: squeeze injection moves disks through the seams of a periodic box "
            "with one radius; here use void or repeller injection (or automatic)");
      }
      Plan alone_squeeze = squeeze_phase;
      alone_squeeze.until = 2.0;
      return {alone_squeeze, finish};  // the repeller adds what a stage left out, if any
    }
    case Method::angle_injection:
      if (!angle) {
        throw InvalidInput("tune: angle injection triangulates the periodic box; here use void, "
                           "repeller or crystal injection (or automatic)");
      }
      return alone(angle_phase);
    case Method::sift_ejection: return alone(sift_phase);
    case Method::attractor_ejection: return {attractor_phase, wide_attractor_phase};
    case Method::crystal_ejection: return alone(crystal_eject_phase);
  }
  return {};
}

/// The last line of defence: the tuned packing gets the exact checks once more. Should
/// it fail them (a bug), it is put back to the closest valid state kept - before the
/// last phase, or as tune got it - and InternalError says which check failed and where.
template <class P>
void check_tuned(P& packing, const P& entry, const P& before_last, Phase last) {
  const std::string defect = packing_defect(packing);
  if (defect.empty()) return;
  std::string kept = "as tune got it";
  if (packing_defect(before_last).empty()) {
    packing = before_last;
    kept = "as it was before that phase";
  } else {
    packing = entry;
  }
  const std::string when = last == Phase::none ? "" : " after the " + to_string(last) + " phase";
  throw InternalError("tune: the packing" + when + " failed the final check: " + defect +
                      ". It was put back " + kept + " (" + std::to_string(packing.size()) +
                      " disks). " + kReportBug);
}

/// Runs the phases in order until the count is `goal` or none makes progress (ejection:
/// in rounds, while a round of them makes some); `unit` is
/// the count at area fraction 1, `after_op(packing)` (if set) runs after each operation.
/// `entry` is the packing as tune got it (valid, before any boundary step); the result
/// is checked by check_tuned unless `final_check` is false (the caller checks it later).
template <class P, class AfterOp>
TuneResult run_phases(P& packing, const P& entry, double unit, std::size_t goal,
                      const std::vector<PhasePlan<P>>& plans, Rng& rng, const TuneOptions& options,
                      const AfterOp& after_op, std::chrono::steady_clock::time_point t0,
                      bool final_check = true) {
  TuneResult result;
  result.target = goal;
  const bool eject = result.target < packing.size();
  // Disks still to add or remove: what each operation may change at most; 0 once the
  // count is at or past the target (no operation may pass it, but a phase must never
  // run on from the wrong side).
  auto missing = [&]() -> std::size_t {
    const std::size_t n = packing.size();
    return eject ? (n > result.target ? n - result.target : 0) : (result.target > n ? result.target - n : 0);
  };
  auto eta = [&] { return static_cast<double>(packing.size()) / unit; };
  // Where the phase hands over at the latest: its area fraction's count, or the target.
  std::size_t phase_goal = goal;
  auto report = [&](Phase phase) {
    if (options.on_progress && !options.on_progress({packing.size(), eta(), phase, phase_goal})) {
      throw Cancelled("tune: cancelled by the progress callback; the packing is as tune got it");
    }
  };

  // A sweep in the order of plan.rank, smallest first: each disk is ranked again when
  // its turn comes (the operations since may have changed it) and goes back into the
  // queue when it now ranks behind the next. Every live disk is tried once; ties keep
  // the random order.
  auto ranked_sweep = [&](const PhasePlan<P>& plan,
                          const std::vector<DiskId>& order) -> std::size_t {
    using Entry = std::tuple<double, std::size_t, DiskId>;  // rank, place in `order`, disk
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    for (std::size_t k = 0; k < order.size(); ++k)
      queue.push({plan.rank(packing, order[k]), k, order[k]});
    const std::size_t tick = std::max<std::size_t>(order.size() / 64, 1);
    for (std::size_t tried = 0; !queue.empty() && missing() > 0;) {
      const auto [ranked, k, d] = queue.top();
      queue.pop();
      if (!packing.alive(d)) continue;
      const double now = plan.rank(packing, d);
      if (now > ranked && !queue.empty() && now > std::get<0>(queue.top())) {
        queue.push({now, k, d});
        continue;
      }
      plan.op(packing, d, rng, missing());
      if (after_op) after_op(packing);
      if (++tried % tick == 0) report(plan.phase);
    }
    return order.size();
  };

  // One sweep of a phase: a whole-packing sweep, or its operation on every disk in
  // random order (or ranked).
  auto run_sweep = [&](const PhasePlan<P>& plan, bool sparse, bool& stalled) -> std::size_t {
    const std::size_t size_before = packing.size();
    if (plan.sweep || plan.polled_sweep) {
      std::size_t steps = 0;
      // What is missing to the phase's goal (squeeze injection adds all of it at once).
      const std::size_t to_phase_goal =
          eject ? missing()
                : std::min(missing(), phase_goal > size_before ? phase_goal - size_before : 0);
      const std::function<void()> after_step = [&] {
        if (after_op) after_op(packing);
        if (++steps % 256 == 0) report(plan.phase);
      };
      if (plan.sweep) {
        plan.sweep(packing, rng, to_phase_goal, after_step);
      } else {
        plan.polled_sweep(packing, rng, to_phase_goal, after_step, [&] { report(plan.phase); });
      }
      return size_before;
    }
    std::vector<DiskId> order = packing.ids();
    for (std::size_t i = order.size(); i > 1; --i)
      std::swap(order[i - 1], order[uniform_index(rng, i)]);
    if constexpr (std::is_same_v<P, Packing>) order = tiled(packing, order, rng);
    if (sparse) {
      std::vector<DiskId> sparsest = sparsest_first(packing, order);
      if (!sparsest.empty()) order = std::move(sparsest);  // else every disk is fixed: all
    }
    if (plan.rank) return ranked_sweep(plan, order);
    const std::size_t tick = std::max<std::size_t>(order.size() / 64, 1);
    const std::size_t part = std::max<std::size_t>(order.size() / 16, 256);  // at least 256 tries
    std::size_t part_start = packing.size();
    for (std::size_t k = 0; k < order.size() && missing() > 0; ++k) {
      if (plan.judge_parts && k > 0 && k % part == 0) {  // the part just done
        const std::size_t now = packing.size();
        const double part_gain =
            static_cast<double>(now > part_start ? now - part_start : part_start - now);
        if (part_gain < std::max(plan.min_gain * static_cast<double>(part), 0.5)) {
          stalled = true;
          return k;
        }
        part_start = now;
      }
      if (!packing.alive(order[k])) continue;
      plan.op(packing, order[k], rng, missing());
      if (after_op) after_op(packing);
      if (k % tick == 0) report(plan.phase);
    }
    return order.size();
  };

  using Clock = std::chrono::steady_clock;
  const auto since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  const auto first_copy = Clock::now();
  std::optional<P> before_phase;  // kept for check_tuned
  if (final_check) before_phase = packing;
  double check_seconds = since(first_copy);
  auto run_phase = [&](const PhasePlan<P>& plan) {
    const auto copy_start = Clock::now();
    if (final_check && result.last_phase != Phase::none)
      before_phase = packing;  // a copy, in place
    check_seconds += since(copy_start);
    result.last_phase = plan.phase;
    phase_goal = eject || plan.until >= 1
                     ? goal
                     : std::min(goal, static_cast<std::size_t>(std::ceil(plan.until * unit)));
    if (plan.thaw) {
      for (const DiskId id : packing.ids()) packing.set_flags(id, packing.flags(id) & ~kFrozen);
    }
    // A sparse-first sweep tries a tenth of the disks: ten of them make one sweep's work.
    // Where they stop paying (the sparsest disks can gain no more, as with radii that
    // vary, where the fewest neighbours mark the smallest disks), sweeps over all go on.
    bool sparse = plan.sparsest;
    double gain = 0, tried = 0;                                    // since progress was last judged
    for (double work = 0; work < options.max_sweeps_per_phase;) {  // in sweeps over all disks
      if (missing() == 0 || (!eject && eta() >= plan.until)) break;
      const std::size_t before = packing.size();
      bool stalled = false;
      const auto now_tried = static_cast<double>(run_sweep(plan, sparse, stalled));
      tried += now_tried;
      work += before > 0 ? now_tried / static_cast<double>(before) : 1;
      ++result.sweeps;
      report(plan.phase);
      if (stalled) break;
      gain += std::abs(static_cast<double>(packing.size()) - static_cast<double>(before));
      // Judged over a whole sweep's worth of tries (one sweep, or ten sparse-first ones).
      if (tried < static_cast<double>(before)) continue;
      if (gain < std::max(std::max(options.min_gain_per_sweep, plan.min_gain) * tried, 0.5)) {
        if (!sparse) break;
        sparse = false;
      }
      gain = tried = 0;
    }
  };
  // Ejection goes round the phases again while a round removed disks: what the later
  // phases moved can let the earlier ones remove more (eight.off to 0.62x: the wide
  // attractor's tail stalled two disks short after 12 s; the one-ring attractor of a
  // second round removed them in 0.7 s).
  for (bool again = true; again;) {
    const std::size_t round_start = packing.size();
    for (const PhasePlan<P>& plan : plans) {
      if (missing() == 0) break;
      run_phase(plan);
    }
    again = eject && missing() > 0 && packing.size() != round_start;
  }
  const auto check_start = Clock::now();
  if (final_check) check_tuned(packing, entry, *before_phase, result.last_phase);
  result.check_seconds = check_seconds + since(check_start);
  result.count = packing.size();
  result.reached = result.count == result.target;
  result.seconds = since(t0);
  return result;
}

}  // namespace disktune::detail
