// SPDX-License-Identifier: GPL-3.0-or-later
// What each space gives the one exact check of a packing (internal; packing_defect.cpp
// writes the check once): the first pair in conflict, and the first uncovered place.
// Both search on every core (the packing is only read) and answer what a search in
// order would: the first disk, or triangle, with a defect.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "disktune/packing.h"
#include "disktune/surface_packing.h"

namespace disktune::detail {

/// Two disks each covering the other's center (closer than the smaller radius), or none.
std::optional<std::array<DiskId, 2>> first_conflict(const Packing& packing);
std::optional<std::array<DiskId, 2>> first_conflict(const SurfacePacking& packing);

/// A place no disk covers, as words ("the point (x, y)", "the boundary point (x, y)",
/// "the point (x, y, z) of triangle t"), or none: the packing is maximal.
std::optional<std::string> first_hole(const Packing& packing);
std::optional<std::string> first_hole(const SurfacePacking& packing);

/// Neither of the two: true when the packing is conflict-free and maximal. In the plane
/// one search per disk does both; on a surface the two above.
bool conflict_free_and_maximal(const Packing& packing);
inline bool conflict_free_and_maximal(const SurfacePacking& packing) {
  return !first_conflict(packing) && !first_hole(packing);
}

}  // namespace disktune::detail
