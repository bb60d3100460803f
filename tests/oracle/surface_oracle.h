// SPDX-License-Identifier: GPL-3.0-or-later
//
// Independent test oracle for disk packings on triangulated surfaces ("sphere-surface"
// disks, paper section 7.2). Written apart from the library: brute force in spirit,
// standard library only (it shares only the plain Conflict type of oracle.h).
//
// Model: a surface given as a triangle mesh (vertex positions, triangles as index
// triples; the surface is the union of the closed triangles, nothing else is assumed:
// no orientation, manifoldness or connectivity), N disks with centers c_i in space and
// radii r_i. Disk i covers the points p of the surface with |p - c_i| <= r_i (the
// Euclidean distance in space: a ball cut with the surface).
//  - on the surface: c_i within r_i*tol of the closest point of some triangle;
//  - conflict: two centers closer than min(r_i, r_j)*(1-tol);
//  - covered center (information, not a failure): no conflict, but closer than
//    max(r_i, r_j)*(1-tol), as the prior-disk rule allows;
//  - covered point: within r_i*(1+tol) of some center i;
//  - maximal: every point of every triangle is covered (checked exactly per triangle
//    via the corners of possible voids, plus probes; see surface_oracle.cpp);
//  - boundary (only with boundary_flags): every boundary edge (an edge that exactly one
//    triangle uses, by vertex indices) is covered by the flagged disks alone (1D
//    maximality, per edge by intervals), and every flagged center lies within r_i*tol
//    of a boundary edge.
// Inputs must be finite, radii > 0 (one per center), 0 <= tol < 1, at least one
// triangle, triangle indices < the number of vertices and flags (when given) one per
// center; otherwise std::invalid_argument is thrown. Degenerate (zero-area) triangles
// are allowed: they are segments, and are checked as such.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "oracle/oracle.h"

namespace oracle {

using Point3 = std::array<double, 3>;

struct SurfaceMeshInput {
  std::vector<Point3> vertices;
  std::vector<std::array<std::size_t, 3>> triangles;
};

struct SurfaceOptions {
  double tol = 1e-6;
  // One flag per center: 1 marks a fixed boundary disk. Empty: no boundary check.
  std::vector<char> boundary_flags;
  // Which checks to run.
  bool on_surface = true;  // (a) every center on the surface
  bool conflicts = true;   // (b) no pair closer than min(r_i, r_j)*(1-tol)
  bool maximality = true;  // (c) exact per-triangle coverage, (d) probes
  bool boundary = true;    // (e) boundary edges covered by flagged disks (needs flags)
  // (d) Random probes per triangle, uniform over it; each triangle's centroid and each
  // edge's midpoint are probed as well.
  std::size_t probes_per_triangle = 8;
  std::uint64_t seed = 1;
};

// A center farther than r*tol from every triangle.
struct OffSurface {
  std::size_t i;
  double x, y, z;
  double distance;  // to the closest point of the surface
};

// Witness of non-maximality: a point of `triangle` that no disk covers (a corner of a
// possible void not covered by any disk but the ones it was built from, or an uncovered
// probe); `why` names the triangle and the kind of candidate.
struct SurfaceUncovered {
  double x, y, z;
  std::size_t triangle;
  std::string why;
};

// A flagged disk farther than r*tol from every boundary edge.
struct SurfaceOffBoundary {
  std::size_t i;
  double x, y, z;
  double distance;  // to the nearest boundary edge (infinity: there is none)
};

// A piece of the boundary edge from vertex v0 to vertex v1 (of `triangle`, the one
// triangle that uses it) that no flagged disk covers: parameters t0 < t1 in [0, 1]
// from v0, and the midpoint.
struct SurfaceBoundaryGap {
  std::size_t triangle, v0, v1;
  double t0, t1;
  double x, y, z;
};

struct SurfaceReport {
  // Which checks were run; an unchecked property reads as false.
  bool on_surface_checked = false, conflicts_checked = false;
  bool maximality_checked = false, boundary_checked = false;
  // Inputs, echoed for summary().
  std::size_t n = 0, triangles = 0;
  std::size_t boundary_edges = 0;  // edges used by exactly one triangle
  std::size_t boundary_count = 0;  // flagged disks
  double r = 0, tol = 0;           // r: the largest radius
  double r_min = 0;                // the smallest radius (== r for one radius)

  // Each list keeps the first 100 found; the *_count fields count them all.
  std::vector<OffSurface> off_surface;
  std::size_t off_surface_count = 0;
  std::vector<Conflict> conflicts;  // i < j
  std::size_t conflict_count = 0;
  // Pairs where only the larger disk covers the other center (never with one radius).
  std::vector<Conflict> covered_centers;
  std::size_t covered_center_count = 0;
  std::vector<SurfaceUncovered> uncovered;
  std::size_t uncovered_count = 0;
  std::vector<SurfaceOffBoundary> off_boundary;
  std::size_t off_boundary_count = 0;
  std::vector<SurfaceBoundaryGap> boundary_gaps;
  std::size_t boundary_gap_count = 0;

  // Smallest distance between two centers (only pairs at most r_i + r_j apart are
  // seen: infinity means none). Largest distance from a probe to its nearest center
  // (infinity when there are no centers).
  double min_distance = std::numeric_limits<double>::infinity();
  double max_probe_gap = 0;
  std::size_t probes = 0;      // probes placed (random, centroids, edge midpoints)
  std::size_t candidates = 0;  // exact candidates tested (corners and crossings)

  bool on_surface() const { return on_surface_checked && off_surface_count == 0; }
  bool conflict_free() const { return conflicts_checked && conflict_count == 0; }
  bool maximal() const { return maximality_checked && uncovered_count == 0; }
  bool boundary_ok() const {
    return boundary_checked && boundary_gap_count == 0 && off_boundary_count == 0;
  }
  // Every check that was run passed (and at least one was run).
  bool ok() const;
  std::string summary() const;  // one paragraph, for test failure messages
};

SurfaceReport check_surface(const SurfaceMeshInput& mesh, const std::vector<Point3>& centers,
                            const std::vector<double>& radii, const SurfaceOptions& options = {});

// The same with one radius r for every disk.
SurfaceReport check_surface(const SurfaceMeshInput& mesh, const std::vector<Point3>& centers,
                            double r, const SurfaceOptions& options = {});

// Distance from p to the closest point of the surface (brute force over the triangles).
double distance_to_surface(const SurfaceMeshInput& mesh, const Point3& p);

}  // namespace oracle
