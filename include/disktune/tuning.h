// SPDX-License-Identifier: GPL-3.0-or-later
// Disk density tuning (the paper's sections 2 and 4): operations that move, add or
// remove disks of a uniform-radius packing, each leaving it conflict-free and maximal,
// and the scheduler that runs them in phases until the count is exactly the target.
#pragma once

#include <cstddef>
#include <functional>
#include <string>

#include "disktune/packing.h"
#include "disktune/periodic_box.h"
#include "disktune/planar_domain.h"
#include "disktune/random.h"

namespace disktune {

class SurfacePacking;

/// What the user asks for: an exact disk count, an area fraction eta, or a relative
/// radius rho (see density.h). Fractions and radii are turned into the nearest count.
struct Target {
  enum class Kind { count, area_fraction, relative_radius };
  Kind kind = Kind::count;
  double value = 0;

  static Target count(std::size_t n) { return {Kind::count, static_cast<double>(n)}; }
  static Target area_fraction(double eta) { return {Kind::area_fraction, eta}; }
  static Target relative_radius(double rho) { return {Kind::relative_radius, rho}; }
};

/// The disk count a target means for radius r in a domain of the given area. Throws
/// InvalidInput for a target that is not finite and positive, or above the densest
/// (hexagonal) packing.
std::size_t target_count(const Target& target, double r, double area);
/// The count a target means where `unit` disks make area fraction 1 (density_unit in
/// packing.h). A count is refused above the hexagonal packing's 0.9069 unit plus
/// `boundary` (boundary_unit in packing.h: what a bounded domain's edges hold beyond it).
std::size_t target_count_for_unit(const Target& target, double unit, double boundary = 0);
/// The count a target means for this packing (its radius or its sizing, and its domain's
/// boundary).
std::size_t target_count(const Target& target, const Packing& packing, double area);

/// The operations, and the phases of the scheduler that run them.
enum class Phase {
  none,
  void_injection,
  repeller_injection,
  crystal_injection,
  grain_injection,    // crystal injection from many nuclei (grain_inject)
  squeeze_injection,  // disks at the largest holes, conflicts pushed apart (squeeze_inject)
  angle_injection,
  sift_ejection,
  attractor_ejection,
  crystal_ejection,
  boundary_injection,  // 1D steps on a planar domain's boundary: the automatic schedule's last
  boundary_ejection,
  relaxation  // disks moved, none added or removed (relax; remesh runs it after tuning)
};
std::string to_string(Phase phase);

/// How `tune` picks operations: `automatic` runs the phases in the paper's order,
/// switching at the area-fraction thresholds or when a phase stops making progress
/// (in the periodic box with one radius: squeeze injection, then grain injection, then
/// one crystal where the grains stall; in a planar domain with one radius: void,
/// repeller, then the grains and the crystal; to grains_from_sample and beyond, grains
/// from the start);
/// the others run one phase alone (angle injection is not part of the automatic
/// schedule: the paper offers it as an alternative that targets obtuse triangles).
/// Targets below the current count run ejection: automatic is sifting, then attractor
/// ejection, then crystal ejection, then wide attractor ejection (three rings; on a
/// surface before the crystal); `attractor_ejection` is one ring, then three. Crystal
/// injection (alone or in the automatic schedule) is followed by repeller injection for
/// the last few disks (`grain_injection` alone: by one crystal where the grains stall,
/// then repeller injection), which crystal steps near the exact target cannot add without
/// passing it. With a sizing (varying radii)
/// there are no crystal phases (paper, 6).
enum class Method {
  automatic,
  void_injection,
  repeller_injection,
  crystal_injection,
  grain_injection,
  squeeze_injection,
  angle_injection,
  sift_ejection,
  attractor_ejection,
  crystal_ejection
};
/// The method called `name`: auto, void, repeller, crystal, grains, squeeze, angle, sift,
/// attractor or crystal-eject (the names `disktune tune --method` takes). Throws InvalidInput,
/// listing them, for any other.
Method method_named(const std::string& name);

struct Progress {
  std::size_t count;
  double area_fraction;
  Phase phase;
  /// The count at which the phase ends at the latest: the target, or sooner where the
  /// automatic schedule moves on at an area fraction (it may also stall before).
  std::size_t phase_goal = 0;
};

struct TuneOptions {
  Method method = Method::automatic;
  /// Area fractions at which the automatic schedule moves on (the paper, section 4, has
  /// 0.75 and 0.79). In the box and planar domains repeller injection takes over from
  /// void injection sooner than the paper's 0.75: from 0.70 it reaches 0.75 twice as
  /// fast, as disordered; and grains take over from it sooner than 0.79: its last
  /// hundredth took half the time of a tune to 0.80 and left it as ordered
  /// (docs/tuning.md). On a curved surface void injection hands over to the crystal, at
  /// surface_void_until.
  double void_until = 0.70;
  double repeller_until = 0.78;
  /// In the periodic box with one radius, squeeze injection replaces void and repeller
  /// injection and hands over to the grains here: to eta 0.80 it leaves 12 % of the
  /// disks locally hexagonal where the grains leave half, in a third of the time; past 0.82 it
  /// slows and orders the packing as it nears jamming (docs/tuning.md).
  double squeeze_until = 0.82;
  double surface_void_until = 0.75;
  /// Targets at or past this area fraction skip void and repeller injection: grain
  /// injection starts from the packing as given (one radius, off curved surfaces). There
  /// the grains cover three quarters of the packing or more whatever they start from
  /// (unit box, r = 0.005, eta 0.84: 78.3 % of the disks hexagonal from the sample,
  /// 74.9 % after the random phases; 0.85 and 0.89 the same within 1.3 points), 12-17
  /// times faster (docs/tuning.md). Above 1: never.
  double grains_from_sample = 0.84;
  /// A sweep over all disks that adds fewer than this fraction of the count is no
  /// progress; the phase then ends.
  double min_gain_per_sweep = 2e-4;
  /// Upper bound on sweeps in one phase, so a run always ends (the repeller phases'
  /// sweeps over the sparsest tenth of the disks count a tenth each).
  int max_sweeps_per_phase = 200;
  /// Called now and then (after each sweep, and each 1/64 of a sweep). Returning false
  /// cancels: tune then puts the packing back as it got it and throws Cancelled.
  std::function<bool(const Progress&)> on_progress;
  /// Called after every single operation that changed the packing (for tests: slow).
  std::function<void(const Packing&)> after_operation;
  /// The same for tuning on a surface (surface_tuning.h).
  std::function<void(const SurfacePacking&)> after_surface_operation;
};

struct TuneResult {
  std::size_t target = 0;  // the count asked for
  std::size_t count = 0;   // the count reached
  bool reached = false;    // count == target
  Phase last_phase = Phase::none;
  std::size_t sweeps = 0;
  double seconds = 0;
  /// Of `seconds`, the time spent on the final check of the result (and on keeping the
  /// packing before each phase, to hand back should that check fail).
  double check_seconds = 0;
};

/// Moves, adds and removes disks of `packing` (uniform radius, conflict-free and
/// maximal on entry) until it has exactly the target count, or no phase makes progress
/// any more (then `reached` is false and the packing is the closest it got). Every
/// intermediate state between operations is conflict-free and maximal. A transaction:
/// when anything throws on the way (a cancel, an error from a callback, running out of
/// memory), the packing is put back as tune got it before the exception goes on.
TuneResult tune(Packing& packing, const PeriodicBox& box, const Target& target, Rng& rng,
                const TuneOptions& options = {});

/// The same in a planar domain: `packing` restricted to it (Packing::set_domain), its
/// boundary disks fixed. The boundary disks are tuned first toward the spacing of a
/// hexagonal packing of the target count (tune_boundary), then the interior as above.
/// Angle injection needs the periodic box.
TuneResult tune(Packing& packing, const PlanarDomain& domain, const Target& target, Rng& rng,
                const TuneOptions& options = {});

// The single operations. Each returns the number of disks it added (0 when it only
// moved disks or changed nothing) and leaves the packing conflict-free and maximal.
// `max_added` caps the count change: an operation that would add more is taken back
// whole and returns 0.

/// Void injection (2.1): lift p, move it to one corner of its void's diameter pair, and
/// inject at the diameter corner of what is left while anything is left.
std::size_t void_inject(Packing& packing, DiskId p, Rng& rng, std::size_t max_added);

/// Repeller injection (2.2): move each neighbour of p to the corner of its void of
/// largest weighted distance |c - p| - r(c) from p (6.1.2) until a gap opens, inject
/// there; otherwise void-inject p.
std::size_t repeller_inject(Packing& packing, DiskId p, Rng& rng, std::size_t max_added);

/// The repeller step alone, around any point: the disks within 2r of `point` (except
/// `self`, the disk at the point if there is one), in random order, each moved to the
/// corner of its own void farthest from the point, until one leaves a gap, which is
/// filled. Returns the number of disks added (0: every disk moved, no gap).
std::size_t repel_from(Packing& packing, Vec2 point, DiskId self, Rng& rng, std::size_t max_added);

/// Crystal-growth injection (2.3): grows one hexagonal crystal of frozen disks from a
/// seed pair at distance r over the whole domain; each step moves a mobile disk onto
/// an attractor site (deleting the disks it would conflict with and refilling their
/// voids) or injects a frozen disk at an uncovered site. Steps that would lower the
/// count or add more than max_added are taken back. `after_step` runs after each step
/// that changed the packing. Returns the number of disks added.
std::size_t crystal_inject(Packing& packing, Rng& rng, std::size_t max_added,
                           const std::function<void()>& after_step = {});

/// The disks a grain of grain_inject holds, on average, by default.
inline constexpr std::size_t kDisksPerGrain = 300;

/// Grain injection (beyond the paper, which grows one crystal): crystal_inject from one
/// nucleus for each `disks_per_grain` disks, far apart, their orientations spread evenly
/// over the lattice's period, all growing from one front until they meet. The packing
/// keeps no common orientation (the unit box at r = 0.005 to eta 0.85: global psi6
/// 0.02-0.05 against 0.62 for one crystal, docs/tuning.md); grain boundaries are looser than a
/// crystal, so it stalls near eta 0.86, where one crystal reaches 0.90. Returns the number of disks
/// added.
std::size_t grain_inject(Packing& packing, Rng& rng, std::size_t max_added,
                         const std::function<void()>& after_step = {},
                         std::size_t disks_per_grain = kDisksPerGrain);

/// Squeeze injection (beyond the paper; the periodic box, one radius): one stage puts
/// max_added new disks at once at the largest holes of the Delaunay triangulation (the
/// largest circumcircles, no two new centers closer than r), relaxes the packing as soft
/// disks where the stage adds at least a sixteenth of it (on every core, the same packing
/// on any number), pushes every pair still closer than r apart until none is left, then
/// refills the voids the moves opened; where the
/// refill passes max_added, as many disks are ejected again (attractor ejection, then
/// sifting, of the refill's disks first). A stage that does not settle, or whose count
/// cannot be brought back, is taken back and tried smaller. The stage moves many disks:
/// the packing is conflict-free and maximal before and after it, not in between, and a
/// stage numbers its disks anew, in order of place (ids held from before it name other
/// disks after it).
/// `after_step` runs once, after the stage. `poll`, where given, is called now and then
/// while a stage's moves are worked out (every 16 steps of the soft disks or sweeps of
/// the pushes: a stage of 10^6 disks takes seconds), the packing still as the call got
/// it; what it throws ends the call and leaves the packing so (tune's progress callback
/// is called there, and can cancel). A quench, so the packing stays about as disordered
/// as it was (docs/tuning.md). Returns the number of disks added (max_added, or fewer
/// where the packing jams); throws InvalidInput in a planar domain or with a sizing.
std::size_t squeeze_inject(Packing& packing, Rng& rng, std::size_t max_added,
                           const std::function<void()>& after_step = {},
                           const std::function<void()>& poll = {});

/// Crystal-growth ejection (3.2): as crystal_inject, with the lattice spacing sqrt(3) r
/// of the sparsest covering: a mobile disk covering a site moves there, the disks it
/// conflicts with are deleted and the voids left refilled. Steps that would raise the
/// count or remove more than max_removed are taken back. Returns the number removed.
std::size_t crystal_eject(Packing& packing, Rng& rng, std::size_t max_removed,
                          const std::function<void()>& after_step = {});

/// Sifted-disks ejection (section 3): p and one overlapping neighbour are replaced by a
/// single disk that covers what they covered (random where there is a choice). Returns
/// the number of disks removed: 1, or 0 when no neighbour allows it.
std::size_t sift_eject(Packing& packing, DiskId p, Rng& rng, std::size_t max_removed);

/// Attractor ejection (3.1): each neighbour of p moves toward p as far as it can while
/// covering its own void and staying out of other disks; then p is removed if its void
/// is covered, else moved to the center of the smallest circle around its void's
/// corners, else everything goes back. Returns the number of disks removed (0 or 1).
std::size_t attractor_eject(Packing& packing, DiskId p, Rng& rng, std::size_t max_removed);

/// Attractor ejection over three rings of neighbours: the disks up to three neighbour
/// steps from p are pulled, the outer rings first, each toward the disk nearer p it
/// neighbours, so that the first ring has room to close over p. It removes disks where
/// the one-ring attractor has stalled (the automatic schedule's last ejection phase),
/// at about four times its cost per operation.
std::size_t wide_attractor_eject(Packing& packing, DiskId p, Rng& rng, std::size_t max_removed);

/// Relaxation (keeps the count): one sweep over the free disks in random order, each
/// pulled toward where spring forces from the disks within 1.5 rest lengths put it
/// (bubble packing; the rest length is `spacing` times the disk's radius, 1/rho for the
/// hexagonal spacing of the packing's density), stopping where it would meet another
/// disk or leave part of its own void uncovered. The packing stays conflict-free and
/// maximal. Returns how many disks moved; throws InvalidInput for a spacing <= 0.
std::size_t relax(Packing& packing, double spacing, Rng& rng);

/// `sweeps` sweeps of relax, each disk's step adding half its step of the sweep before
/// (momentum: density differences travel across the packing faster than the springs'
/// local pull alone carries them; remesh and `tune --relax` use this). `after_sweep(k)`,
/// if given, runs after sweep k and stops the run by returning false. Returns the moves
/// over all sweeps; throws InvalidInput for a spacing <= 0 or sweeps < 0.
std::size_t relax(Packing& packing, double spacing, int sweeps, Rng& rng,
                  const std::function<bool(int)>& after_sweep = {});

/// Injection for angles (2.4), one sweep: the circumcenter of every obtuse triangle of
/// the periodic Delaunay triangulation, in random order, is used as a repeller point
/// (triangles whose disks moved meanwhile wait for the next sweep). Returns the number
/// of disks added; `after_step` runs after each repeller step.
std::size_t angle_inject(Packing& packing, Rng& rng, std::size_t max_added,
                         const std::function<void()>& after_step = {});

}  // namespace disktune
