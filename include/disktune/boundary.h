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

/// The boundary disks in order along each loop of the domain (loop 0 outer).
using BoundaryLoops = std::vector<std::vector<DiskId>>;

/// 1D maximal Poisson-disk sampling of the boundary: a fixed disk on every corner, then
/// darts uniform over the uncovered part of each segment until none is left; radii are
/// the packing's radius_at. Call on a packing with no disks near the boundary (a new
/// one). Throws InvalidInput naming two corners when one lies in the other's disk.
void sample_boundary(Packing& packing, const PlanarDomain& domain, Rng& rng);

/// Fills the 1D voids of the boundary: darts uniform over the part of each segment no
/// fixed disk covers (segments in random order), each a new fixed disk, until none is
/// left. An uncovered point lies outside every fixed disk, so no dart conflicts with
/// another boundary disk.
void fill_boundary_voids(Packing& packing, const PlanarDomain& domain, Rng& rng);

/// 1D tuning of the boundary toward a spacing (paper, 7: boundary disks are adjusted
/// first, then stay fixed): the disks between the corners of each segment are replaced
/// by ones spaced `spacing_factor` times the local radius (r(x), or r), as many as make
/// the spacing closest to that, kept within [r, 2r]; those in conflict across corners
/// or loops are dropped and the 1D voids left refilled. Interior disks in conflict with
/// the new boundary disks are removed and the interior voids this leaves refilled, so
/// the packing stays conflict-free and maximal.
void tune_boundary(Packing& packing, const PlanarDomain& domain, double spacing_factor, Rng& rng);

/// The disks of `packing` whose centers lie on the domain's boundary (within 1e-9 r),
/// flagged fixed, in order along each loop; the others lose the fixed flag. For a
/// packing read from a file. Throws InvalidInput when a corner has no disk.
BoundaryLoops boundary_loops(Packing& packing, const PlanarDomain& domain);

}  // namespace disktune
