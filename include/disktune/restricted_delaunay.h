// SPDX-License-Identifier: GPL-3.0-or-later
// Surface resampling's output mesh (paper section 7.2): the restricted Delaunay
// triangulation of sample points on a triangulated surface, and how far it lies from
// that surface. CGAL stays in src/mesh/restricted_delaunay.cpp.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "disktune/surface_domain.h"
#include "disktune/surface_mesh.h"
#include "disktune/surface_packing.h"
#include "disktune/vec3.h"

namespace disktune {

/// The Delaunay triangles of `samples` (in space) whose dual Voronoi edge meets
/// `surface`, each turned so that its normal agrees with the surface's there. Vertex i
/// is samples[i]; a sample in no kept triangle, or a repeat of an earlier equal sample,
/// stays an isolated vertex (check_surface_mesh counts them). The result is a manifold
/// of the surface's topology only when the samples are dense enough: check it. Throws
/// InvalidInput for fewer than 4 samples, a non-finite coordinate, or samples that do
/// not span a plane. The dual test is exact: many samples on one flat face make flat
/// slivers whose circumcenters, rounded, land anywhere. Interval arithmetic settles
/// almost every facet and exact arithmetic the rest; the whole costs 3-5 times CGAL's
/// Delaunay triangulation of the samples (docs/benchmarks.md), the search of the dual
/// edges on every core (the mesh is the same for any number).
SurfaceMesh restricted_delaunay(const std::vector<Vec3>& samples, const SurfaceDomain& surface);

/// The same on a surface with sharp features, each sample's patch given
/// (SurfaceDomain::triangle_patch, or kAnyPatch for a sample on a feature curve or an
/// open boundary, which belongs to every patch there), and the pairs of samples consecutive
/// along a feature curve. Near a sharp crease the dual test can keep, around a sample x
/// beside a feature edge ab, the triangle abx and two fans from a to b, one of them
/// across the crease (ax and bx in three triangles, ab in one; three faces of a
/// tetrahedron in the simplest case): the fan bent further from abx gives way to a cap
/// over its rim, which holds the feature edge. A triangle whose vertices lie in two different patches, joining the
/// two sides of a feature, is dropped where it shares an edge with two or more others
/// (where feature disks are too far apart for an edge between them, the mesh needs such
/// triangles and they stay).
/// Throws as above, and InvalidInput unless there is one patch per sample, each a patch
/// of the surface or kAnyPatch, and each feature edge joins two different samples.
SurfaceMesh restricted_delaunay(const std::vector<Vec3>& samples, const SurfaceDomain& surface,
                                const std::vector<std::uint32_t>& sample_patch,
                                const std::vector<std::array<std::uint32_t, 2>>& feature_edges = {});

/// What the caller knows of a packing's coverage: `maximal` vouches that every point of
/// the surface lies within r_max of a center (as sample_mps, tune, relax and
/// open_obtuse_angles leave it: they check or keep it). A point of the surface on a
/// facet's dual edge is as near its three corners as any sample, so then within r_max of
/// them, and only that part of each dual edge is searched: the same mesh in about two
/// thirds of the time (elephant, 10^4 disks). On a packing with a void, `maximal` may
/// lose triangles there.
enum class Coverage { unknown, maximal };

/// The mesh of a packing: vertex i is the i-th live disk (packing.ids() order); a fixed
/// disk (on a feature curve or the open boundary) belongs to every patch, any other to
/// the patch of the triangle it lies in. The dual edges are searched on up to `threads`
/// threads (0: one per core, as for the samples' overloads above); the mesh is the same
/// for any number.
SurfaceMesh restricted_delaunay(const SurfacePacking& packing,
                                Coverage coverage = Coverage::unknown, unsigned threads = 0);

namespace detail {
struct RestrictedDelaunayState;
}
/// What one mesh of a packing keeps for the next mesh of it once a few disks have moved
/// (remesh meshes again after its angle-opening passes): the Delaunay triangulation, in which
/// the moved centers are moved, and each facet's verdict, which holds while its two
/// cells stand (they fix its dual edge). The next mesh is the same as a new one's.
/// Where more than one disk in eight moved, or the count or the surface changed, the
/// triangulation is built anew.
class RestrictedDelaunayReuse {
 public:
  RestrictedDelaunayReuse();
  ~RestrictedDelaunayReuse();
  RestrictedDelaunayReuse(RestrictedDelaunayReuse&&) noexcept;
  RestrictedDelaunayReuse& operator=(RestrictedDelaunayReuse&&) noexcept;

 private:
  friend SurfaceMesh restricted_delaunay(const SurfacePacking&, Coverage, unsigned,
                                         RestrictedDelaunayReuse*);
  std::unique_ptr<detail::RestrictedDelaunayState> state_;
};
/// The mesh of a packing as above, starting from what `reuse` (where not null) kept of
/// the last mesh it was given to, and keeping this one in it.
SurfaceMesh restricted_delaunay(const SurfacePacking& packing, Coverage coverage, unsigned threads,
                                RestrictedDelaunayReuse* reuse);

/// The symmetric Hausdorff distance between the mesh's triangles and the surface,
/// approximated from below: `samples_per_mesh` area-weighted random points on each (and
/// all vertices of each) measured to the other's closest point, on `threads` threads
/// (0: one per core). Same seed, same result, whatever the number of threads.
/// Throws InvalidInput for a mesh without triangles.
double hausdorff_distance(const SurfaceMesh& mesh, const SurfaceDomain& surface,
                          std::size_t samples_per_mesh, std::uint64_t seed, unsigned threads = 1);

}  // namespace disktune
