// SPDX-License-Identifier: GPL-3.0-or-later
// Planar void corners: the uncovered intersection points of disk boundaries. A void
// (the uncovered region) is an arc-gon; its vertices are corners. The union of closed
// disks covers the domain exactly when no corner is uncovered and no circle is
// isolated, so corners are both how voids are found and how maximality is certified.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "disktune/geometry.h"
#include "disktune/packing.h"

namespace disktune {

/// An intersection point of the boundaries of disks `a` and `b` that no other disk
/// covers. `point` is in the unwrapped frame of the query that produced it. On an
/// isolated circle (no other circle meets it) a single point of it is reported, with
/// `b == kNoDisk`.
struct Corner {
  Vec2 point;
  DiskId a;
  DiskId b;
};

/// Appends to `out` the uncovered corners on the boundary of disk `p`: where the void
/// next to p, if any, touches p. Empty exactly when p's circle is covered by others.
void corners_on_circle(const Packing& packing, DiskId p, std::vector<Corner>& out);

/// Appends to `out` the uncovered corners inside the closed disk D(center, R), treating
/// the disks in `ignore` as absent (e.g. a disk just lifted to compute its void).
/// `center` may be given in any unwrapped frame; corners come in that frame.
void corners_in_region(const Packing& packing, Vec2 center, double R,
                       const std::vector<DiskId>& ignore, std::vector<Corner>& out);

/// The parts of segment [a, b] no disk covers, as sorted disjoint parameter intervals
/// [t0, t1] of a + t (b - a), t in [0, 1]: the 1D voids of a boundary segment. With
/// `fixed_only`, only fixed disks count (the boundary disks, which alone must cover the
/// boundary). Expected time O(length / r + disks found).
std::vector<std::array<double, 2>> uncovered_on_segment(const Packing& packing, Vec2 a, Vec2 b,
                                                        bool fixed_only);

/// True when no corner of the whole packing is uncovered and no circle is isolated,
/// and, in a planar domain, no boundary point is uncovered: the packing is maximal (up
/// to the tolerance). Linear time.
bool is_maximal(const Packing& packing);

/// True when no two disks cover each other's centers (the prior-disk rule, pairwise: a
/// center may lie in a larger disk, which came later). Linear time.
bool is_conflict_free(const Packing& packing);

/// Throws InvalidInput unless the packing is non-empty, conflict-free and maximal,
/// naming a conflicting pair or an uncovered point; `what` names the input in the
/// message (e.g. a file name). Linear time.
void validate_packing(const Packing& packing, const std::string& what);

/// What makes the packing invalid, as a phrase naming the place, every digit of it: no
/// disks, a conflicting pair first ("the disks centered at (x, y) and (x, y) cover each
/// other's centers (a conflict): they are closer than r"), then a hole ("not maximal: the point (x, y) is covered by no
/// disk"); empty when it is conflict-free and maximal. One check for every space
/// (packing_defect.cpp), the same words on a surface.
std::string packing_defect(const Packing& packing);

}  // namespace disktune
