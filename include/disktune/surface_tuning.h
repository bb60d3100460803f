// SPDX-License-Identifier: GPL-3.0-or-later
// Density tuning on a curved surface (paper, section 7.2): void and repeller injection,
// sifted and attractor ejection, crystal growth, with the surface void points
// (surface_voids.h) in place of planar corners. The fixed disks of open boundary curves
// stay. Sampling the surface is surface_sampling.h's (included here: tuning starts from it).
#pragma once

#include <cstddef>
#include <functional>

#include "disktune/random.h"
#include "disktune/surface_mesh.h"
#include "disktune/surface_packing.h"
#include "disktune/surface_sampling.h"
#include "disktune/tuning.h"

namespace disktune {

/// The count a target means on the surface (density_unit in surface_packing.h).
std::size_t target_count(const Target& target, const SurfacePacking& packing);

/// Tunes the count to the target as tune() does in the plane, with the surface's
/// operations and nearly the same automatic schedule: injection is void injection, then
/// crystal injection (no repeller phase before it: on a curved surface the crystal
/// barely grows in the packing that phase leaves, measured), then repeller injection for
/// the last few; ejection is sifting, attractor, crystal
/// ejection (no crystal phases with a sizing), or one method alone. Angle injection
/// throws InvalidInput (it needs the periodic Delaunay mesh). Fixed disks never move.
/// `options.after_surface_operation`, when set, runs after every operation.
TuneResult tune(SurfacePacking& packing, const Target& target, Rng& rng, const TuneOptions& options = {});

/// 1D tuning of the open boundary (paper, 7), the surface form of tune_boundary
/// (boundary.h), with the same core: each boundary loop is a closed curve (no pinned
/// disk) whose fixed disks move along it by 1D injection and ejection until the loop
/// holds the number of disks that spaces them spacing_factor times the local radius
/// (the sizing's, at each point; kept within [r, 2r] per step), or no step changes the
/// count for a while (a step that changes no count is retried on a run of consecutive
/// disks laid out again evenly; at the end the loop is laid out evenly at once where
/// valid, else sweeps even out the gaps, as in the plane).
/// After every step the boundary disks stay max(r_i, r_j) apart in
/// space and cover the boundary, interior disks they conflict with are gone and the
/// voids refilled. tune() does this first, at the spacing of a hexagonal packing of the
/// target count. A closed surface has nothing to tune.
void respace_surface_boundary(SurfacePacking& packing, double spacing_factor, Rng& rng);

/// One 1D injection (ejection) at a boundary disk drawn at random, as boundary_inject
/// (boundary_eject) in boundary.h does in the plane. Returns the boundary disks added
/// (-1 when one was removed); 0 on a closed surface.
long boundary_inject(SurfacePacking& packing, Rng& rng);
long boundary_eject(SurfacePacking& packing, Rng& rng);

// The single operations; each returns the number of disks added (removed) and leaves the
// packing conflict-free and maximal; one that would pass `max_added` is taken back.
std::size_t void_inject(SurfacePacking& packing, DiskId p, Rng& rng, std::size_t max_added);
std::size_t repeller_inject(SurfacePacking& packing, DiskId p, Rng& rng, std::size_t max_added);
std::size_t sift_eject(SurfacePacking& packing, DiskId p, Rng& rng, std::size_t max_removed);
std::size_t attractor_eject(SurfacePacking& packing, DiskId p, Rng& rng, std::size_t max_removed);
std::size_t wide_attractor_eject(SurfacePacking& packing, DiskId p, Rng& rng, std::size_t max_removed);
/// Relaxation on a surface (tuning.h): each step in the tangent plane at the disk. The
/// disks move in cubes of space a few radii wide, cubes far apart at once on up to
/// `threads` threads (0: one per core); the result is the same for any number.
std::size_t relax(SurfacePacking& packing, double spacing, Rng& rng, unsigned threads = 0);
/// When several sweeps of relax keep the packing maximal. `every_move`: each move is
/// checked not to uncover anything (the packing is maximal after every move).
/// `at_end`: the sweeps' moves are checked for conflicts only (but those of disks near
/// an open boundary's fixed disks); then the voids they opened (a handful among 10^4
/// disks) are found by an exact scan of the surface and closed by checked moves of the
/// disks next to them, or, where two rounds of such moves leave one open, by a disk put
/// in it and the nearest disk that attractor ejection can take out taken out (the count
/// stays; disk ids are not kept then), and two more sweeps, checked, move the disks
/// within two rest lengths of those (after_sweep sees sweeps + 2); where a void will
/// not close, the sweeps run again from the start as `every_move` (same seed, same
/// result). The result is maximal either way and the meshes alike; `at_end` takes about
/// a third of the time (remesh uses it), but `after_sweep` may see voids.
enum class Maximality { every_move, at_end };
/// Several sweeps with momentum (tuning.h), on up to `threads` threads as above.
std::size_t relax(SurfacePacking& packing, double spacing, int sweeps, Rng& rng,
                  const std::function<bool(int)>& after_sweep = {}, unsigned threads = 0,
                  Maximality maximality = Maximality::every_move);
/// For each angle above 90 degrees in `mesh` (the packing's restricted Delaunay mesh,
/// vertex i its i-th live disk), moves the free disk at it radially away from the
/// midpoint of the opposite edge, outside the circle with that edge as diameter (the
/// angle there 87 degrees; or half, or a quarter of the way), where the packing stays
/// conflict-free and maximal; where that disk is fixed or has no room, moves one of the
/// other two toward the far side instead, until the angle is just under 90 degrees. Mesh
/// the packing again after it. Returns how many disks moved; throws InvalidInput when
/// the mesh's vertex count is not the packing's.
std::size_t open_obtuse_angles(SurfacePacking& packing, const SurfaceMesh& mesh);

/// For each angle below `degrees` in `mesh` (as open_obtuse_angles takes it), moves the
/// free disk at it toward the midpoint of the opposite edge, to where the angle would be
/// two degrees above `degrees` (or half, or a quarter of the way), where the packing
/// stays conflict-free and maximal; where that disk is fixed or has no room, moves one
/// of the edge's ends away from the other instead. Mesh the packing again after it.
/// Returns how many disks moved; throws InvalidInput when the mesh's vertex count is not
/// the packing's, or `degrees` is not in (0, 60).
std::size_t open_sharp_angles(SurfacePacking& packing, const SurfaceMesh& mesh, double degrees);

/// Crystal growth on the surface (one radius only): a crystal of frozen disks at spacing
/// r (injection) or sqrt(3) r (ejection) grows over the surface, its sites the points at
/// that distance from two frozen neighbours; as in the plane (tuning.h), steps past the
/// target are taken back. `after_step` runs after each kept step.
std::size_t crystal_inject(SurfacePacking& packing, Rng& rng, std::size_t max_added,
                           const std::function<void()>& after_step = {});
std::size_t crystal_eject(SurfacePacking& packing, Rng& rng, std::size_t max_removed,
                          const std::function<void()>& after_step = {});
/// Crystal injection from many nuclei (tuning.h, grain_inject).
std::size_t grain_inject(SurfacePacking& packing, Rng& rng, std::size_t max_added,
                         const std::function<void()>& after_step = {},
                         std::size_t disks_per_grain = kDisksPerGrain);

}  // namespace disktune
