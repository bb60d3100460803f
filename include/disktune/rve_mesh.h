// SPDX-License-Identifier: GPL-3.0-or-later
// A periodic finite-element mesh of a fiber RVE (rve.h): a conforming triangle mesh of
// the W x H cell in which every triangle lies in the matrix or in one fiber, the fiber
// boundaries are polygons of a chosen number of segments per circle, and the nodes on
// opposite sides of the cell match (same count, coordinates equal up to the period), as
// periodic boundary conditions need. Gmsh (its C API, OpenCASCADE geometry) does the
// meshing; nothing of it shows here, and its library is loaded only when a mesh is made.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "disktune/geometry.h"
#include "disktune/quality.h"
#include "disktune/rve.h"

namespace disktune {

struct RveMeshSpec {
  /// Segments of a whole fiber boundary (a fiber cut by a side keeps its share); the
  /// smallest fiber's, for unequal fibers, the others having more of that length.
  std::size_t fiber_segments = 24;
  /// The largest triangle edge in the matrix and fibers; 0: one segment's length of the
  /// smallest fiber, pi d_min / fiber_segments.
  double element_size = 0;
  /// The memory meshing may use, in bytes; 0: what the process may still allocate.
  double max_memory = 0;
};

struct RveMesh {
  double width = 0, height = 0;
  std::vector<Vec2> nodes;
  /// Counterclockwise node triples.
  std::vector<std::array<std::uint32_t, 3>> triangles;
  /// Per triangle: 0 in the matrix, k + 1 in fiber k (the Rve's centers[k]).
  std::vector<std::uint32_t> material;
  /// The nodes on each side in increasing coordinate along it, corners excluded. Periodic
  /// pairs: left[i] (x = 0) and right[i] (x = W) have the same y; bottom[i] (y = 0) and
  /// top[i] (y = H) the same x.
  std::vector<std::uint32_t> left, right, bottom, top;
  /// The corner nodes at (0,0), (W,0), (W,H), (0,H).
  std::array<std::uint32_t, 4> corners{};
  /// Triangle shape: angles in degrees, and the radius ratio, circumradius over twice
  /// the inradius (1 for an equilateral triangle, growing without bound for slivers).
  QualityReport::Angles angles;
  Statistics radius_ratio;
  /// The least distance between a fiber boundary and a cell side it does not cross or
  /// the tangent point where it would, over all fibers (make_rve keeps this large).
  double side_clearance = 0;
};

/// Checks that fibers of `rve` can be meshed as `mesh` asks, before they are made:
/// throws InvalidInput (saying what to change) for a gap under d / 1000, d the smallest
/// fiber's diameter (fibers that nearly touch leave no matrix between them to mesh),
/// segments outside [6, 10^4], an element size that is not finite or is under d / 1000,
/// or a mesh too large for the memory allowed (Remedy::memory); IoError when Gmsh's
/// library cannot be loaded (it is loaded here, so a job fails before its work).
void check_rve_mesh(const RveSpec& rve, const RveMeshSpec& mesh);

/// Meshes the cell of `rve` (fiber k of diameter rve.diameters[k]). Throws InvalidInput
/// as check_rve_mesh does, when a fiber touches a cell side, or without one diameter per
/// fiber; IoError when Gmsh's library (the soname disktune was built with) cannot be
/// loaded; a std::runtime_error when Gmsh fails.
RveMesh mesh_rve(const Rve& rve, const RveMeshSpec& spec = {});

/// Gmsh's MSH 4.1 (ASCII) of the mesh: entities for the corners, the four sides and
/// each fiber and the matrix; physical groups "matrix", "fibers", "fiber K" (K from 1),
/// "left", "right", "bottom", "top" and "corners"; the right side declared a periodic
/// copy of the left (translation W) and the top of the bottom (translation H), with
/// every node pair. Written atomically (io.h).
void write_rve_msh(const std::string& path, const RveMesh& mesh);

/// Abaqus input (.inp) of the mesh: nodes, 3-node plane-strain triangles (CPE3), element
/// sets MATRIX, FIBERS and FIBER-K, node sets LEFT, RIGHT, BOTTOM, TOP (the periodic
/// pairs in matching order) and CORNER-1..4 (counterclockwise from the origin). No
/// materials or steps: those are the analysis's. Written atomically (io.h).
void write_rve_inp(const std::string& path, const RveMesh& mesh);

}  // namespace disktune
