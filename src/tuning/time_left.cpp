// SPDX-License-Identifier: GPL-3.0-or-later
#include "disktune/time_left.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace disktune {
namespace {

constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();
constexpr double kNever = std::numeric_limits<double>::infinity();

}  // namespace

void PhaseTimeLeft::add(double seconds, const Progress& progress) {
  if (reports_.empty() || progress.phase != phase_ || progress.phase_goal != goal_) {
    reports_.clear();
    phase_ = progress.phase;
    goal_ = progress.phase_goal;
    start_ = progress.count;
    phase_start_ = seconds;
    first_ = 0;
  }
  count_ = progress.count;
  const double done = std::fabs(static_cast<double>(progress.count) - static_cast<double>(start_));
  reports_.push_back({seconds, done});
  // Only the window's reports count (seconds_left), and its start never goes back: the
  // older ones are passed for good, and dropped now and then.
  while (first_ + 1 < reports_.size() && seconds - reports_[first_].seconds > window()) ++first_;
  if (first_ >= 1024 && 2 * first_ >= reports_.size()) {
    reports_.erase(reports_.begin(), reports_.begin() + static_cast<std::ptrdiff_t>(first_));
    first_ = 0;
  }
}

double PhaseTimeLeft::phase_seconds() const {
  return reports_.empty() ? 0 : reports_.back().seconds - phase_start_;
}

double PhaseTimeLeft::window() const {
  // The last 30 % of the phase's time, at least half a second of it (the pace drifts; a
  // short window follows it, a long one smooths the noise).
  return std::max(0.5, 0.3 * phase_seconds());
}

double PhaseTimeLeft::seconds_left() const {
  const double left = std::fabs(static_cast<double>(goal_) - static_cast<double>(count_));
  if (left == 0) return 0;
  if (reports_.size() < 4) return kUnknown;
  const Report& now = reports_.back();
  const auto first = reports_.begin() + static_cast<std::ptrdiff_t>(first_);  // the window's first
  const auto middle = std::lower_bound(first, reports_.end(), (first->seconds + now.seconds) / 2,
                                       [](const Report& r, double t) { return r.seconds < t; });
  if (reports_.end() - first < 4 || !(now.seconds > first->seconds)) return kUnknown;
  // Nothing done yet in the phase: not a stall, a pace not seen yet (a squeeze stage
  // adds all its disks at its end).
  if (!(now.done > 0)) return kUnknown;
  const double moved = now.done - first->done;
  if (!(moved > 0)) return kNever;
  double pace = moved / (now.seconds - first->seconds);  // disks per second
  // The fall of the pace: from the window's first half to its second, per disk done.
  if (middle != first && middle != reports_.end() - 1 && middle->seconds > first->seconds &&
      now.seconds > middle->seconds) {
    const double early = (middle->done - first->done) / (middle->seconds - first->seconds);
    const double late = (now.done - middle->done) / (now.seconds - middle->seconds);
    const double early_at = (first->done + middle->done) / 2,
                 late_at = (middle->done + now.done) / 2;
    if (late > 0 && early > late && late_at > early_at) {
      const double fall = std::log(early / late) / (late_at - early_at);
      pace = late * std::exp(-fall * (now.done - late_at));
      // The time to do `left` more disks at pace(x) = pace e^(-fall x).
      const double exponent = fall * left;
      return exponent > 50 ? kNever : std::expm1(exponent) / (fall * pace);
    }
  }
  return left / pace;
}

double PhaseTimeLeft::phase_fraction() const {
  const double left = seconds_left();
  if (std::isnan(left)) return kUnknown;
  if (std::isinf(left)) return 0;
  const double so_far = phase_seconds();
  return so_far + left > 0 ? so_far / (so_far + left) : 1;
}

}  // namespace disktune
