// SPDX-License-Identifier: GPL-3.0-or-later
// The checks of a radius every domain shares (internal): finite and positive, and not
// so small that a packing could not even number its disks. Whether the job fits in the
// memory at hand is another question, asked before any work by check_resources
// (resources.h).
#pragma once

#include <string>

namespace disktune::detail {

/// The most disks a packing can hold: they are numbered with 32-bit ids (DiskId), and
/// the grids index their cells with int.
constexpr double kMaxDisks = 4e9;

/// Throws InvalidInput unless r is finite and positive and a maximal packing of a
/// domain of this area (about 0.7 A / r^2 disks) holds at most kMaxDisks disks;
/// `domain` names it in the message ("the 1 x 1 box", "this domain of area 0.8").
void check_radius_for_area(double r, double area, const std::string& domain);

}  // namespace disktune::detail
