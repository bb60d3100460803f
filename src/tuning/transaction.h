// SPDX-License-Identifier: GPL-3.0-or-later
// A whole tune() as a transaction: a copy of the packing as it came in is put back
// unless the work ends normally, so an exception (a cancel, an error thrown by a
// callback, std::bad_alloc) never leaves a half-tuned packing behind.
#pragma once

#include <utility>

#include "disktune/errors.h"

namespace disktune::detail {

/// Runs work(entry), `entry` a copy of `packing` as it came in, and returns its result.
/// When work throws, `packing` is that copy again - except on InternalError, whose
/// thrower (check_tuned) has already put back the closest valid state it kept.
template <class P, class Work>
auto as_transaction(P& packing, Work&& work) {
  struct Guard {
    P& live;
    P saved;
    bool done = false;
    // Moving the copy back allocates nothing, so it cannot fail while unwinding.
    ~Guard() {
      if (!done) live = std::move(saved);
    }
  } guard{packing, packing};
  try {
    auto result = work(static_cast<const P&>(guard.saved));
    guard.done = true;
    return result;
  } catch (const InternalError&) {
    guard.done = true;
    throw;
  }
}

}  // namespace disktune::detail
