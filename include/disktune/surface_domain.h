// SPDX-License-Identifier: GPL-3.0-or-later
// A curved surface to pack disks on: a triangle mesh in space, validated once so later
// steps can rely on a consistently oriented 2-manifold (possibly with boundary).
// Plain arrays only; CGAL and OpenMesh meshes come in through the adapter headers
// disktune/cgal/surface_from_cgal.h and disktune/openmesh/surface_from_openmesh.h.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "disktune/vec3.h"

namespace disktune {

/// A mesh edge by its two vertices, the smaller index first.
using MeshEdge = std::array<std::size_t, 2>;

/// A polyline of mesh vertices, consecutive ones joined by a mesh edge. An open curve runs
/// from corner to corner (both ends may be one vertex) with no corner inside; a closed
/// one comes back from its last vertex to its first.
struct SurfaceCurve {
  std::vector<std::size_t> vertices;
  bool closed = false;
  /// Its edges: edge k runs from vertices[k] to vertices[(k + 1) % size].
  std::size_t edge_count() const { return vertices.size() - (closed ? 0 : 1); }
};

/// Sharp features of a surface (surface_features.h finds them): feature edges chained
/// into curves, and the corners where curves end.
struct SurfaceFeatures {
  std::vector<MeshEdge> edges;        // sorted, each once
  std::vector<std::size_t> corners;   // sorted vertex indices
  std::vector<SurfaceCurve> curves;   // every feature edge in exactly one curve
};

/// An open boundary turning by more than this many degrees at a vertex (the angle
/// between the directions of its two edges) has a corner there: a fixed disk, as every
/// polygon vertex of a planar domain has, which the boundary's even layout starts from.
constexpr double kBoundaryCornerAngle = 60;

class SurfaceDomain {
 public:
  using Triangle = std::array<std::size_t, 3>;

  /// Throws InvalidInput, naming the face, edge or vertex and its position, when a
  /// triangle names a missing vertex or has no area (within 1e-12 of its squared longest
  /// edge), an edge lies in more than two triangles, two triangles sharing an edge run it
  /// the same way (inconsistent orientation), a vertex's triangles form more than one fan
  /// (bow tie), or a vertex lies in no triangle; or when there are no triangles.
  SurfaceDomain(std::vector<Vec3> vertices, std::vector<Triangle> triangles);

  const std::vector<Vec3>& vertices() const { return vertices_; }
  const std::vector<Triangle>& triangles() const { return triangles_; }
  std::size_t edge_count() const { return edge_count_; }
  /// The open boundaries, each an ordered vertex list run with the surface on its left
  /// (seen from the side the triangles' normals point to); empty for a closed surface.
  const std::vector<std::vector<std::size_t>>& boundary_loops() const { return loops_; }
  bool is_closed() const { return loops_.empty(); }

  /// Connected components (through shared vertices), numbered by their lowest triangle.
  std::size_t component_count() const { return genus_.size(); }
  /// The component of each triangle.
  const std::vector<std::size_t>& triangle_component() const { return component_; }
  /// Genus of each component, from Euler's formula V - E + F = 2 - 2g - b.
  const std::vector<int>& component_genus() const { return genus_; }
  /// The sum of the components' genera.
  int genus() const;

  /// Makes `features` part of the surface, as meshers see it: its curves hold fixed
  /// disks like the open boundary, its corners a disk each. Throws InvalidInput, naming
  /// the curve, when a curve names a missing vertex, steps along an edge that is not a
  /// feature edge, or (open) does not end at corners. Replaces earlier features.
  void set_features(SurfaceFeatures features);
  const SurfaceFeatures& features() const { return features_; }
  /// The vertices that hold a fixed disk each (sorted): the feature corners, and the
  /// vertices where an open boundary turns by more than kBoundaryCornerAngle.
  const std::vector<std::size_t>& corners() const { return corners_; }
  /// The curves that hold fixed disks (paper, section 7): every open boundary loop, cut
  /// into open curves at the corners on it (a loop with none stays closed), then every
  /// feature curve. Corners are the ends of the open ones.
  const std::vector<SurfaceCurve>& fixed_curves() const { return curves_; }
  /// The index in fixed_curves() of the first feature curve (the boundary pieces come first).
  std::size_t first_feature_curve() const { return curves_.size() - features_.curves.size(); }
  /// The patches the feature curves cut the surface into: triangles joined across every
  /// edge that is no feature edge, numbered from 0 by their lowest triangle. Without
  /// features, the connected components.
  const std::vector<std::uint32_t>& triangle_patch() const { return patch_; }
  std::size_t patch_count() const { return patch_count_; }

  Vec3 bbox_min() const { return lo_; }
  Vec3 bbox_max() const { return hi_; }
  double area() const { return area_; }

 private:
  std::vector<Vec3> vertices_;
  std::vector<Triangle> triangles_;
  std::size_t edge_count_ = 0;
  std::vector<std::vector<std::size_t>> loops_;
  SurfaceFeatures features_;
  std::vector<std::size_t> corners_;
  std::vector<SurfaceCurve> curves_;
  std::vector<std::uint32_t> patch_;
  std::size_t patch_count_ = 0;
  std::vector<std::size_t> component_;
  std::vector<int> genus_;
  Vec3 lo_, hi_;
  double area_ = 0;
};

/// A surface from a mesh file (.off, .obj, .ply, .stl, by extension), read by disktune's
/// own validating readers (the soup CGAL 5.5's readers give for valid files). OFF files
/// may start with '#' comments. STL corners with equal coordinates are merged. Faces are
/// then turned, component by component, to agree with the first triangle's orientation
/// where that is possible. Throws IoError when the file cannot be opened or read, and
/// InvalidInput, naming the file and the line (or the vertex or face), when it is
/// malformed or no valid surface (see the constructor).
SurfaceDomain read_surface(const std::string& path);

/// The same through OpenMesh's readers (OpenMesh::IO::read_mesh), without reorienting
/// or merging. OpenMesh rejects OFF files that start with '#' comments: those throw
/// IoError suggesting read_surface. OpenMesh's OFF reader parses coordinates as float
/// (about 7 digits), and it may split non-manifold input itself, with a warning on
/// stderr, before disktune sees it.
SurfaceDomain read_surface_openmesh(const std::string& path);

}  // namespace disktune
