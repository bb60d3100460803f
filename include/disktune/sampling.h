// SPDX-License-Identifier: GPL-3.0-or-later
// Maximal Poisson-disk sampling (MPS).
#pragma once

#include <cstddef>
#include <memory>

#include "disktune/packing.h"
#include "disktune/periodic_box.h"
#include "disktune/planar_domain.h"
#include "disktune/random.h"
#include "disktune/sizing.h"

namespace disktune {

/// The widest spacing of the fixed disks laid out along a planar domain's boundary
/// segments and a surface's sharp feature curves, in units of the local radius: below
/// the sqrt(2) r under which no other disk can encroach on the curve between two
/// consecutive ones (docs/planar.md, "Boundary spacing").
constexpr double kCurveSpacing = 1.2;

struct MpsOptions {
  /// Darts per active cell at each level of the dart-throwing phase.
  double darts_per_active_cell = 1.0;
  /// Refinement levels of the dart phase: each splits the active cells in four and
  /// drops the children one disk covers. Exact void filling finishes the job.
  int levels = 4;
};

struct MpsStats {
  std::size_t darts = 0;         // darts thrown in the dart phase
  std::size_t dart_disks = 0;    // disks accepted in the dart phase
  std::size_t void_cells = 0;    // cells left active after the dart levels
  std::size_t void_disks = 0;    // disks added by exact void elimination
  int levels = 0;               // dart levels run
  // Where the time went, in seconds.
  double darts_seconds = 0, prune_seconds = 0, voids_seconds = 0, build_seconds = 0;
  double check_seconds = 0;  // the final check of the sample (is it still maximal?)
};

/// A maximal Poisson-disk sample of the periodic box with uniform radius r: unbiased
/// dart throwing on a refining background grid (every accepted dart is uniform over
/// the uncovered area), then exact void elimination in the cells still active.
/// Conflict-free and maximal up to kRelTol; ids follow a spatial order. The same seed
/// gives the same sample. Throws InvalidInput for a bad radius.
Packing sample_mps(const PeriodicBox& box, double r, Rng& rng, const MpsOptions& options = {},
                   MpsStats* stats = nullptr);

/// A maximal Poisson-disk sample of a planar domain with uniform radius r (paper,
/// section 7): 1D MPS of the boundary first (sample_boundary: fixed disks on every
/// corner and along the segments), then darts uniform over the domain on a background
/// grid whose covered cells are dropped after each round, then exact void filling: each
/// uncovered void corner in the domain gets a disk at a random point of the void near
/// it (the corner itself when darts miss). The packing is restricted to the domain
/// (Packing::set_domain). Throws InvalidInput for a bad radius.
Packing sample_mps(std::shared_ptr<const PlanarDomain> domain, double r, Rng& rng);

/// The same with spatially varying radii r(x) (paper, section 6): each disk takes the
/// sizing's radius at its center, and a new center must lie outside every disk. The
/// sizing is sampled over the domain first (measure_sizing) and refused when its
/// gradation is too steep (check_gradation).
Packing sample_mps(std::shared_ptr<const PlanarDomain> domain, std::shared_ptr<const Sizing> sizing,
                   Rng& rng);

/// An empty packing of the frame for the sizing's radii, restricted to the domain (none:
/// nullptr): the sizing is sampled (measure_sizing, its figures in `stats`) and refused
/// when too steep (check_gradation). For reading a varying-radius packing back.
Packing sized_packing(const Frame& frame, std::shared_ptr<const PlanarDomain> domain,
                      std::shared_ptr<const Sizing> sizing, SizingStats* stats = nullptr);

/// A maximal sample of the periodic box with spatially varying radii (darts on a grid,
/// then exact void filling; r should be periodic too, or the seam is a steep gradation).
Packing sample_mps(const PeriodicBox& box, std::shared_ptr<const Sizing> sizing, Rng& rng);

}  // namespace disktune
