// SPDX-License-Identifier: GPL-3.0-or-later
// How long the running phase of a tune has left, from its progress reports (tuning.h),
// for a progress bar whose fraction follows the time the work takes rather than the
// count. Within a phase the speed at which disks are added (or removed) falls about
// exponentially with the disks added so far: the voids and gaps left are ever fewer
// (measured on void injection, docs/tuning.md). So the speed and its fall are fitted
// over the latest reports, and the time to the phase's goal follows from them.
#pragma once

#include <cstddef>
#include <vector>

#include "disktune/tuning.h"

namespace disktune {

class PhaseTimeLeft {
 public:
  /// A report `seconds` after the tune started. A report of another phase (or goal)
  /// starts a new fit.
  void add(double seconds, const Progress& progress);

  /// Seconds until the phase reaches its goal (Progress::phase_goal) at the fitted
  /// pace: NaN while there are too few reports to tell or the phase has not changed the
  /// count yet (a squeeze stage adds its disks at its end), infinity where the count has
  /// stopped moving or the fitted pace never gets there (the phase then stalls, and the
  /// schedule moves on).
  double seconds_left() const;
  /// The phase's time so far over that time plus seconds_left(): the share of its work
  /// done (NaN while seconds_left() is, 0 where it is infinite).
  double phase_fraction() const;
  /// Seconds since the phase's first report.
  double phase_seconds() const;
  Phase phase() const { return phase_; }

 private:
  struct Report {
    double seconds;
    double done;  // disks added or removed since the phase's first report
  };
  double window() const;         // the span of the latest reports that the fit reads
  std::vector<Report> reports_;  // the phase's, but those older than the window
  Phase phase_ = Phase::none;
  std::size_t start_ = 0, goal_ = 0, count_ = 0;
  std::size_t first_ = 0;  // the window's first report
  double phase_start_ = 0;
};

}  // namespace disktune
