// SPDX-License-Identifier: GPL-3.0-or-later
// Relaxation, once for the plane and surfaces (space.h): each free disk is pulled toward
// the place where spring forces from its neighbours put it, as in bubble packing
// (Shimada and Gossard), the rest length a hexagonal spacing. A step is taken (or half,
// or a quarter of it) only where the disk meets no other and still covers what only it
// covers, so the packing stays conflict-free and maximal and its count does not change;
// what changes is its shape: the triangles of its mesh come closer to equilateral.
// open_obtuse_angles then moves the vertex of each obtuse angle of the mesh just out of
// the circle whose diameter is the opposite edge, under the same rule, or where that
// vertex cannot move, one of its two neighbours until the angle closes.
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <type_traits>
#include <unordered_set>
#include <utility>
#include <vector>

#include "../geometry/threads.h"
#include "../voids/surface_cell.h"
#include "colour_blocks.h"
#include "disktune/surface_tuning.h"
#include "disktune/surface_voids.h"
#include "disktune/tuning.h"
#include "neighbour_lists.h"
#include "relax_at_end.h"
#include "space.h"

namespace disktune {
namespace {

// The bubble-packing force at distance w rest lengths: pushes below 1, pulls between 1
// and 1.5, nothing beyond.
double spring(double w) { return w >= 1.5 ? 0.0 : (1.25 * w - 2.375) * w * w + 1.125; }

// Moves disk p to `to` (put on the domain), or half or a quarter of the way, where it
// meets no other disk and still holds everything only it covers (a void lies in the
// convex hull of its points in each plane, and a disk is convex). Returns the part of
// the way it went: 1, 0.5, 0.25, or 0 where none fits. `near_p`: the triangles near p,
// where known (a surface's). Unless `keep_covered`, only meeting no disk counts: the
// caller closes the voids such moves open (close_voids).
// `lists`: p's neighbours, where kept (a surface's relaxation), for the conflict check.
template <class P>
double move_toward(P& packing, DiskId p, typename detail::Space<P>::Location to,
                   const std::vector<std::uint32_t>* near_p = nullptr, bool keep_covered = true,
                   const detail::NeighbourLists* lists = nullptr) {
  using S = detail::Space<P>;
  const auto c = packing.center(p);
  const double r = packing.radius(p);
  const auto meets_another = [&](const typename S::Point& x) {
    if constexpr (std::is_same_v<P, SurfacePacking>) {
      if (lists)
        if (const std::optional<bool> listed = lists->conflicts(packing, p, x)) return *listed;
    }
    return packing.conflicts(x, p);
  };
  auto step = to - c;
  double part = 1;
  // What a halving's check learns for the next (a surface's): p's cell, a void point.
  [[maybe_unused]] detail::LiftedDisk* lifted = nullptr;
  if constexpr (std::is_same_v<P, SurfacePacking>) {
    thread_local detail::LiftedDisk kept;  // its lists reused from move to move
    kept.forget();
    lifted = &kept;
  }
  const auto covers = [&](const typename S::Point& x) {
    if constexpr (std::is_same_v<P, SurfacePacking>) {
      return S::covers_lifted_voids(packing, c, S::void_reach(r), p, x, near_p, lifted);
    } else {
      return S::covers_lifted_voids(packing, c, S::void_reach(r), p, x, near_p);
    }
  };
  for (int halvings = 0; halvings < 3; ++halvings, step = step * 0.5, part *= 0.5) {
    typename S::Point x;
    if (!S::project(packing, p, c + step, x) || meets_another(x)) continue;
    if (!keep_covered) {
      packing.move(p, x);
      return part;
    }
    if (!covers(x)) continue;
    detail::BasicUndoLog<P> log(packing);
    log.move(p, x);
    // With one radius covers_all is exact; with a sizing p's radius changed on the way.
    if (S::one_radius(packing) || S::void_free_near(packing, c, r)) return part;
    log.revert();
    return 0;
  }
  return 0;
}

// Each disk's step of the sweep before, added at half weight to its next (heavy-ball
// momentum): the springs only pull locally, so without it a density difference spreads
// over the packing like heat, a few disks a sweep. Measured on remesh at 10^4 vertices,
// 30 sweeps: angles in [50, 70] 81.6 -> 86.1 % (elephant), 84.5 -> 89.7 % (eight.off);
// weights 0.6 and 0.7 overshoot (78.5 and 64.0 % on the elephant), 0.3 and 0.4 gain less.
constexpr double kMomentum = 0.5;

template <class P>
using Steps = std::vector<decltype(std::declval<P>().center(DiskId{}) - std::declval<P>().center(DiskId{}))>;

// The triangles near each disk, kept from sweep to sweep (a surface's; none in the plane).
template <class P>
using NearTriangles = std::conditional_t<std::is_same_v<P, SurfacePacking>,
                                         detail::TrianglesNearDisks, std::nullptr_t>;

// The disks within each disk's springs' reach, kept from sweep to sweep (a surface's;
// the plane's come from its grid).
template <class P>
using SpringNeighbours =
    std::conditional_t<std::is_same_v<P, SurfacePacking>, detail::NeighbourLists, std::nullptr_t>;

// What a surface's relaxation keeps from sweep to sweep, made for `spacing`: the lists of
// triangles a little wider than a ball, renewed after a move of half a radius, and of the
// disks within the springs' reach, renewed after a move of kListSlack radii (most disks
// keep theirs for a few sweeps), and where each disk's grid cells ahead were made
// (sweep). Measured on the elephant at 10^4 disks, 30 sweeps: relaxation 0.42 -> 0.30 s
// on one thread with the disks' lists (their conflict checks from them too).
constexpr double kListSlack = 0.3;

// The fixed disks on an open boundary (on one of its edges or vertices), by id.
std::vector<char> fixed_on_open_boundary(const SurfacePacking& packing) {
  std::vector<char> on(packing.id_bound(), 0);
  const SurfaceDomain& domain = packing.domain();
  if (domain.is_closed()) return on;
  std::unordered_set<std::uint64_t> edges;
  std::unordered_set<std::size_t> loop_vertices;
  const auto key = [](std::size_t a, std::size_t b) {
    return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
  };
  for (const std::vector<std::size_t>& loop : domain.boundary_loops()) {
    for (std::size_t i = 0; i < loop.size(); ++i) {
      edges.insert(key(loop[i], loop[(i + 1) % loop.size()]));
      loop_vertices.insert(loop[i]);
    }
  }
  const std::vector<Vec3>& v = domain.vertices();
  const double tol = 1e-9 * norm(domain.bbox_max() - domain.bbox_min());
  for (const DiskId id : packing.ids()) {
    if (!(packing.flags(id) & kFixed)) continue;
    const Vec3 c = packing.center(id);
    const SurfaceDomain::Triangle& t = domain.triangles()[packing.point(id).triangle];
    for (int k = 0; k < 3 && !on[id]; ++k) {
      const std::size_t a = t[k], b = t[(k + 1) % 3];
      on[id] = (edges.count(key(a, b)) && distance_to_segment(c, v[a], v[b]) <= tol) ||
               (loop_vertices.count(a) && norm(c - v[a]) <= tol);
    }
  }
  return on;
}

struct SurfaceKept {
  SurfaceKept(const SurfacePacking& packing, double spacing)
      : near(packing.id_bound(), packing.max_radius() * (1 + 1e-6), 0.5 * packing.max_radius()),
        springs(packing.id_bound(), 1.5 * spacing * packing.max_radius(),
                kListSlack * packing.max_radius()),
        cells_made_at(packing.id_bound(), Vec3{kFar, kFar, kFar}),
        on_open_boundary(fixed_on_open_boundary(packing)) {}
  static constexpr double kFar = 1e300;
  detail::TrianglesNearDisks near;
  detail::NeighbourLists springs;
  std::vector<Vec3> cells_made_at;
  std::vector<char> on_open_boundary;  // of the fixed disks
};

struct PlaneKept {
  PlaneKept(const Packing&, double) {}
  std::nullptr_t near = nullptr, springs = nullptr;
};

template <class P>
using Kept = std::conditional_t<std::is_same_v<P, SurfacePacking>, SurfaceKept, PlaneKept>;

// Where `unchecked_but_near` is given (a surface's), a disk with none of the fixed disks
// it marks in reach of its springs is checked for conflicts only (move_toward): the
// caller closes the voids such moves open (close_voids). Pushed off an open boundary, a
// disk opens gaps along it that no neighbour fills: checked there, remesh's meshes of
// mesh_with_border keep 87.0-88.0 % of their angles in [50, 70] against 85.1-86.1 %
// (10^4 vertices, seeds 1-4), at no cost in time; beside a feature curve not (fandisk:
// a quarter of remesh's instructions spared, 0.3 points fewer angles in [50, 70]).
template <class P>
bool relax_disk(P& packing, DiskId p, double spacing, Steps<P>* last, NearTriangles<P>& near,
                SpringNeighbours<P>& springs,
                const std::vector<char>* unchecked_but_near = nullptr) {
  using S = detail::Space<P>;
  if (packing.flags(p) & (kFixed | kFrozen)) return false;
  const auto c = packing.center(p);
  const double r = packing.radius(p), rest = spacing * r;
  auto force = c - c;
  bool checked = !unchecked_but_near;
  const auto push = [&](DiskId q, decltype(c) image, double d2) {
    // Across a feature too, though disks there do not conflict: pushed apart, they do not
    // make thin triangles at the crease (fandisk, r = 0.04, 12 sweeps: angles in [50, 70]
    // 63 % with these forces, 60 % without).
    if (q == p || d2 <= 0 || d2 > 2.25 * rest * rest) return;
    const double d = std::sqrt(d2);
    // A fixed disk (a boundary or a crease) only pushes: pulled toward a crease, a disk
    // can end where its Voronoi cell reaches across it.
    const bool fixed = packing.flags(q) & kFixed;
    checked = checked || (fixed && (*unchecked_but_near)[q]);
    const double f = fixed ? std::max(spring(d / rest), 0.0) : spring(d / rest);
    force = force + (c - image) * (f / d);
  };
  if constexpr (std::is_same_v<P, SurfacePacking>) {
    springs.for_each(packing, p, c, [&](DiskId q, double d2) { push(q, packing.center(q), d2); });
  } else {
    S::for_each_near(packing, c, 1.5 * rest, [&](const auto& q) { push(q.id, q.image, q.d2); });
  }
  // Half the force, at most a quarter of the rest length: steps that do not overshoot.
  auto pull = force * (0.5 * rest);
  if (last) pull = pull + (*last)[p] * kMomentum;
  auto step = S::along_surface(packing, p, pull);
  const double length = norm(step);
  if (last) (*last)[p] = step * 0.0;
  if (!(length > 1e-3 * rest)) return false;  // at rest already
  if (length > 0.25 * rest) step = step * (0.25 * rest / length);
  double part = 0;
  if constexpr (std::is_same_v<P, SurfacePacking>) {
    part = checked ? move_toward(packing, p, c + step, &near.of(packing, p), true, &springs)
                   : move_toward(packing, p, c + step, nullptr, false, &springs);
    if (part > 0) springs.moved(packing, p);
  } else {
    part = move_toward(packing, p, c + step);
  }
  if (last) (*last)[p] = step * part;
  return part > 0;
}

void check_spacing(double spacing) {
  if (!(spacing > 0 && std::isfinite(spacing))) {
    throw InvalidInput("relax: the spacing must be a positive factor of the radius, got " + std::to_string(spacing));
  }
}

std::size_t sweep(Packing& packing, double spacing, Rng& rng, Steps<Packing>* last,
                  PlaneKept& kept) {
  std::vector<DiskId> order = packing.ids();
  for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[uniform_index(rng, i)]);
  std::size_t moved = 0;
  for (const DiskId p : order)
    moved += relax_disk(packing, p, spacing, last, kept.near, kept.springs);
  return moved;
}

// On a surface the disks move cube by cube (colour_blocks.h), the cubes of one colour at
// once. What one disk's move reads lies within `read` of its center: the springs' reach,
// the disks whose bisectors cut its cell and whose circles bound its void (twice its
// radius), those it could meet at its new place; it writes its own entries and the grid
// cells it leaves and enters, within `write` (a step is at most a quarter rest length,
// and its projection onto the surface at most doubles it). A grid query reads whole cells
// meeting its box, so with cubes wider than read + twice write + two cells, a cell one
// move reads and a cell another (a cube of the same colour away) enters or leaves
// differ, and so do the cells two such moves write. The cells a move can enter are made
// beforehand, so no move changes the grid's table: those within write + slack of where
// the disk is, again once it has moved more than slack since. A move that relists its
// disk (NeighbourLists::moved) writes the lists of the disks within the listed reach,
// so cubes wider than twice that and twice write keep two such moves off one list, and
// off the list of a disk another thread is moving.
std::size_t sweep(SurfacePacking& packing, double spacing, Rng& rng, Steps<SurfacePacking>* last,
                  SurfaceKept& kept, unsigned threads, bool check_all = true,
                  const std::vector<char>* only = nullptr) {
  // Where `only` is given, only its disks move, so only they need lists, grid cells made
  // ahead and places in the cubes (after a closing that exchanged disks, the lists are
  // made anew: for a sixth of fandisk's disks at 10^4, not all).
  std::vector<DiskId> order = packing.ids();
  if (only)
    order.erase(std::remove_if(order.begin(), order.end(), [&](DiskId p) { return !(*only)[p]; }),
                order.end());
  detail::NeighbourLists& springs = kept.springs;
  springs.make(packing, threads, &order);
  for (std::size_t i = order.size(); i > 1; --i)
    std::swap(order[i - 1], order[uniform_index(rng, i)]);
  const double r = packing.max_radius();
  const double read = std::max({springs.listed_reach(), (1 + 0.5 * spacing) * r, 2.001 * r});
  const double write = 0.5 * spacing * r * 1.001;
  const double cube = 1.01 * std::max(read + write + 2 * packing.grid_cell() + write,
                                      2 * springs.listed_reach() + 2 * write);
  if (!packing.grid_cells_distinct(cube)) threads = 1;
  // The cubes shifted at random and the colours in a random order, each sweep: a disk's
  // neighbours are not always moved before it, or always after.
  const Vec3 origin{cube * uniform01(rng), cube * uniform01(rng), cube * uniform01(rng)};
  const detail::ColourBlocks blocks = detail::colour_blocks(packing, order, cube, origin);
  std::array<int, 8> colours{0, 1, 2, 3, 4, 5, 6, 7};
  for (std::size_t i = colours.size(); i > 1; --i)
    std::swap(colours[i - 1], colours[uniform_index(rng, i)]);
  std::atomic<std::size_t> moved{0};
  for (const int colour : colours) {
    if (threads > 1) {
      const double slack = 0.5 * r;
      for (const auto& [first, end] : blocks.groups[colour])
        for (std::uint32_t k = first; k < end; ++k) {
          const DiskId p = blocks.disks[k];
          const Vec3 c = packing.center(p);
          if (squared_norm(c - kept.cells_made_at[p]) <= slack * slack) continue;
          packing.add_grid_cells(c, write + slack);
          kept.cells_made_at[p] = c;
        }
    }
    detail::for_each_group(blocks, colour, threads, [&](const DiskId* first, const DiskId* end) {
      std::size_t here = 0;
      for (const DiskId* p = first; p != end; ++p)
        here += relax_disk(packing, *p, spacing, last, kept.near, springs,
                           check_all ? nullptr : &kept.on_open_boundary);
      moved += here;
    });
  }
  return moved;
}

// The triangles of the surface holding a void point, in order (all scanned, on every core).
std::vector<std::uint32_t> triangles_with_voids(const SurfacePacking& packing, unsigned threads) {
  constexpr std::size_t kChunk = 256;
  const std::size_t n = packing.domain().triangles().size();
  std::vector<char> holed(n, 0);
  detail::parallel_for((n + kChunk - 1) / kChunk, threads, [&](std::size_t chunk, unsigned) {
    thread_local std::vector<SurfaceVoidPoint> found;
    for (std::size_t t = chunk * kChunk; t < std::min(n, (chunk + 1) * kChunk); ++t) {
      found.clear();
      void_points_in_triangle(packing, t, {}, found);
      holed[t] = !found.empty();
    }
  });
  std::vector<std::uint32_t> out;
  for (std::size_t t = 0; t < n; ++t)
    if (holed[t]) out.push_back(static_cast<std::uint32_t>(t));
  return out;
}

// Takes as many disks out as `injected` holds, for each the nearest free disk other than
// itself (within a few radii, else any) that attractor ejection removes; appends the
// disks near each one taken out to `pulled`. Nothing where some cannot be matched.
std::optional<std::size_t> eject_beside(SurfacePacking& packing,
                                        const std::vector<DiskId>& injected, Rng& rng,
                                        std::vector<DiskId>& pulled) {
  const double r = packing.max_radius();
  const auto movable = [&](DiskId q) { return !(packing.flags(q) & (kFixed | kFrozen)); };
  const auto eject = [&](DiskId q) {
    const Vec3 c = packing.center(q);
    if (attractor_eject(packing, q, rng, 1) != 1) return false;
    packing.for_each_near(c, 2 * r, [&](DiskId id) { pulled.push_back(id); });
    return true;
  };
  std::vector<std::pair<double, DiskId>> near;  // squared distance, disk
  for (const DiskId in : injected) {
    const Vec3 c = packing.center(in);
    near.clear();
    packing.for_each_near(c, 6 * r, [&](DiskId q) {
      if (q != in && movable(q)) near.emplace_back(squared_norm(packing.center(q) - c), q);
    });
    std::sort(near.begin(), near.end());
    bool done = false;
    for (const auto& [d2, q] : near)
      if (packing.alive(q) && (done = eject(q))) break;
    if (!done) {
      for (const DiskId q : packing.ids())
        if (q != in && movable(q) && (done = eject(q))) break;
    }
    if (!done) return std::nullopt;
  }
  return injected.size();
}

// Closes the voids that sweeps without coverage checks opened (a handful among 10^4
// disks: where a spring pulled a disk off a gap no neighbour filled). Each void point
// pulls the nearest free disk within two radii that can cover it (on its patch) until
// it lies a tenth of that disk's radius inside, by a checked move (move_toward), or the
// next nearest where that one has no room. A checked move opens no void, so the voids
// only shrink, within the triangles found at first. Where a round moves no disk (each
// void's disks held on all sides: a sliver between a fixed disk and a free one pressed
// against it), the nearest disk that meets none there is pulled over each void anyway,
// by a move checked for conflicts only: the void moves behind it, among disks with room
// to close it, and the triangles near where the disk was are scanned from then on (a
// move uncovers nothing farther). From round `inject_from` on, each void still open
// gets a disk of its own, and once none is left, as many disks are ejected, each the
// nearest one to a new disk that attractor ejection can take out (a checked operation):
// the count stays. (Such voids lie mostly beside a feature curve, among disks pressed
// against its fixed disks; pulled round after round, they closed by hairs, and some
// never.) Returns how many disks were exchanged, or nothing where some void remains
// after 16 rounds or some new disk has no partner. `pulled` gets each disk moved (once
// a move) or new, and those near each disk ejected.
std::optional<std::size_t> close_voids(SurfacePacking& packing, unsigned threads, Rng& rng,
                                       int inject_from, std::size_t& moved,
                                       std::vector<DiskId>& pulled) {
  std::vector<DiskId> injected;
  std::vector<std::uint32_t> holed = triangles_with_voids(packing, threads);
  std::vector<SurfaceVoidPoint> voids;
  std::vector<std::pair<double, DiskId>> near;  // squared distance, disk
  std::vector<std::uint32_t> uncovered;         // triangles near a disk pulled unchecked
  // The free disks within two radii of void point v that can cover it, nearest first.
  const auto disks_near = [&](const SurfaceVoidPoint& v) {
    const PatchSet patch = packing.index().patch_of_triangle(v.at.triangle);
    near.clear();
    packing.for_each_near(v.at.p, 2 * packing.max_radius(), [&](DiskId q) {
      if (!(packing.flags(q) & (kFixed | kFrozen)) &&
          packing.share_patch(packing.patches(q), patch))
        near.emplace_back(squared_norm(packing.center(q) - v.at.p), q);
    });
    std::sort(near.begin(), near.end());
  };
  for (int round = 0;; ++round) {
    voids.clear();
    std::vector<std::uint32_t> still;
    for (const std::uint32_t t : holed) {
      const std::size_t before = voids.size();
      void_points_in_triangle(packing, t, {}, voids);
      if (voids.size() > before) still.push_back(t);
    }
    holed.swap(still);
    if (voids.empty()) return eject_beside(packing, injected, rng, pulled);
    if (round == 16) return std::nullopt;
    if (round >= inject_from) {
      const std::size_t before = injected.size();
      for (const SurfaceVoidPoint& v : voids) {
        if (packing.conflicts(v.at)) continue;  // a disk put at an earlier void point
        injected.push_back(packing.insert(v.at));
        pulled.push_back(injected.back());
      }
      if (injected.size() > before) continue;
    }
    const std::size_t moved_before = moved;
    for (const SurfaceVoidPoint& v : voids) {
      disks_near(v);
      // To `inside` of the void point, straight at it, then (a disk held on its way in by
      // a neighbour may pass beside it) from 25 and 50 degrees to either side.
      const Vec3 n = packing.index().plane(v.at.triangle).normal();
      const auto pull = [&](DiskId q, double d, double inside, double angle) {
        const Vec3 c = packing.center(q), u = (c - v.at.p) * (inside / d);
        const Vec3 turned = u * std::cos(angle) + cross(n, u) * std::sin(angle) +
                            n * (dot(n, u) * (1 - std::cos(angle)));
        return move_toward(packing, q, v.at.p + turned) > 0;
      };
      // Steps of a tenth of a radius first, then smaller ones (most voids are slivers,
      // and a disk held on all sides may still have room for a hair).
      constexpr double kDegree = 3.14159265358979323846 / 180;
      const auto close_one = [&] {
        for (const double angle : {0.0, 25 * kDegree, -25 * kDegree, 50 * kDegree, -50 * kDegree})
          for (const double share : {0.9, 0.99, 0.999})
            for (const auto& [d2, q] : near) {
              const double d = std::sqrt(d2), inside = share * packing.radius(q);
              if (d <= inside) return;  // covered by a move made since the scan
              if (pull(q, d, inside, angle)) {
                ++moved;
                pulled.push_back(q);
                return;
              }
            }
      };
      close_one();
    }
    if (moved > moved_before) continue;
    // Stuck: every void's disks held. Pulled over it unchecked, the nearest that can go.
    for (const SurfaceVoidPoint& v : voids) {
      disks_near(v);
      for (const auto& [d2, q] : near) {
        const Vec3 c = packing.center(q);
        const double d = std::sqrt(d2), inside = 0.9 * packing.radius(q);
        if (d <= inside) break;  // covered by a move made since the scan
        if (move_toward(packing, q, v.at.p + (c - v.at.p) * (inside / d), nullptr, false) > 0) {
          ++moved;
          pulled.push_back(q);
          packing.index().triangles_near(c, packing.radius(q) * (1 + 1e-6), uncovered);
          holed.insert(holed.end(), uncovered.begin(), uncovered.end());
          break;
        }
      }
    }
    std::sort(holed.begin(), holed.end());
    holed.erase(std::unique(holed.begin(), holed.end()), holed.end());
  }
}

// The first `unchecked` sweeps (a surface's) check their moves for conflicts only; then
// `close(moved, pulled)` must make the packing maximal again (listing the disks it moved
// in `pulled`, answering how many disks it exchanged), or the run stops there, answering
// nothing. The sweeps after it move only the disks `only` marks, where given (a
// surface's).
template <class P>
std::optional<std::size_t> relax_in(
    P& packing, double spacing, int sweeps, Rng& rng, const std::function<bool(int)>& after_sweep,
    unsigned threads, int unchecked = 0,
    const std::function<std::optional<std::size_t>(std::size_t&, std::vector<DiskId>&)>& close = {},
    const std::vector<char>* only = nullptr) {
  check_spacing(spacing);
  if (sweeps < 0) throw InvalidInput("relax: the number of sweeps must be 0 or more, got " + std::to_string(sweeps));
  Steps<P> last(packing.id_bound(), typename Steps<P>::value_type{});
  Kept<P> kept(packing, spacing);
  std::size_t moved = 0;
  bool open = unchecked > 0;  // voids may be open
  std::vector<DiskId> pulled;
  for (int k = 0; k < sweeps; ++k) {
    if (open && k == unchecked) {
      const std::optional<std::size_t> exchanged = close(moved, pulled);
      if (!exchanged) return std::nullopt;
      if (*exchanged > 0) {  // disks came and went: what is kept of each made anew
        last.assign(packing.id_bound(), typename Steps<P>::value_type{});
        kept = Kept<P>(packing, spacing);
      } else if constexpr (std::is_same_v<P, SurfacePacking>) {
        for (const DiskId q : pulled) kept.springs.moved(packing, q);  // at its last place
      }
      open = false;
    }
    if constexpr (std::is_same_v<P, SurfacePacking>) {
      moved += sweep(packing, spacing, rng, &last, kept, threads, k >= unchecked,
                     k >= unchecked ? only : nullptr);
    } else {
      moved += sweep(packing, spacing, rng, &last, kept);
    }
    if (after_sweep && !after_sweep(k + 1)) break;
  }
  if (open && !close(moved, pulled)) return std::nullopt;
  return moved;
}

}  // namespace

