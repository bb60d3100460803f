// SPDX-License-Identifier: GPL-3.0-or-later
// Repair of bow-tie vertices in a restricted Delaunay mesh (internal; issue #15).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "disktune/surface_mesh.h"

namespace disktune::detail {

/// A sample whose ball reaches across a thin part of the surface (two faces closer than
/// r, as under one of fandisk's ledges) can own a Voronoi cell that meets the far face
/// too. The dual test then gives it a second closed fan: a cone whose rim lies on the far
/// face, a bow tie. Where every fan of a vertex is a closed, consistently oriented cycle,
/// the fan that stands out most from its rim (the vertex farthest from the rim's plane
/// for the rim's size) gives way to a cap over its rim, ear-clipped in that plane with
/// the rim's orientation, so every rim edge keeps two triangles. Nothing changes unless
/// the cap's diagonals and triangles are new to the mesh. Returns the caps made.
std::size_t cap_bow_ties(SurfaceMesh& mesh);

/// The triangles `fan` (indices into mesh.triangles) give way to `cap`, each cap triangle
/// turned to start at its smallest index as the mesh's others do. The repairs' last step.
void replace_fan(SurfaceMesh& mesh, const std::vector<std::size_t>& fan,
                 const std::vector<std::array<std::uint32_t, 3>>& cap);

}  // namespace disktune::detail
