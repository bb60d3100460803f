// SPDX-License-Identifier: GPL-3.0-or-later
// The periodic Delaunay triangulation of a packing, as a plain triangle mesh laid out
// in the plane. The public type holds no CGAL; the triangulation itself is built with
// CGAL in one translation unit (src/mesh/periodic_delaunay.cpp).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "disktune/geometry.h"
#include "disktune/packing.h"

namespace disktune {

/// A triangulation of the torus laid out in the plane. Each torus triangle appears
/// exactly once, as the copy whose centroid lies in the box [0,W) x [0,H); its corners
/// keep unwrapped coordinates, so a triangle crossing the seam uses a vertex that is a
/// periodic copy of a disk lying outside the box. The result is a planar mesh (no two
/// triangles overlap) whose area is W*H; where the seam cuts it, it has a boundary.
struct TriangleMesh {
  /// Vertex positions. Vertices [0, disk_count) are the live disks in increasing id
  /// order at their own centers; later vertices are periodic copies used across the seam.
  std::vector<Vec2> vertices;
  /// The disk each vertex is a copy of.
  std::vector<DiskId> vertex_disk;
  /// The copy's periodic offset: vertices[v] = center(vertex_disk[v]) + offset * (W, H).
  std::vector<std::array<std::int32_t, 2>> vertex_offset;
  /// Counterclockwise vertex triples.
  std::vector<std::array<std::uint32_t, 3>> triangles;
  /// Number of live disks (2 * disk_count triangles: Euler's formula on the torus).
  std::size_t disk_count = 0;
  /// The box sides W, H.
  Vec2 period{1, 1};
};

/// The periodic Delaunay triangulation of the live disk centers of a packing in a
/// periodic frame of any width and height. Exact: the centers are snapped to a grid of
/// spacing about 2^-51 of the box size (moving each by ~1e-16 of it), so that every
/// periodic copy is an exact translate; CGAL's exact predicates and its symbolic
/// perturbation of cocircular points (translation invariant) then give one consistent
/// triangulation of the torus, also for lattices, where every cell is cocircular.
/// Throws InvalidInput for an empty or non-periodic packing, or two coinciding centers.
TriangleMesh periodic_delaunay(const Packing& packing);

/// A triangle mesh of a bounded planar domain (no periodic copies): a constrained
/// Delaunay mesh of a packing, or the CVT reference mesh.
struct PlanarMesh {
  std::vector<Vec2> vertices;
  /// The disk each vertex is (kNoDisk for a mesh not made from a packing).
  std::vector<DiskId> vertex_disk;
  /// Counterclockwise vertex triples.
  std::vector<std::array<std::uint32_t, 3>> triangles;
  /// The boundary's edges (the constrained segments), each as its two vertex indices in
  /// the order of its loop, and the loop each lies on (0 the outer boundary, then the
  /// holes); written as lines, named by loop in Gmsh files.
  std::vector<std::array<std::uint32_t, 2>> boundary_edges = {};
  std::vector<std::uint32_t> boundary_loop = {};
};

/// The constrained Delaunay triangulation (CGAL) of the live disk centers of a packing
/// in a bounded domain whose boundary is given as closed loops of disks: `loops[k]`
/// lists the disks on boundary loop k in order along it (loop 0 the outer boundary,
/// the others holes; each consecutive pair, and last to first, is a constrained edge).
/// Only triangles inside the outer loop and outside the holes are kept. Vertices are
/// the live disks in increasing id order. Throws InvalidInput for a loop with fewer
/// than 3 disks, a dead id, or constraints that cross.
PlanarMesh constrained_delaunay(const Packing& packing, const std::vector<std::vector<DiskId>>& loops);

/// Each edge of the torus triangulation once, as a pair of vertex indices (a, b) with
/// the segment vertices[a]..vertices[b] at its laid-out position in one triangle.
std::vector<std::array<std::uint32_t, 2>> unique_edges(const TriangleMesh& mesh);

}  // namespace disktune
