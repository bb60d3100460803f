// SPDX-License-Identifier: GPL-3.0-or-later
// A one-line progress bar on stderr, drawn only when stderr is a terminal (so logs and
// pipes stay clean), at most ten times a second.
#pragma once

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <string>

namespace disktune::cli {

class ProgressBar {
 public:
  ProgressBar() : live_(isatty(STDERR_FILENO) != 0) {}
  ~ProgressBar() { clear(); }

  /// Shows `done` of `total`, with a short status after the bar.
  void update(double done, double total, const std::string& status) {
    if (!live_) return;
    const auto now = std::chrono::steady_clock::now();
    if (drawn_ && now - last_ < std::chrono::milliseconds(100)) return;
    last_ = now;
    const double f = total > 0 ? std::min(std::max(done / total, 0.0), 1.0) : 0.0;
    constexpr int kWidth = 30;
    const int full = static_cast<int>(f * kWidth + 0.5);
    std::fprintf(stderr, "\r[%s%s] %5.1f%% %s\033[K", std::string(full, '#').c_str(),
                 std::string(kWidth - full, '.').c_str(), 100 * f, status.c_str());
    std::fflush(stderr);
    drawn_ = true;
  }
  void clear() {
    if (drawn_) std::fprintf(stderr, "\r\033[K");
    drawn_ = false;
  }

 private:
  bool live_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point last_{};
};

}  // namespace disktune::cli
