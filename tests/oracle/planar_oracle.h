// SPDX-License-Identifier: GPL-3.0-or-later
//
// Independent test oracle for disk packings of a planar domain with holes. Written
// apart from the library: brute force in spirit, standard library only (it shares only
// the plain witness types of oracle.h).
//
// Model: a closed polygonal domain (loop 0 the outer boundary, the others holes, any
// orientation; the loops are trusted to be simple and disjoint), N disks of radius r,
// or each with its own radius r_i (the overload taking `radii`; with equal radii both
// give identical reports). For disk i, "r" below is r_i.
//  - a point is in the domain when even-odd crossing over all segments says so, or it
//    lies within r*tol of a segment (the closed domain, with slack);
//  - a boundary disk is one whose center lies within r*tol of a segment (or one the
//    caller flags so);
//  - conflict: two centers closer than min(r_i, r_j)*(1-tol);
//  - covered center (information, not a failure): no conflict, but closer than
//    max(r_i, r_j)*(1-tol), as the prior-disk rule allows;
//  - covered point: within r_i*(1+tol) of some center i;
//  - maximal: every point of the domain is covered (checked exactly via the corners of
//    possible voids, plus random probes; see planar_oracle.cpp), and every boundary
//    point is covered by a boundary disk (1D maximality, per segment by intervals).
// Inputs must be finite, radii > 0 (one per center), 0 <= tol < 1, loops of >= 3
// vertices and flags (when given) one per center; otherwise std::invalid_argument is
// thrown.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "oracle/oracle.h"

namespace oracle {

struct Domain {
  // Loop 0 outer, loops 1.. holes; each loop closes from its last vertex to its first.
  std::vector<std::vector<std::array<double, 2>>> loops;
};

struct PlanarOptions {
  double tol = 1e-6;
  // One flag per center: 1 marks a boundary disk. Empty: the oracle decides (a center
  // within r*tol of a segment is a boundary disk).
  std::vector<char> boundary_flags;
  // Which checks to run.
  bool containment = true;   // (a) every center in the closed domain
  bool boundary = true;      // (b) boundary disks on the boundary, a disk on every corner
  bool conflicts = true;     // (c) no pair closer than r*(1-tol)
  bool maximality = true;    // (d) 2D coverage (exact + probes) and 1D boundary coverage
  std::size_t probes = 20000;  // random probes, uniform over the domain
  std::uint64_t seed = 1;
};

// A center outside the closed domain (by more than r*tol).
struct OutsideCenter {
  std::size_t i;
  double x, y;
  double distance_to_boundary;
};

// A flagged boundary disk farther than r*tol from every segment.
struct OffBoundary {
  std::size_t i;
  double x, y;
  double distance_to_boundary;
};

// A polygon vertex with no center within r*tol.
struct BareCorner {
  std::size_t loop, vertex;
  double x, y;
  double nearest_center;  // infinity when there are no centers
};

// A piece of segment `segment` of `loop` (from vertex `segment` to the next) that no
// boundary disk covers: parameters t0 < t1 in [0, 1], and the midpoint.
struct BoundaryGap {
  std::size_t loop, segment;
  double t0, t1;
  double x, y;
};

struct PlanarReport {
  // Which checks were run; an unchecked property reads as false.
  bool containment_checked = false, boundary_checked = false;
  bool conflicts_checked = false, maximality_checked = false;
  // Inputs, echoed for summary().
  std::size_t n = 0, boundary_count = 0;
  double r = 0, tol = 0;  // r: the largest radius
  double r_min = 0;       // the smallest radius (== r for one radius)

  // Each list keeps the first 100 found; the *_count fields count them all.
  std::vector<OutsideCenter> outside;
  std::size_t outside_count = 0;
  std::vector<OffBoundary> off_boundary;
  std::size_t off_boundary_count = 0;
  std::vector<BareCorner> bare_corners;
  std::size_t bare_corner_count = 0;
  std::vector<Conflict> conflicts;
  std::size_t conflict_count = 0;
  // Pairs where only the larger disk covers the other center (never with one radius).
  std::vector<Conflict> covered_centers;
  std::size_t covered_center_count = 0;
  std::vector<Uncovered> uncovered;  // 2D: void corners and probes
  std::size_t uncovered_count = 0;
  std::vector<BoundaryGap> boundary_gaps;  // 1D
  std::size_t boundary_gap_count = 0;

  // Smallest distance between two centers (only pairs at most r_i + r_j apart are
  // seen: infinity means none). Largest distance from a probe to its nearest center
  // (infinity when one has none within 2r, r the largest radius).
  double min_distance = std::numeric_limits<double>::infinity();
  double max_probe_gap = 0;
  std::size_t probes = 0;  // probes actually placed in the domain

  bool inside() const { return containment_checked && outside_count == 0; }
  bool on_boundary() const {
    return boundary_checked && off_boundary_count == 0 && bare_corner_count == 0;
  }
  bool conflict_free() const { return conflicts_checked && conflict_count == 0; }
  bool maximal() const { return maximality_checked && uncovered_count == 0; }
  bool boundary_maximal() const { return maximality_checked && boundary_gap_count == 0; }
  // Every check that was run passed (and at least one was run).
  bool ok() const;
  std::string summary() const;  // one paragraph, for test failure messages
};

PlanarReport check_planar(const Domain& domain, const std::vector<std::array<double, 2>>& centers,
                          double r, const PlanarOptions& options = {});

// The same with one radius per center (radii.size() == centers.size()).
PlanarReport check_planar(const Domain& domain, const std::vector<std::array<double, 2>>& centers,
                          const std::vector<double>& radii, const PlanarOptions& options = {});

// The area by the shoelace formula: |outer loop| minus the |holes|, any orientation.
double domain_area(const Domain& domain);

// Even-odd crossing over all segments (no tolerance: points on the boundary can go
// either way).
bool even_odd_inside(const Domain& domain, double x, double y);

// Distance from (x, y) to the nearest segment of any loop.
double distance_to_boundary(const Domain& domain, double x, double y);

}  // namespace oracle
