// SPDX-License-Identifier: GPL-3.0-or-later
// How many threads the library starts. Where a call takes a thread count, 0 means this
// default; where it takes none (the final checks of sample and tune, the restricted
// Delaunay mesh of a surface's samples), it uses this default. Results never depend on
// the number of threads, only the time does.
#pragma once

namespace disktune {

/// Sets the default: at most this many threads per call, 0 for one per core (the
/// default). The command line's --threads sets it. Safe to call from any thread.
void set_default_threads(unsigned threads);
/// The default set, 0 for one per core.
unsigned default_threads();

}  // namespace disktune
