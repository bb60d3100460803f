// SPDX-License-Identifier: GPL-3.0-or-later
// Sizing functions r(x): the disk radius wanted at each point (paper, section 6). Small
// disks near features, large ones far away. A sizing is a plain function with a name;
// measure_sizing samples it over a domain for its range and its gradation (Lipschitz
// constant L), which bounds the mesh quality a packing can guarantee.
#pragma once
#include <cstddef>
#include <functional>
#include <memory>
#include <string>

#include "disktune/frame.h"
#include "disktune/geometry.h"
#include "disktune/planar_domain.h"

namespace disktune {

class Sizing {
 public:
  /// `r` must be cheap, deterministic, and finite and positive over the domain.
  Sizing(std::function<double(Vec2)> r, std::string description)
      : r_(std::move(r)), description_(std::move(description)) {}
  double operator()(Vec2 x) const { return r_(x); }
  /// What the sizing is, for messages and reports (e.g. "0.01 + 0.02*x").
  const std::string& description() const { return description_; }

 private:
  std::function<double(Vec2)> r_;
  std::string description_;
};

/// r(x) = r everywhere. Throws InvalidInput unless r is finite and positive.
Sizing constant_sizing(double r);

/// An expression in x and y (muParser syntax: + - * / ^, sin, cos, exp, sqrt, abs, min,
/// max, pi, ...). Throws InvalidInput naming the position of a syntax error or an
/// unknown variable. Copies share one parser; calls from several threads are serialized.
Sizing expression_sizing(const std::string& expression);

/// A gridded field read from a text file: a line `nx ny x0 y0 x1 y1` (nx, ny >= 2,
/// x0 < x1, y0 < y1), then ny lines of nx radii (row j at y = y0 + j (y1 - y0)/(ny - 1),
/// column i at x = x0 + i (x1 - x0)/(nx - 1); '#' comments and blank lines allowed),
/// bilinearly interpolated and clamped at the grid's edges. Throws IoError when the file
/// cannot be read, InvalidInput naming the line for bad content (non-positive radius,
/// wrong count).
Sizing grid_sizing(const std::string& path);

/// Distance-to-boundary grading for a planar domain: r(x) = min(r_max, r_min + g d(x)),
/// d the distance to the nearest boundary segment, g the grading (the Lipschitz
/// constant of r). Throws InvalidInput unless 0 < r_min <= r_max and 0 <= g.
Sizing boundary_grading_sizing(std::shared_ptr<const PlanarDomain> domain, double r_min,
                               double r_max, double g);

/// The share of the local feature size a feature sizing gives the radius: under a half,
/// so that every segment holds a disk between its two corner disks and facing boundary
/// parts stay at least 2.2 r apart (docs/sizing.md, "Feature sizing").
constexpr double kFeatureShare = 0.45;
/// The gradation (Lipschitz constant) of a feature sizing unless told otherwise: it
/// keeps Delaunay angles above 14.5 degrees (angle_bound_degrees).
constexpr double kFeatureGradation = 0.2;

/// Local feature size sizing for a planar domain: r(x) = min(r_max, the smallest
/// kFeatureShare lfs(p) + gradation |x - p| over boundary sites p), where lfs(p) is the
/// distance from p to the nearest boundary segment other than p's own and those next to
/// it along its loop (at a polygon vertex: the nearest segment not ending there). The
/// radius shrinks near thin parts, close holes and short segments, grows away from them
/// at the gradation, and is r_max elsewhere; it is `gradation`-Lipschitz. Sites lie on the
/// boundary a quarter of their radius apart; evaluating r searches them (a kd-tree,
/// branch and bound) in about logarithmic time. Throws InvalidInput unless r_max > 0 and 0 < gradation < 0.5.
Sizing feature_sizing(std::shared_ptr<const PlanarDomain> domain, double r_max,
                      double gradation = kFeatureGradation);

/// Parses the command line's --sizing, trying in this order: a number (constant),
/// "boundary:RMIN,RMAX,G" and "auto:RMAX[,G]" (feature_sizing) (for a planar domain only:
/// throws InvalidInput when domain is null), a path to an existing file (grid_sizing), else an expression.
Sizing parse_sizing(const std::string& spec, std::shared_ptr<const PlanarDomain> domain);

/// What sampling r over a domain found.
struct SizingStats {
  double min = 0, max = 0;
  /// Largest |r(a) - r(b)| / |a - b| over neighbouring sample points: an estimate of
  /// the Lipschitz constant L from below (exact for piecewise-linear r on the grid).
  double lipschitz = 0;
  /// A bound on r anywhere in the domain, for sizing a packing's grid: max plus
  /// lipschitz times a sample cell's diagonal, and at least 5 % above max.
  double upper = 0;
};

/// Samples r on a grid of about `samples` points over the frame with near-square cells
/// (on its edges for a bounded frame; for a periodic frame evenly around the torus, and
/// the differences across the seam count too). Points outside the domain, if any, are
/// skipped. Throws InvalidInput, naming a point, where r is not finite and positive.
SizingStats measure_sizing(const Sizing& sizing, const Frame& frame, const PlanarDomain* domain,
                           int samples = 250000);

/// The smallest Delaunay angle (degrees) a maximal packing guarantees for a sizing of
/// Lipschitz constant L: asin((1 - 2L) / (2 (1 + L))), 30 for L = 0, none (0) from 1/2
/// on (docs/sizing.md).
double angle_bound_degrees(double lipschitz);

/// The gradation limit: with L >= 1/2 no minimum angle is guaranteed (sin of the smallest
/// Delaunay angle >= (1 - 2L) / (2 (1 + L)), see docs/sizing.md). Throws InvalidInput
/// with L and the bound when stats.lipschitz >= limit.
void check_gradation(const SizingStats& stats, double limit = 0.5);

/// The integral of 4 / (pi r(x)^2) over the domain (the frame without one): the disk
/// count at relative density 1, by the midpoint rule on the cells between
/// measure_sizing's grid points; the mean over cells centered inside the domain times the
/// domain's exact area. Throws InvalidInput, naming a point, where r is not finite and
/// positive, or when no cell center lies inside the domain.
double density_integral(const Sizing& sizing, const Frame& frame, const PlanarDomain* domain,
                        int samples = 250000);

/// The largest integral of 4 / (pi r(x)^2) over one cell of a grid of cells at most
/// `cell` wide over the frame, laid out as SpatialGrid lays out its cells: the disk
/// count at relative density 1 in the fullest cell. From the cells between
/// measure_sizing's grid points (each adds its share to the cell holding its center),
/// or, for cells smaller than those, the largest 4 / (pi r^2) found times a cell's area.
/// Throws InvalidInput as density_integral does, or unless `cell` is finite and positive.
double densest_cell_integral(const Sizing& sizing, const Frame& frame, const PlanarDomain* domain,
                             double cell, int samples = 250000);

/// The disk count whose relative density is eta in a varying-radius domain:
/// eta * integral of 4 / (pi r(x)^2) over the domain, which is count_for_area_fraction
/// for a constant r (density_integral does the integral). Throws InvalidInput unless
/// eta is finite and positive and the count is between 1 and the most disks a packing
/// can number (4e9).
std::size_t count_for_density(double eta, const Sizing& sizing, const Frame& frame,
                              const PlanarDomain* domain, int samples = 250000);

}  // namespace disktune