std::size_t relax(Packing& packing, double spacing, Rng& rng) {
  check_spacing(spacing);
  PlaneKept kept(packing, spacing);
  return sweep(packing, spacing, rng, nullptr, kept);
}

std::size_t relax(SurfacePacking& packing, double spacing, Rng& rng, unsigned threads) {
  check_spacing(spacing);
  SurfaceKept kept(packing, spacing);
  return sweep(packing, spacing, rng, nullptr, kept, detail::thread_count(threads));
}

std::size_t relax(Packing& packing, double spacing, int sweeps, Rng& rng, const std::function<bool(int)>& after_sweep) {
  return *relax_in(packing, spacing, sweeps, rng, after_sweep, 1);
}

std::size_t relax(SurfacePacking& packing, double spacing, int sweeps, Rng& rng,
                  const std::function<bool(int)>& after_sweep, unsigned threads,
                  Maximality maximality) {
  if (maximality == Maximality::every_move)
    return *relax_in(packing, spacing, sweeps, rng, after_sweep, detail::thread_count(threads));
  return detail::relax_at_end(packing, spacing, sweeps, rng, after_sweep, threads,
                              detail::kInjectFromRound);
}

std::size_t detail::relax_at_end(SurfacePacking& packing, double spacing, int sweeps, Rng& rng,
                                 const std::function<bool(int)>& after_sweep, unsigned threads,
                                 int inject_from) {
  threads = detail::thread_count(threads);
  if (sweeps <= 0) return *relax_in(packing, spacing, sweeps, rng, after_sweep, threads);
  // The sweeps with only the conflict checks, the voids they opened closed, and two
  // checked sweeps over the disks within two rest lengths of those closing moved, which
  // smooth what it bent (the smallest angle of remesh's meshes at 10^4 vertices, elephant
  // and eight, seeds 1-4: 31.6-33.4 degrees without them, 34.9-37.6 with). Until
  // 2026-12-06 the last two of `sweeps` were the checked ones, over every disk; against
  // that (remesh on four surfaces at 10^4 and 3·10^4 vertices, seeds 1-2) relaxation of
  // the elephant at 10^4 took 0.34-0.37 -> 0.27-0.31 s on one core, the angles in [50, 70]
  // and the obtuse triangles alike, the smallest angle 0.7-2.4 degrees higher in three
  // meshes and 3.2-3.6 lower in two. Where a void will not close, the sweeps again from
  // the start with every move checked.
  constexpr int kSmoothing = 2;
  const SurfacePacking start = packing;
  const Rng start_rng = rng;
  std::vector<char> near_pulled;
  const auto close = [&](std::size_t& moved,
                         std::vector<DiskId>& pulled) -> std::optional<std::size_t> {
    const std::optional<std::size_t> exchanged =
        close_voids(packing, threads, rng, inject_from, moved, pulled);
    if (!exchanged) return std::nullopt;
    std::sort(pulled.begin(), pulled.end());  // a disk may be pulled more than once
    pulled.erase(std::unique(pulled.begin(), pulled.end()), pulled.end());
    near_pulled.assign(packing.id_bound(), 0);
    const double reach = 2 * spacing * packing.max_radius();
    for (const DiskId q : pulled) {
      if (packing.alive(q))  // not one ejected since
        packing.for_each_near(packing.center(q), reach, [&](DiskId id) { near_pulled[id] = 1; });
    }
    return exchanged;
  };
  if (const auto moved = relax_in(packing, spacing, sweeps + kSmoothing, rng, after_sweep, threads,
                                  sweeps, close, &near_pulled))
    return *moved;
  packing = start;
  rng = start_rng;
  return *relax_in(packing, spacing, sweeps, rng, after_sweep, threads);
}

