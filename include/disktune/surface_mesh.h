// SPDX-License-Identifier: GPL-3.0-or-later
// A triangle mesh in space as plain arrays (the output of surface resampling), its
// topology check and its file output. No CGAL: the mesh is built in restricted_delaunay.h.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "disktune/vec3.h"

namespace disktune {

struct SurfaceMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;  // indices into `vertices`
  /// The mesh edges that follow the input's sharp feature curves (each joins two fixed
  /// disks consecutive along one); written as lines in OBJ and VTK files.
  std::vector<std::array<std::uint32_t, 2>> feature_edges = {};
};

/// What check_surface_mesh finds. Boundary edges are no problem by themselves (the
/// input surface may be open); everything else non-zero here is.
struct SurfaceMeshCheck {
  bool manifold = false;  // no non-manifold edge or vertex
  bool oriented = false;  // every edge of two triangles is run both ways
  std::size_t components = 0;  // connected through triangles; isolated vertices excluded
  int genus = -1;              // sum over components of V - E + F = 2 - 2g - b; -1 unless manifold
  std::size_t boundary_edges = 0, non_manifold_edges = 0, non_manifold_vertices = 0,
              isolated_vertices = 0;
  std::size_t boundary_loops = 0;  // compare with the input's: a mesh of a closed surface has none
  /// Empty when all is well; otherwise a sentence listing what is wrong and the likely fix.
  std::string problems;
};

/// Pure combinatorics: edges in more than two triangles, vertices whose triangles form
/// more than one fan (bow ties), edges two triangles run the same way, vertices in no
/// triangle, connected components, and the genus by Euler's formula per component with
/// its boundary loops counted. Throws InvalidInput when a triangle names a missing vertex
/// or repeats one.
SurfaceMeshCheck check_surface_mesh(const SurfaceMesh& mesh);

/// Writes the mesh as ASCII OFF, OBJ, PLY or legacy VTK, chosen by the extension of
/// `path` (any letter case; mesh_io.h writes every mesh kind alike), every coordinate in the shortest form that reads back to the same double
/// (at most 17 significant digits), through write_file_atomically; the feature edges as
/// line elements in OBJ ('l') and VTK (LINES), so a viewer shows the curves (OFF and PLY
/// hold the triangles only). Throws InvalidInput,
/// naming the allowed extensions, for any other extension, and IoError when the file
/// cannot be written.
void write_surface_mesh(const std::string& path, const SurfaceMesh& mesh);
/// Throws as write_surface_mesh does for a path whose extension it cannot write, so a
/// caller can refuse it before any work.
void check_surface_mesh_path(const std::string& path);

}  // namespace disktune
