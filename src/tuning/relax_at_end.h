// SPDX-License-Identifier: GPL-3.0-or-later
// Relaxation maximal at the end (internal): relax(..., Maximality::at_end) with the round
// of void closing from which a void still open gets a disk of its own (and a disk nearby
// is ejected for it) given, so that tests can turn that off and reach the fall-back to
// checking every move (relaxation.cpp).
#pragma once

#include <cstddef>
#include <functional>

#include "disktune/random.h"
#include "disktune/surface_packing.h"

namespace disktune::detail {

/// The round relax uses: after two rounds of checked pulls (most voids close in the
/// first; those left lie among disks held on all sides).
constexpr int kInjectFromRound = 2;
/// Past the last round of void closing: no void gets a disk of its own.
constexpr int kNeverInject = 17;

std::size_t relax_at_end(SurfacePacking& packing, double spacing, int sweeps, Rng& rng,
                         const std::function<bool(int)>& after_sweep, unsigned threads,
                         int inject_from);

}  // namespace disktune::detail
