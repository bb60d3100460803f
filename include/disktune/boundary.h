// SPDX-License-Identifier: GPL-3.0-or-later
// Boundary disks of a planar domain (paper, section 7): centers on the boundary
// segments, a disk on every corner, conflict-free in the plane (also across segments
// meeting at sharp corners and across nearby holes) and maximal in 1D: every boundary
// point lies within r of a boundary center. They are fixed (kFixed): the interior
// operations never move or remove them, so the boundary stays covered, and the interior
// voids are then bounded by circles alone (voids.h).
#pragma once
#include <vector>

#include "disktune/packing.h"
#include "disktune/planar_domain.h"
#include "disktune/random.h"

namespace disktune {

/// Which way boundary tuning may change each curve's disk count.
enum class BoundaryChange { any, only_more, only_fewer };

/// The longest even boundary step tune() lets tune_boundary plan, in units of r, however
/// sparse the target: below the sqrt(2) r under which no interior center fits in the
/// circle on two consecutive boundary disks (the angle bound of docs/planar.md,
/// "Boundary spacing"), with room for a sizing's change along one step.
constexpr double kLongestTunedStep = 1.35;

/// The boundary disks in order along each loop of the domain (loop 0 outer).
using BoundaryLoops = std::vector<std::vector<DiskId>>;

/// 1D maximal Poisson-disk sampling of the boundary: a fixed disk on every corner, then
/// each segment's uncovered stretches laid out evenly at most kCurveSpacing r apart where
/// that fits (sampling.h), then darts uniform over the uncovered part of each segment
/// until none is left; radii are the packing's radius_at. Call on a packing with no disks near the boundary (a new
/// one). Throws InvalidInput naming two corners when one lies in the other's disk.
void sample_boundary(Packing& packing, const PlanarDomain& domain, Rng& rng);

/// Fills the 1D voids of the boundary: darts uniform over the part of each segment no
/// fixed disk covers (segments in random order), each a new fixed disk, until none is
/// left. An uncovered point lies outside every fixed disk, so no dart conflicts with
/// another boundary disk.
void fill_boundary_voids(Packing& packing, const PlanarDomain& domain, Rng& rng);

/// 1D tuning of the boundary toward a spacing (paper, 7: boundary disks are adjusted
/// first, then stay fixed). Each segment is a curve between two corner disks, which never
/// move; its other disks move along it by 1D injection and ejection (boundary_inject,
/// boundary_eject) at random disks until it holds the number of disks that spaces them
/// `spacing_factor` times the local radius (r(x), or r; the integral of ds / (factor r)
/// steps, kept within [r, 2r] per step), or until no step changes the count for a while
/// (the segment then keeps what it has); where a step at a disk changes no count, the
/// run of consecutive disks around it is laid out again evenly with one disk less (more)
/// between the two disks bounding it, and at the end sweeps move each disk to the middle
/// of its neighbours (in ds / r) where valid. After every step the boundary disks stay
/// max(r_i, r_j) apart (also across corners and loops) and cover the boundary, and the
/// packing stays conflict-free and maximal. Marks the boundary disks first
/// (boundary_loops), so it also takes a packing read from a file. With `change` other
/// than any, no segment's count moves the other way, and the segments' counts change by
/// at most `budget` disks in all (each scaled down alike): tune() passes the way to its
/// target and how many disks are missing, as in a thin domain nearly every disk is on
/// the boundary, and spacing it for the interior's density would overshoot the target.
/// No segment gets so few disks that its even steps exceed `longest_step` r where it has
/// room for more (tune() passes kLongestTunedStep).
void tune_boundary(Packing& packing, const PlanarDomain& domain, double spacing_factor, Rng& rng,
                   BoundaryChange change = BoundaryChange::any,
                   std::size_t budget = static_cast<std::size_t>(-1), double longest_step = 2);

/// 1D injection or ejection until the boundary holds `change` disks more (fewer when
/// negative), shared among the segments in proportion to their lengths, as far as the
/// steps get (tune_boundary's steps and guarantees). The scheduler's last phase, for
/// domains whose disks are nearly all on the boundary. Returns the net disks added to
/// the boundary (interior disks it displaces are refilled and not counted).
long boundary_tune_by(Packing& packing, const PlanarDomain& domain, long change, Rng& rng);

/// One 1D injection at a movable boundary disk p drawn at random (paper 2.1 along the
/// boundary): p moves to one end, at random, of the stretch of its segment its
/// neighbours leave uncovered without it, and new fixed disks fill what is left of that
/// stretch from there. Interior disks in conflict with a moved or new boundary disk (the
/// latest arrival) are removed and every region a disk left is refilled, so the
/// boundary stays conflict-free and 1D maximal and the packing conflict-free and
/// maximal. Returns the number of disks added to the boundary: 0 when p only moved or
/// had no room.
long boundary_inject(Packing& packing, const PlanarDomain& domain, Rng& rng);

/// One 1D ejection at a movable boundary disk p drawn at random (the attractor, paper
/// 3.1, along the boundary): p's two neighbours on its segment (unless corners) move
/// toward it as far as they can while keeping their other sides covered and no conflict;
/// if they then cover p's stretch, p is removed, else p moves to the middle of what is
/// left of its void (or nothing changes). The interior is repaired as in
/// boundary_inject. Returns -1 when p was removed, else 0.
long boundary_eject(Packing& packing, const PlanarDomain& domain, Rng& rng);

/// The disks of `packing` whose centers lie on the domain's boundary (within 1e-9 r),
/// flagged fixed, in order along each loop; the others lose the fixed flag. For a
/// packing read from a file. Throws InvalidInput when a corner has no disk.
BoundaryLoops boundary_loops(Packing& packing, const PlanarDomain& domain);

}  // namespace disktune
