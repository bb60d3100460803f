// SPDX-License-Identifier: GPL-3.0-or-later
// What a sampling or tuning job will need, estimated before any work: how many disks
// it holds and its peak memory, for every domain kind with one radius or a sizing; the
// memory this process may still use; and the one guard that refuses a job that would
// not fit (docs/sizing.md, "What a job needs").
#pragma once

#include <string>

#include "disktune/density.h"
#include "disktune/periodic_box.h"
#include "disktune/planar_domain.h"
#include "disktune/sizing.h"
#include "disktune/surface_domain.h"
#include "disktune/surface_sizing.h"

namespace disktune {

/// The estimate of one job. `disks` and `bytes` are what the guard compares; the
/// other figures say where they come from.
struct ResourceEstimate {
  double unit = 0;   ///< disks at area fraction 1: the integral of 4 / (pi r(x)^2)
  double disks = 0;  ///< the most disks the job holds: its maximal sample's, or the tuning target's if more
  double bytes = 0;  ///< its peak memory, in bytes
  double min_radius = 0, max_radius = 0;  ///< the radii's range over the domain
  /// Disks in the fullest cell of the neighbour grid (cells as wide as the largest
  /// radius; box and planar domains, 0 on a surface): (r_max / r_min)^2 grows it.
  double densest_cell = 0;
  std::string subject;  ///< "radius 0.01" or "the sizing \"0.01 + 0.02*x\"", for messages
  std::string where;    ///< "the 1 x 1 box", "this domain of area 0.8", "this surface of area 1.02"

  /// The same job tuned to `count` disks after sampling (a count below the sample's
  /// changes nothing: sampling holds more then).
  ResourceEstimate tuned_to(double count) const;

  // The model's parts (resources.cpp): the neighbour grid, plus sampling or, when
  // tuned, the larger of sampling and tuning.
  double sample_bytes = 0;    ///< sampling: its disks and the dart cells
  double dart_cells = 0;      ///< cells as small as the smallest radius over the whole frame
  double grid_cells = 0;      ///< cells of the neighbour grid (box and planar domains)
  double bytes_per_disk = 0;  ///< while tuning
};

/// Estimates, without sampling, a maximal sample of the domain (area fraction
/// kMpsAreaFraction) with one radius r or the sizing's radii. A sizing is sampled over
/// the domain as measure_sizing and density_integral do (about 2 x 250 000 values of
/// r), and its fullest neighbour-grid cell is found (densest_cell_integral). Throws
/// InvalidInput where r is not finite and positive.
ResourceEstimate estimate_resources(const PeriodicBox& box, double r);
ResourceEstimate estimate_resources(const PeriodicBox& box, const Sizing& sizing);
ResourceEstimate estimate_resources(const PlanarDomain& domain, double r);
ResourceEstimate estimate_resources(const PlanarDomain& domain, const Sizing& sizing);
ResourceEstimate estimate_resources(const SurfaceDomain& surface, const SurfaceSizing& sizing);

/// The bytes this process may still allocate: the smallest of the system's
/// MemAvailable (/proc/meminfo), the soft RLIMIT_AS and RLIMIT_DATA less what is in
/// use, and the cgroup's memory limit less its usage (v2 memory.max, v1
/// memory.limit_in_bytes). Infinity where none of them can be read.
double available_memory();

/// The guard every sampling and tuning front end calls before any work. Throws
/// InvalidInput (Remedy::memory) when estimate.bytes exceeds `limit` bytes, naming the
/// disks, the bytes, the limit and the radius that would fit; and (Remedy::sizing) when
/// the radii vary so much that one neighbour-grid cell would hold more disks than a
/// cell can (kMaxCellDisks).
void check_resources(const ResourceEstimate& estimate, double limit);

/// The most disks the guard lets into one neighbour-grid cell: a cell can hold 32768
/// (16-bit counts); half that leaves room for a random packing's fluctuations.
constexpr double kMaxCellDisks = 16384;

}  // namespace disktune
