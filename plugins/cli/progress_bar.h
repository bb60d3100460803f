// SPDX-License-Identifier: GPL-3.0-or-later
// Progress on stderr: on a terminal a one-line bar redrawn at most ten times a second;
// elsewhere (a log, a pipe) a plain line every ten seconds (DISKTUNE_PROGRESS_SECONDS
// sets another interval, 0 a line at every update), none for a job shorter than that. Both
// show the time so far; the caller's status says what the fraction is of.
#pragma once

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "commands.h"

namespace disktune::cli {

class ProgressBar {
 public:
  /// `what` opens each logged line ("tune").
  explicit ProgressBar(std::string what)
      : what_(std::move(what)), terminal_(isatty(STDERR_FILENO) != 0) {
    // A value that is not a number in [0, 10^6) leaves the ten seconds.
    if (const char* every = std::getenv("DISKTUNE_PROGRESS_SECONDS")) {
      char* end = nullptr;
      const double seconds = std::strtod(every, &end);
      if (end != every && *end == '\0' && seconds >= 0 && seconds < 1e6)
        log_every_ = std::chrono::duration<double>(seconds);
    }
  }
  ~ProgressBar() { clear(); }

  /// Seconds since the bar was made.
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

  /// Shows the bar filled to `fraction` (0 to 1; the status says what of), with a short
  /// status after it.
  void update(double fraction, const std::string& status) {
    using namespace std::chrono;
    if (quiet()) return;
    const auto now = steady_clock::now();
    if (now - last_ < (terminal_ ? duration<double>(0.1) : log_every_)) return;
    last_ = now;
    const double f = fraction >= 0 ? std::min(fraction, 1.0) : 0.0;  // NaN: empty
    const double seconds = duration<double>(now - start_).count();
    if (!terminal_) {
      std::fprintf(stderr, "%s: %s, %.1f s so far\n", what_.c_str(), status.c_str(), seconds);
      return;
    }
    constexpr int kWidth = 30;
    const int full = static_cast<int>(f * kWidth + 0.5);
    std::fprintf(stderr, "\r[%s%s] %s, %.1f s\033[K", std::string(full, '#').c_str(),
                 std::string(kWidth - full, '.').c_str(), status.c_str(), seconds);
    std::fflush(stderr);
    drawn_ = true;
  }
  void clear() {
    if (drawn_) std::fprintf(stderr, "\r\033[K");
    drawn_ = false;
  }

 private:
  std::string what_;
  bool terminal_;
  bool drawn_ = false;
  std::chrono::duration<double> log_every_{10.0};
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now(), last_ = start_;
};

}  // namespace disktune::cli
