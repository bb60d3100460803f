// SPDX-License-Identifier: GPL-3.0-or-later
// run_together (threads.h) on a team of threads kept waiting between calls. Making a
// thread and joining it cost 30-90 us on this project's machines (2026-12-06), and
// waking one that sleeps about 60 us, where relaxation makes some 300 calls a run of a
// millisecond or less each (a colour of its cubes). So a team thread that has done its
// part stays awake a little while for the next call before it sleeps: relaxation's
// calls come closer together than that, and an awake thread takes the next at once.
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "threads.h"

namespace disktune::detail {
namespace {

// How long a thread waits awake before it sleeps: long enough to bridge relaxation's
// serial steps between two calls, short enough that an idle process soon stops using
// cores. Awake it yields the core to any thread that has work (with more threads than
// cores a thread that spun without yielding made a loop of 9,000 small calls 9x slower
// than making threads for each; yielding, 14x faster).
// Threads past one per core sleep at once: awake, even yielding, they kept the ones with
// work from the cores (that loop, eight threads on two cores, with two other processes
// busy: 10.5 s awake).
constexpr std::chrono::microseconds kAwake{500}, kAsleep{0};

class Team {
 public:
  // job(t) for t in [0, n) as run_together says, or false (nothing run) where the team
  // is taken, or this is a child process whose team's threads were not copied by fork.
  bool try_run(unsigned n, const std::function<void(unsigned)>& job) {
    // A flag, not a mutex: a job may call again on the same thread, where try_lock on a
    // mutex the thread holds is undefined.
    if (getpid() != pid_ || busy_.exchange(true, std::memory_order_acquire)) return false;
    struct Release {
      std::atomic<bool>& busy;
      ~Release() { busy.store(false, std::memory_order_release); }
    } release{busy_};
    const std::uint64_t last = call_.load(std::memory_order_relaxed);
    while (members_.size() + 1 < std::min(n, kMost)) {
      try {
        members_.emplace_back(
            [this, t = static_cast<unsigned>(members_.size() + 1), last] { serve(t, last); });
      } catch (...) {  // no thread to be had (std::system_error, std::bad_alloc)
        break;         // fewer threads: the same result, later
      }
    }
    const auto helpers = static_cast<unsigned>(std::min<std::size_t>(n - 1, members_.size()));
    job_ = &job;
    left_.store(helpers, std::memory_order_relaxed);
    {
      const std::lock_guard<std::mutex> hold(lock_);
      call_.store(((last >> 16) + 1) << 16 | helpers, std::memory_order_release);
    }
    wake_.notify_all();
    job(0);
    // The others' parts: awake a little while, then asleep until the last one is done.
    const auto until = std::chrono::steady_clock::now() + (n <= cores_ ? kAwake : kAsleep);
    while (left_.load(std::memory_order_acquire) > 0 && std::chrono::steady_clock::now() < until)
      std::this_thread::yield();
    if (left_.load(std::memory_order_acquire) > 0) {
      std::unique_lock<std::mutex> hold(lock_);
      done_.wait(hold, [&] { return left_.load(std::memory_order_acquire) == 0; });
    }
    return true;
  }

 private:
  static constexpr unsigned kMost = 1u << 16;  // threads in a call: the helpers fit 16 bits

  // Team thread t, made after call `seen`: each later call's part where it takes part,
  // waiting for the next call in between.
  void serve(unsigned t, std::uint64_t seen) {
    for (;;) {
      const auto until = std::chrono::steady_clock::now() + (t < cores_ ? kAwake : kAsleep);
      while (call_.load(std::memory_order_acquire) == seen &&
             std::chrono::steady_clock::now() < until)
        std::this_thread::yield();
      if (call_.load(std::memory_order_acquire) == seen) {
        std::unique_lock<std::mutex> hold(lock_);
        wake_.wait(hold, [&] { return call_.load(std::memory_order_acquire) != seen; });
      }
      // The call and who takes part in one word: a thread that skipped a call reads the
      // one it now sees, never parts of two. Its job stays set until its helpers are done.
      seen = call_.load(std::memory_order_acquire);
      if (t > (seen & 0xffff)) continue;
      (*job_)(t);
      if (left_.fetch_sub(1, std::memory_order_acq_rel) == 1) {
        const std::lock_guard<std::mutex> hold(lock_);
        done_.notify_one();
      }
    }
  }

  std::atomic<bool> busy_{false};  // set by the call the team works on
  const unsigned cores_ = std::max(1u, std::thread::hardware_concurrency());
  const pid_t pid_ = getpid();
  std::vector<std::thread> members_;  // team thread t is members_[t - 1]
  // Set by the caller before it counts the call, read by the helpers after they see it.
  const std::function<void(unsigned)>* job_ = nullptr;
  // The calls so far (bits 16 up) and the helpers taking part in the last (bits 0-15).
  std::atomic<std::uint64_t> call_{0};
  std::atomic<unsigned> left_{0};  // helpers still on the current call
  std::mutex lock_;                // for the sleepers' condition variables
  std::condition_variable wake_, done_;
};

}  // namespace

void run_together(unsigned n, const std::function<void(unsigned)>& job) {
  if (n <= 1) {
    job(0);
    return;
  }
  // Never destroyed: its threads wait for calls until the process ends, and none may
  // outlive a team destroyed at exit while another thread still calls.
  static Team* const team = new Team;
  if (team->try_run(n, job)) return;
  std::vector<std::thread> helpers;
  for (unsigned t = 1; t < n; ++t) {
    try {
      helpers.emplace_back(job, t);
    } catch (...) {  // no thread to be had: fewer threads, the same result later
      break;
    }
  }
  job(0);
  for (std::thread& t : helpers) t.join();
}

}  // namespace disktune::detail
