// SPDX-License-Identifier: GPL-3.0-or-later
// Disks in a periodic box pushed apart as soft disks (internal): every pair closer than
// r repels like a spring, and the positions follow FIRE, the fast inertial relaxation of
// Bitzek, Koskinen, Gähler, Moseler and Gumbsch (2006), with the half step back on a
// restart of its 2.0 version (Guénolé et al., 2020). Every disk moves at every step,
// computed from the positions of the step before: on any number of threads the same
// arithmetic in the same order, so the same positions.
#pragma once

#include <functional>
#include <vector>

#include "disktune/frame.h"
#include "disktune/geometry.h"

namespace disktune::detail {

/// Whether a box is wide enough for the relaxation's cells (3 across each way, about
/// 3.6 r).
bool soft_disks_fit(const Frame& frame, double r);

/// Moves the disks at `x` (relative to the frame's origin, ends wrapped into
/// [0, extent)) until no two are closer than `stop` (some fraction of r just below 1), or
/// `max_steps` steps have passed. Returns whether they got there. Only the positions
/// matter: nothing is checked or kept of the packing they came from. `poll`, where set,
/// is called every kPollSteps steps; it may throw (and `x` is then lost).
bool relax_soft_disks(const Frame& frame, double r, std::vector<Vec2>& x, double stop,
                      long max_steps, unsigned threads, const std::function<void()>& poll = {});

/// How many steps pass between two calls of relax_soft_disks's `poll` (about 0.3 s at
/// 10^6 disks on two cores).
constexpr long kPollSteps = 16;

}  // namespace disktune::detail