namespace {

// The disk of each vertex of `mesh`, the packing's own (vertex i is the i-th live disk);
// InvalidInput, naming `who`, where the counts differ.
std::vector<DiskId> disks_of_vertices(const SurfacePacking& packing, const SurfaceMesh& mesh, const char* who) {
  std::vector<DiskId> ids = packing.ids();
  if (mesh.vertices.size() != ids.size()) {
    throw InvalidInput(std::string(who) + ": the mesh has " + std::to_string(mesh.vertices.size()) +
                       " vertices, the packing " + std::to_string(ids.size()) +
                       " disks; give the packing's own mesh (restricted_delaunay)");
  }
  return ids;
}

}  // namespace

std::size_t open_obtuse_angles(SurfacePacking& packing, const SurfaceMesh& mesh) {
  const std::vector<DiskId> ids = disks_of_vertices(packing, mesh, "open_obtuse_angles");
  // Outside the circle over ab, so that the angle at the vertex is under 90 (87 degrees):
  // remesh at 10^4 vertices, seeds 1-10, obtuse triangles left on the elephant 44 -> 40
  // and on eight.off 25 -> 20 against 1.02 times the half-edge (89 degrees), where the
  // disks' later moves tipped more of them back.
  constexpr double kOutside = 1.06;
  // The cosine a neighbour's move aims at when the vertex itself cannot move (88 degrees).
  constexpr double kAcute = 0.035;
  const auto center = [&](std::uint32_t vertex) { return packing.center(ids[vertex]); };
  const auto movable = [&](DiskId p) { return !(packing.flags(p) & (kFixed | kFrozen)); };
  std::size_t moved = 0;
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const DiskId p = ids[t[k]];
      const Vec3 a = center(t[(k + 1) % 3]), b = center(t[(k + 2) % 3]), v = center(t[k]);
      if (dot(a - v, b - v) >= 0) continue;  // not obtuse at v (or no longer)
      const Vec3 mid = (a + b) * 0.5, off = v - mid;
      const double d = norm(off), half = 0.5 * norm(a - b);
      if (movable(p) && d > 0 && move_toward(packing, p, mid + off * (kOutside * half / d)) > 0) {
        ++moved;
        continue;
      }
      // v holds (a feature or boundary disk, or no room): turn a neighbour toward the
      // other one's side, along the direction that closes the angle at v fastest.
      for (const int side : {1, 2}) {
        const DiskId q = ids[t[(k + side) % 3]];
        const Vec3 x = center(t[(k + side) % 3]), far = center(t[(k + 3 - side) % 3]) - v;
        const double reach = norm(far);
        if (!movable(q) || !(reach > 0)) continue;
        const double shift = (kAcute * norm(x - v) * reach - dot(x - v, far)) / reach;
        if (move_toward(packing, q, x + far * (shift / reach)) > 0) {
          ++moved;
          break;
        }
      }
    }
  }
  return moved;
}

