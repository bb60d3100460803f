// SPDX-License-Identifier: GPL-3.0-or-later
// The mesh-improvement stage in one call: a triangulated surface in, a new mesh of the
// same surface out with exactly the number of vertices asked for, its vertices a tuned
// maximal random packing (conflict-free and maximal) and its triangles their restricted
// Delaunay triangulation. Adapters to CGAL and OpenMesh meshes are in
// disktune/cgal/remesh.h and disktune/openmesh/remesh.h.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "disktune/surface_domain.h"
#include "disktune/surface_mesh.h"
#include "disktune/surface_sizing.h"
#include "disktune/tuning.h"

namespace disktune {

struct RemeshOptions {
  /// The density the vertices end at: the radius is the one at which `vertex_count`
  /// disks make this area fraction (radius_for_count), so a maximal sample (about
  /// 0.547) is tuned up to it by injection (or down, below 0.547, by ejection). Where
  /// the sample at that radius has more disks than asked (fixed disks on many features
  /// make it denser), the radius grows until it has fewer, and the density ends a
  /// little higher. Near the sample's own density relaxation has the most room.
  double area_fraction = 0.55;
  /// Relaxation sweeps after the count is reached (relax, surface_tuning.h): the disks
  /// move toward a hexagonal spacing while the packing stays conflict-free and maximal,
  /// which makes the triangles closer to equilateral; then the obtuse angles of the mesh
  /// are opened (open_obtuse_angles, three passes) and its sharp ones (open_sharp_angles),
  /// twice, with the mesh's edges flipped toward Delaunay between the rounds, and the
  /// surface is meshed again. 0: neither.
  int relax_sweeps = 30;
  std::uint64_t seed = 1;
  /// Sharp edges to keep: where the surface has no features set (SurfaceDomain::
  /// set_features), its edges folding by more than this many degrees become feature
  /// curves with disks on them (detect_features), as the command line's --features does;
  /// 0 keeps none. A surface with features set keeps its own.
  double feature_angle = 60;
  /// The tuning's schedule, and a progress callback that can cancel.
  TuneOptions tune;
  /// The memory the job may use, in bytes; 0: what the process may still allocate
  /// (available_memory). A larger job is refused before any work (check_resources).
  double max_memory = 0;
  /// Threads for relaxation and the restricted Delaunay meshes (0: one per core); the
  /// mesh is the same for any number.
  unsigned threads = 0;
};

struct RemeshResult {
  /// Exactly the vertex count asked for when `tuning.reached` (vertex i is disk i); a
  /// vertex in no triangle is possible where the samples are too sparse: see `check`.
  SurfaceMesh mesh;
  /// Manifold? Genus (compare with the input's)? Isolated vertices?
  SurfaceMeshCheck check;
  /// The conflict radius where the surface leaves room: vertices at least this far
  /// apart, but for where `sizing` is smaller.
  double radius = 0;
  /// The radii the vertices were placed with: `radius` everywhere, or smaller where
  /// another part of the surface faces a point closer than radius / 0.45 (a thin wall,
  /// a ledge) or two feature curves or boundaries come that close (thickness_sizing):
  /// where one radius would give a mesh that is no manifold, or leave a stretch of a
  /// feature without vertices of its own (curves_fit).
  SurfaceSizing sizing;
  /// Why the radii vary, in a sentence for the user (where, down to what); empty when
  /// `sizing` is constant.
  std::string grading_note;
  /// Vertex i's radius (the sizing at it), for measuring edges in units of r.
  std::vector<double> radii;
  /// The input triangle vertex i lies in (to carry attributes such as texture
  /// coordinates over to the new mesh by barycentric interpolation).
  std::vector<std::uint32_t> input_triangles;
  /// Whether vertex i holds a feature curve or the open boundary (a fixed disk there,
  /// which counts on the patches on both sides; surface_packing.h).
  std::vector<bool> on_curves;
  TuneResult tuning;
};

/// Samples `surface` at the radius for `vertex_count` vertices (smaller in thin parts:
/// RemeshResult::sizing), tunes the count to exactly that, relaxes the packing and
/// meshes the result. Same seed, same mesh. Throws InvalidInput for
/// fewer than 4 vertices, an area fraction outside (0, 0.9069], a feature angle outside
/// [0, 180), a negative number of relaxation sweeps, or more vertices than memory can hold; Cancelled when the progress callback
/// cancels.
RemeshResult remesh(std::shared_ptr<const SurfaceDomain> surface, std::size_t vertex_count,
                    const RemeshOptions& options = {});
/// The same on a copy of `surface`.
RemeshResult remesh(const SurfaceDomain& surface, std::size_t vertex_count, const RemeshOptions& options = {});

}  // namespace disktune
