// SPDX-License-Identifier: GPL-3.0-or-later
// A planar domain: one outer polygon and any number of polygonal holes (paper, section
// 7.1), non-convex, with sharp corners. Every polygon vertex is a corner: boundary
// sampling puts a disk on each, and meshes keep each boundary segment as edges.
#pragma once
#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>
#include "disktune/frame.h"
#include "disktune/geometry.h"
#include "disktune/random.h"

namespace disktune {

/// One straight piece of a boundary loop: from loops[loop][index] to the next vertex.
struct BoundarySegment {
  Vec2 a, b;
  std::size_t loop = 0, index = 0;
};

class PlanarDomain {
 public:
  /// Validates and stores the loops: each has at least 3 vertices, no repeated or
  /// collinear-degenerate vertices, no two segments of any loops meet except consecutive
  /// ones at their shared vertex, every hole lies inside the outer loop and outside the
  /// other holes. Loops are stored with the outer one counterclockwise and holes
  /// clockwise (the domain on the left of every segment). Throws InvalidInput naming the
  /// offending loop, segment or vertex (0-based, in the order given) and its position.
  PlanarDomain(std::vector<Vec2> outer, std::vector<std::vector<Vec2>> holes = {});

  /// Loop 0 is the outer boundary, loops 1.. the holes.
  const std::vector<std::vector<Vec2>>& loops() const { return loops_; }
  std::vector<BoundarySegment> segments() const;
  double area() const { return area_; }
  /// The bounding box, as a non-periodic frame.
  const Frame& frame() const { return frame_; }
  /// True when p lies in the closed domain (boundary included, within a relative 1e-12
  /// of the frame size). Expected O(1): a background grid classifies its cells as
  /// inside, outside or crossed by the boundary; only crossed cells test segments.
  bool contains(Vec2 p) const;
  /// Euclidean distance from p to the nearest boundary segment.
  double distance_to_boundary(Vec2 p) const;
  /// A point uniformly distributed over the domain.
  Vec2 random_point(Rng& rng) const;
  /// Throws InvalidInput unless r is finite and positive, no two corners (polygon
  /// vertices, of any loops) are closer than r (a disk sits on every corner, so they
  /// would conflict; the message names the pair), and a maximal packing at r would
  /// hold at most 4e9 disks (the most a packing can number; whether it fits in memory
  /// is check_resources's question, resources.h).
  void validate_radius(double r) const;
  /// True when no two corners are closer than r: one radius r gives every corner its
  /// disk. Where it does not, a sizing that shrinks near them can (feature_sizing).
  bool corners_fit(double r) const;

 private:
  // Two corners, each as {loop, index}, and their squared distance.
  struct CornerPair {
    std::array<std::size_t, 2> first, second;
    double d2;
  };
  std::optional<CornerPair> conflicting_corners(double r) const;
  struct CellGrid;  // the inside/outside/crossed background grid
  std::vector<std::vector<Vec2>> loops_;
  double area_ = 0;
  Frame frame_;
  std::shared_ptr<const CellGrid> grid_;
};

/// Reads Triangle's .poly format (vertices, segments, holes; '#' comments; 0- or
/// 1-based vertex numbers; markers and attributes ignored). The segments must form
/// closed loops; the outer loop is the one enclosing all others, and each other loop
/// must contain one of the file's hole points. Throws IoError when the file cannot be
/// read, InvalidInput naming the line or loop when its content is wrong.
PlanarDomain read_poly(const std::string& path);

/// The domain bounded by the boundary edges (edges of exactly one triangle) of a planar
/// triangle mesh, given as positions and triangles (z ignored by callers). Throws
/// InvalidInput when an edge has more than two triangles, a boundary vertex has more
/// than one outgoing boundary edge, or the loops are not one outer and holes.
PlanarDomain planar_domain_from_triangles(const std::vector<Vec2>& points,
                                          const std::vector<std::array<std::size_t, 3>>& triangles);

/// Reads a planar domain from .poly (Triangle), or from the boundary loops of a planar
/// triangle mesh in .off or .obj (z must be 0, or constant). Chooses by extension.
PlanarDomain read_planar_domain(const std::string& path);

}  // namespace disktune
