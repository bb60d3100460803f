// SPDX-License-Identifier: GPL-3.0-or-later
// Sharp features of a surface (issue #15): the edges where the surface folds by more
// than an angle, chained into curves that run from corner to corner (or close on
// themselves). Meshers keep such curves as mesh edges; here they are the curves that
// feature disks will sit on, as open boundaries do.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "disktune/surface_domain.h"

namespace disktune {

struct FeatureOptions {
  /// An interior edge is a feature when the normals of its two triangles differ by more
  /// than this (degrees; CGAL's detect_sharp_edges uses the same rule and default).
  double angle = 60;
  /// A vertex on exactly two feature edges is a corner when the curve turns there by
  /// more than this (degrees between the directions of its two edges).
  double corner_angle = 60;
  /// Stray folds are dropped: a group of feature edges (connected through shared
  /// vertices) with a loose end (a vertex on exactly one feature edge, not on an open
  /// boundary) whose total length is below this fraction of the bounding-box diagonal.
  /// Scanned and organic models fold past 60 degrees in short scratches that are no
  /// creases (the elephant: 84 curves in 71 groups, the longest 15 % of its diagonal);
  /// a CAD model's creases form closed loops or networks that end at corners and
  /// boundaries, which are kept however short. 0 keeps every feature edge.
  double stray_length = 0.2;
};

/// The feature edges of `domain` by the angle rule, less the stray folds
/// (options.stray_length), chained into curves. A vertex is a corner when it lies on one
/// or three or more feature edges, on a feature edge and an open boundary, or where its
/// curve turns by more than options.corner_angle. Throws InvalidInput unless
/// 0 < angle < 180, 0 < corner_angle <= 180 and 0 <= stray_length.
SurfaceFeatures detect_features(const SurfaceDomain& domain, const FeatureOptions& options = {});

/// The same from feature edges given by their end vertices (any order; repeats are
/// merged), as a CAD model lists them; only options.corner_angle is used (every edge
/// given is kept). Throws
/// InvalidInput, naming the pair, when one is not an edge between two triangles of the
/// surface (boundary edges are boundaries already).
SurfaceFeatures features_from_edges(const SurfaceDomain& domain, std::vector<MeshEdge> edges,
                                    const FeatureOptions& options = {});

}  // namespace disktune
