// SPDX-License-Identifier: GPL-3.0-or-later
// Work spread over threads (internal): how many threads a count asks for, a loop that
// hands items out one at a time to that many threads, and the first item a test holds
// for. Callers make each item's result independent of which thread ran it, so results
// do not depend on the count.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "disktune/threads.h"

namespace disktune::detail {

/// The number of threads asked for, 0 meaning the default (set_default_threads), and
/// where that is 0 too, one per core.
inline unsigned thread_count(unsigned threads) {
  if (threads == 0) threads = default_threads();
  return threads > 0 ? threads : std::max(1u, std::thread::hardware_concurrency());
}

/// job(t) for t = 0 on the caller's thread and t = 1, ..., n - 1 on other threads at
/// once, returning when every call has: on threads kept waiting from one call to the
/// next (thread_team.cpp), or where those are taken (a call on another thread, or from
/// within a job), on threads made for it. Where no thread can be had, fewer t run: a
/// job must give the same result for any number of them from 1 up. A job must not
/// throw (parallel_for's catches and hands the exception on).
void run_together(unsigned n, const std::function<void(unsigned)>& job);

/// work(item, thread) for every item in [0, count), on up to `threads` threads (the
/// caller's among them; `thread` in [0, threads) names the one running it, for scratch
/// space of its own). The first exception thrown is rethrown once all have stopped;
/// the other threads stop after their current item.
template <class Work>
void parallel_for(std::size_t count, unsigned threads, Work&& work) {
  const auto n = static_cast<unsigned>(std::min<std::size_t>(std::max(threads, 1u), count));
  if (n <= 1) {
    for (std::size_t i = 0; i < count; ++i) work(i, 0u);
    return;
  }
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_lock;
  const auto run = [&](unsigned thread) {
    try {
      for (std::size_t i; (i = next++) < count;) work(i, thread);
    } catch (...) {
      const std::lock_guard<std::mutex> hold(failure_lock);
      if (!failure) failure = std::current_exception();
      next = count;
    }
  };
  run_together(n, [&run](unsigned thread) { run(thread); });
  if (failure) std::rethrow_exception(failure);
}

/// fill(from, to, part) for the items [0, count) in chunks on up to `threads` threads,
/// each chunk with a `part` of its own (a default Part); then join(part) for the chunks
/// in order: what one loop over the items would give, whatever the thread count. Some
/// 64 chunks where the items are few (a sphere of 320 triangles, each split into a
/// thousand cells), else 512 items each.
template <class Part, class Fill, class Join>
void ordered_chunks(std::size_t count, unsigned threads, Fill&& fill, Join&& join) {
  const std::size_t chunk_size = std::clamp<std::size_t>(count / 64, 1, 512);
  std::vector<Part> parts((count + chunk_size - 1) / chunk_size);
  parallel_for(parts.size(), threads, [&](std::size_t chunk, unsigned) {
    fill(chunk * chunk_size, std::min(count, (chunk + 1) * chunk_size), parts[chunk]);
  });
  for (Part& part : parts) join(part);
}

/// The smallest i in [0, count) for which found(i) holds, or `count` where none does:
/// items in chunks on up to `threads` threads, each chunk in order, a chunk skipped
/// once a smaller i is known. The answer is the one a plain loop would give.
template <class Found>
std::size_t first_index(std::size_t count, unsigned threads, Found&& found) {
  constexpr std::size_t kChunk = 256;
  std::atomic<std::size_t> best{count};
  parallel_for((count + kChunk - 1) / kChunk, threads, [&](std::size_t chunk, unsigned) {
    const std::size_t end = std::min(count, (chunk + 1) * kChunk);
    for (std::size_t i = chunk * kChunk; i < end && i < best.load(); ++i) {
      if (!found(i)) continue;
      for (std::size_t seen = best.load(); i < seen && !best.compare_exchange_weak(seen, i);) {
      }
      return;
    }
  });
  return best.load();
}

}  // namespace disktune::detail
