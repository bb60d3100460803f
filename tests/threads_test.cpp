// SPDX-License-Identifier: GPL-3.0-or-later
// The thread loops (src/geometry/threads.h) on the waiting team of thread_team.cpp:
// every item handled once, by a thread index below the count asked for, whether the
// calls come one after another, from two threads at once, from within an item, after
// an exception, or in a child process made by fork (whose team's threads fork did not
// copy). Counted with atomics, item by item.
#include "../src/geometry/threads.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstddef>
#include <stdexcept>
#include <thread>
#include <vector>

namespace disktune {
namespace {

// g++ names ThreadSanitizer with a macro, clang with a feature.
#if defined(__SANITIZE_THREAD__)
constexpr bool kThreadSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
constexpr bool kThreadSanitizer = true;
#else
constexpr bool kThreadSanitizer = false;
#endif
#else
constexpr bool kThreadSanitizer = false;
#endif

// parallel_for over `count` items on `threads` threads: true when each item ran once,
// on a thread index below `threads`.
bool each_once(std::size_t count, unsigned threads) {
  std::vector<std::atomic<int>> runs(count);
  std::atomic<bool> index_ok{true};
  detail::parallel_for(count, threads, [&](std::size_t i, unsigned t) {
    runs[i].fetch_add(1);
    if (t >= threads) index_ok = false;
  });
  for (const auto& r : runs)
    if (r.load() != 1) return false;
  return index_ok.load();
}

TEST(Threads, EveryItemOnceOnEveryCountOfThreadsCallAfterCall) {
  for (int round = 0; round < 300; ++round)
    for (const unsigned threads : {1u, 2u, 3u, 4u, 8u})
      for (const std::size_t count : {0u, 1u, 2u, 7u, 64u, 1000u})
        ASSERT_TRUE(each_once(count, threads)) << count << " items, " << threads << " threads";
}

TEST(Threads, RunTogetherRunsEachPartOnceAndReturnsAfterAll) {
  for (int round = 0; round < 2000; ++round) {
    const unsigned n = 2 + round % 7;
    std::vector<std::atomic<int>> runs(n);
    detail::run_together(n, [&](unsigned t) {
      if (t % 2 == 1) std::this_thread::yield();  // parts that end at different times
      runs[t].fetch_add(1);
    });
    // Every part ran once before the call returned (no thread is refused here).
    for (unsigned t = 0; t < n; ++t) ASSERT_EQ(runs[t].load(), 1) << "part " << t << " of " << n;
  }
}

TEST(Threads, CallsFromTwoThreadsAtOnceAndFromWithinAnItem) {
  std::atomic<bool> ok{true};
  const auto calls = [&] {
    for (int round = 0; round < 200; ++round) {
      if (!each_once(500, 2)) ok = false;
      // An item that makes a call of its own (the team is taken: new threads).
      std::atomic<int> inner{0};
      detail::parallel_for(4, 2, [&](std::size_t, unsigned) {
        if (each_once(50, 2)) inner.fetch_add(1);
      });
      if (inner.load() != 4) ok = false;
    }
  };
  std::thread other(calls);
  calls();
  other.join();
  EXPECT_TRUE(ok.load());
}

TEST(Threads, AnExceptionReachesTheCallerAndTheTeamWorksOn) {
  for (int round = 0; round < 50; ++round) {
    EXPECT_THROW(detail::parallel_for(100, 2,
                                      [&](std::size_t i, unsigned) {
                                        if (i == 37) throw std::runtime_error("item 37");
                                      }),
                 std::runtime_error);
    ASSERT_TRUE(each_once(300, 2));
  }
}

TEST(Threads, AChildProcessMadeByForkRunsItsLoops) {
  if (kThreadSanitizer)
    GTEST_SKIP() << "ThreadSanitizer starts no thread in a child forked from a threaded process";
  ASSERT_TRUE(each_once(1000, 2));  // the team is made, its threads waiting
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    alarm(20);  // a loop that waited for the parent's threads would hang: SIGALRM ends it
    bool ok = true;
    for (int round = 0; round < 20; ++round) ok = ok && each_once(1000, 2);
    _exit(ok ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFEXITED(status)) << "the child was killed by signal " << WTERMSIG(status);
  if (WIFEXITED(status)) {
    EXPECT_EQ(WEXITSTATUS(status), 0);
  }
}

}  // namespace
}  // namespace disktune