std::size_t open_sharp_angles(SurfacePacking& packing, const SurfaceMesh& mesh, double degrees) {
  const std::vector<DiskId> ids = disks_of_vertices(packing, mesh, "open_sharp_angles");
  if (!(degrees > 0 && degrees < 60)) {
    throw InvalidInput("open_sharp_angles: the angle must be in (0, 60) degrees, got " +
                       std::to_string(degrees));
  }
  constexpr double kDegree = 3.14159265358979323846 / 180;
  const double below = std::cos(degrees * kDegree);  // a sharper angle's cosine is above it
  const double aim =
      1 / std::tan(0.5 * (degrees + 2) * kDegree);  // height over half the opposite edge
  const auto center = [&](std::uint32_t vertex) { return packing.center(ids[vertex]); };
  const auto movable = [&](DiskId p) { return !(packing.flags(p) & (kFixed | kFrozen)); };
  std::size_t moved = 0;
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = center(t[(k + 1) % 3]), b = center(t[(k + 2) % 3]), v = center(t[k]);
      const Vec3 va = a - v, vb = b - v;
      if (dot(va, vb) <= below * norm(va) * norm(vb)) continue;  // not sharp at v (or no longer)
      // v toward the middle of ab, to the height that makes the angle at v the aim.
      const Vec3 mid = (a + b) * 0.5, off = v - mid;
      const double d = norm(off), half = 0.5 * norm(a - b);
      const DiskId p = ids[t[k]];
      if (movable(p) && d > 0 && move_toward(packing, p, mid + off * (aim * half / d)) > 0) {
        ++moved;
        continue;
      }
      // v holds: one end of ab moves away from the other, by what widens ab to the aim
      // at v's height.
      const double widen = std::max(0.0, 2 * (d / aim - half));
      for (const int side : {1, 2}) {
        const DiskId q = ids[t[(k + side) % 3]];
        const Vec3 x = center(t[(k + side) % 3]), y = center(t[(k + 3 - side) % 3]), away = x - y;
        const double length = norm(away);
        if (!movable(q) || !(length > 0)) continue;
        if (move_toward(packing, q, x + away * (widen / length)) > 0) {
          ++moved;
          break;
        }
      }
    }
  }
  return moved;
}

}  // namespace disktune
