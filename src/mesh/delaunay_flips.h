// SPDX-License-Identifier: GPL-3.0-or-later
// Edge flips that bring a surface mesh back toward Delaunay after some of its vertices
// moved (internal): what remesh's angle-opening passes see between two rounds, where a
// new restricted Delaunay mesh cost a sixth of remesh's time (fandisk at 10^4 vertices).
#pragma once

#include <cstddef>
#include <vector>

#include "disktune/surface_mesh.h"

namespace disktune::detail {

/// Moves the mesh's vertices to `now` (one point per vertex) and, around the vertices
/// that moved, flips each edge whose two facing angles sum to more than 180 degrees
/// (Lawson's flip), repeated around the flipped edges' corners until none is left or
/// eight rounds passed. An edge keeps its place where it is a feature edge, lies in
/// other than two triangles or in two run the same way, or where its flip would repeat
/// an edge or fold the quad over. Deterministic: vertices in index order. Returns the
/// flips made.
std::size_t flip_toward_delaunay(SurfaceMesh& mesh, const std::vector<Vec3>& now);

}  // namespace disktune::detail
