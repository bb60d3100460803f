// SPDX-License-Identifier: GPL-3.0-or-later
#include "disktune/threads.h"

#include <atomic>

namespace disktune {
namespace {

std::atomic<unsigned> g_default_threads{0};

}  // namespace

void set_default_threads(unsigned threads) { g_default_threads = threads; }
unsigned default_threads() { return g_default_threads; }

}  // namespace disktune
