// SPDX-License-Identifier: GPL-3.0-or-later
// Maximal Poisson-disk sampling on a surface, unbiased as Ebeida et al.'s sampler of the
// box is: fixed disks first (on the feature corners, evenly along the feature curves,
// then by 1D darts into what is left uncovered of the fixed curves), then darts by area over the
// surface and over ever smaller cells around the uncovered part, then each remaining void gets a
// disk at a uniform point of it (never at its vertices, which would bias the spacing). The scans
// that only read the packing (which cells one disk covers, which darts land uncovered,
// which cells hold a void) run on every core, in chunks joined in order; insertions stay
// in order on one thread: the same sample for any number of threads.
#include "surface_mps.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>

#include "../geometry/threads.h"
#include "../voids/final_check.h"
#include "curve_layout.h"
#include "disktune/errors.h"
#include "disktune/surface_sampling.h"
#include "disktune/surface_voids.h"
#include "disktune/tolerance.h"
#include "weight_picker.h"

namespace disktune {
namespace {

// Weights with prefix sums (a Fenwick tree, appended to as gaps appear): a dart picks a
// gap by its length in O(log n), and a gap is emptied in O(log n).
class LengthTree {
 public:
  std::size_t size() const { return weight_.size(); }
  double weight(std::size_t k) const { return weight_[k]; }
  std::size_t push(double w) {
    const std::size_t i = weight_.size() + 1;
    weight_.push_back(w);
    tree_.push_back(w + prefix(i - 1) - prefix(i - (i & (~i + 1))));
    return i - 1;
  }
  void clear_weight(std::size_t k) {
    const double d = -weight_[k];
    weight_[k] = 0;
    for (std::size_t i = k + 1; i < tree_.size(); i += i & (~i + 1)) tree_[i] += d;
  }
  double total() const { return prefix(weight_.size()); }
  // The k whose weight holds x: prefix(k) <= x < prefix(k + 1).
  std::size_t find(double x) const {
    std::size_t pos = 0, step = 1;
    while (step * 2 < tree_.size()) step *= 2;
    for (; step > 0; step /= 2)
      if (pos + step < tree_.size() && tree_[pos + step] <= x) x -= tree_[pos += step];
    return pos;
  }

 private:
  std::vector<double> weight_;
  std::vector<double> tree_{0.0};  // 1-based
  double prefix(std::size_t i) const {
    double sum = 0;
    for (; i > 0; i -= i & (~i + 1)) sum += tree_[i];
    return sum;
  }
};

// A fixed disk on each corner (features' and the boundary's) that no earlier one covers
// (two corners closer than r share one disk), in vertex order.
void sample_corners(SurfacePacking& packing) {
  const SurfaceDomain& d = packing.domain();
  if (d.corners().empty()) return;
  std::vector<std::uint32_t> triangle_at(d.vertices().size());
  for (std::size_t t = 0; t < d.triangles().size(); ++t)
    for (const std::size_t v : d.triangles()[t]) triangle_at[v] = static_cast<std::uint32_t>(t);
  for (const std::size_t v : d.corners())
    if (!packing.covered(d.vertices()[v], kAnyPatch)) packing.insert({d.vertices()[v], triangle_at[v]}, kFixed);
}

// Each fixed curve's disks laid out evenly (curve_layout.h): between its corner disks,
// or around a closed curve (a boundary loop without corners) from a random point. A curve
// where that does not fit (a short curve, or another curve close by) keeps none of them;
// the 1D darts then cover it.
void lay_out_curves(SurfacePacking& packing, Rng& rng) {
  const SurfaceDomain& d = packing.domain();
  for (std::size_t c = 0; c < d.fixed_curves().size(); ++c) {
    const SurfaceCurve& curve = d.fixed_curves()[c];
    const std::size_t edges = curve.edge_count();
    // u in [0, edges]: edge floor(u) at t = u - floor(u).
    const auto at = [&](double u) {
      const auto e = std::min(static_cast<std::size_t>(std::max(u, 0.0)), edges - 1);
      return packing.index().on_curve(c, e, std::clamp(u - static_cast<double>(e), 0.0, 1.0));
    };
    const auto radius = [&](const SurfacePoint& q) { return packing.radius_at(q); };
    const auto place = [&](const SurfacePoint& q) { return packing.covered(q.p, kAnyPatch) ? kNoDisk : packing.insert(q, kFixed); };
    const auto remove = [&](DiskId id) { packing.remove(id); };
    detail::lay_out_evenly(0, static_cast<double>(edges), curve.closed, false, curve.closed ? uniform01(rng) : 0,
                           8 * edges, at, radius, place, remove);
  }
}

// 1D darts into the uncovered parts of the fixed curves' edges, as fixed disks.
void sample_curves(SurfacePacking& packing, Rng& rng) {
  const SurfaceDomain& d = packing.domain();
  struct Edge {
    std::size_t curve, edge;
    Vec3 a, b;
    std::map<double, std::uint32_t> gaps;  // its live gaps by their start
  };
  std::vector<Edge> edges;
  std::vector<CurveGap> gaps;
  LengthTree lengths;
  const auto add_gap = [&](std::size_t e, double t0, double t1) {
    edges[e].gaps.emplace(t0, static_cast<std::uint32_t>(gaps.size()));
    gaps.push_back({edges[e].curve, edges[e].edge, t0, t1});
    lengths.push((t1 - t0) * norm(edges[e].b - edges[e].a));
  };
  // The edges in pieces of at most r_max in a grid, to find those a new disk reaches.
  const double r_max = packing.max_radius();
  SpaceGrid near_edges(2 * r_max);
  std::vector<CurveGap> found;
  for (std::size_t c = 0; c < d.fixed_curves().size(); ++c) {
    const SurfaceCurve& curve = d.fixed_curves()[c];
    const auto& v = curve.vertices;
    for (std::size_t k = 0; k < curve.edge_count(); ++k) {
      const std::size_t e = edges.size();
      edges.push_back({c, k, d.vertices()[v[k]], d.vertices()[v[(k + 1) % v.size()]], {}});
      found.clear();
      uncovered_on_curve_edge(packing, c, k, true, found);
      for (const CurveGap& g : found) add_gap(e, g.t0, g.t1);
      const Vec3 a = edges[e].a, ab = edges[e].b - a;
      const int pieces = std::max(1, static_cast<int>(std::ceil(norm(ab) / r_max)));
      for (int p = 0; p < pieces; ++p) near_edges.insert(static_cast<std::uint32_t>(e), a + ab * ((p + 0.5) / pieces));
    }
  }
  std::size_t live = 0;
  for (std::size_t g = 0; g < gaps.size(); ++g) live += lengths.weight(g) > 0;
  std::vector<std::uint32_t> reached;
  while (live > 0) {
    // A dart uniform over the uncovered length (the sums drift by rounding: a draw that
    // lands on an emptied gap is drawn again from the live ones by a plain walk).
    std::size_t k = lengths.find(uniform01(rng) * lengths.total());
    if (k >= gaps.size() || lengths.weight(k) <= 0) {
      double left = 0;
      for (std::size_t g = 0; g < gaps.size(); ++g) left += lengths.weight(g);
      double u = uniform01(rng) * left;
      std::size_t last_live = 0;
      for (k = 0; k < gaps.size(); ++k) {
        if (lengths.weight(k) <= 0) continue;
        if (u < lengths.weight(k)) break;
        u -= lengths.weight(k);
        last_live = k;
      }
      if (k == gaps.size()) k = last_live;
    }
    const CurveGap g = gaps[k];
    const DiskId id =
        packing.insert(packing.index().on_curve(g.curve, g.edge, g.t0 + (g.t1 - g.t0) * uniform01(rng)), kFixed);
    // The new disk covers one interval of each edge it reaches: cut it out of the gaps
    // there.
    const Vec3 c = packing.center(id);
    const double r = packing.radius(id) * (1 + kRelTol);
    reached.clear();
    near_edges.for_each_in_box(c, r + r_max, [&](std::uint32_t e) { reached.push_back(e); });
    std::sort(reached.begin(), reached.end());
    reached.erase(std::unique(reached.begin(), reached.end()), reached.end());
    for (const std::uint32_t e : reached) {
      const auto in = segment_in_ball(edges[e].a, edges[e].b, c, r);
      if (!in) continue;
      // The gaps meeting [in0, in1]: from the last one starting at or before in0.
      auto& mine = edges[e].gaps;
      auto it = mine.upper_bound((*in)[0]);
      if (it != mine.begin()) --it;
      std::vector<std::uint32_t> hit;
      for (; it != mine.end() && it->first < (*in)[1]; ++it)
        if (gaps[it->second].t1 > (*in)[0]) hit.push_back(it->second);
      for (const std::uint32_t h : hit) {
        const CurveGap old = gaps[h];
        mine.erase(old.t0);
        lengths.clear_weight(h);
        --live;
        if (old.t0 < (*in)[0]) add_gap(e, old.t0, (*in)[0]), ++live;
        if ((*in)[1] < old.t1) add_gap(e, (*in)[1], old.t1), ++live;
      }
    }
  }
}

// Keeps each dart that no disk covers, the darts kept before it included, as throwing
// them one at a time in their order does, but in two passes: first the darts that the
// disks already there cover are dropped, asked in the order of `group` (darts of one
// group, and of groups next in number, lie near each other), so that each query finds
// in cache most of what it reads; then the others, in their own order, are kept where
// still uncovered. At 10^6 disks a query at a random place waits on several cache
// misses, and most darts fall in the first pass. The same sample bit for bit.
void keep_uncovered(SurfacePacking& packing, std::vector<SurfacePoint> darts,
                    const std::vector<std::uint32_t>& group, std::size_t groups) {
  std::vector<std::uint32_t> start(groups + 1, 0);  // a counting sort by group
  for (const std::uint32_t g : group) ++start[g + 1];
  for (std::size_t g = 0; g < groups; ++g) start[g + 1] += start[g];
  std::vector<std::uint32_t> rank(darts.size());   // by group: each dart's place in the throw
  std::vector<SurfacePoint> placed(darts.size());  // by group: the darts
  for (std::size_t k = 0; k < darts.size(); ++k) {
    const std::uint32_t at = start[group[k]]++;
    rank[at] = static_cast<std::uint32_t>(k);
    placed[at] = darts[k];
  }
  darts = {};
  // The darts no disk covered, each as its rank in the throw (high half) and its place
  // in `placed` (low half), so that sorting the numbers puts them in the throw's order.
  std::vector<std::uint64_t> open;
  detail::ordered_chunks<std::vector<std::uint64_t>>(
      placed.size(), detail::thread_count(0),
      [&](std::size_t from, std::size_t to, std::vector<std::uint64_t>& part) {
        for (auto at = static_cast<std::uint32_t>(from); at < to; ++at)
          if (!packing.covered(placed[at])) part.push_back(std::uint64_t{rank[at]} << 32 | at);
      },
      [&](const std::vector<std::uint64_t>& part) {
        open.insert(open.end(), part.begin(), part.end());
      });
  std::sort(open.begin(), open.end());
  for (const std::uint64_t key : open) {
    const SurfacePoint& q = placed[static_cast<std::uint32_t>(key)];
    if (!packing.covered(q)) packing.insert(q);
  }
}

// A cell: one of the 4^level similar triangles into which halving every edge `level`
// times splits domain triangle t. In the barycentric lattice of step 1/n (n = 2^level)
// from t's first corner, (i, j) is the cell's lowest lattice point; an "up" cell has the
// corners (i, j), (i+1, j), (i, j+1), the other kind (i+1, j), (i, j+1), (i+1, j+1).
struct Cell {
  std::uint32_t triangle, i, j;
  std::uint8_t level;
  bool up;
};

constexpr int kDeepestLevel = 31;  // i and j stay below 2^31

// The cells' geometry on one domain, and the darts into them.
class Cells {
 public:
  explicit Cells(const SurfaceDomain& d) : domain_(d) {
    for (const auto& t : d.triangles()) {
      const Vec3 a = d.vertices()[t[0]], b = d.vertices()[t[1]], c = d.vertices()[t[2]];
      area_.push_back(0.5 * norm(cross(b - a, c - a)));
      longest_.push_back(std::sqrt(std::max({squared_norm(b - a), squared_norm(c - b), squared_norm(a - c)})));
    }
  }
  double area(const Cell& c) const { return area_[c.triangle] * half_to_[2 * c.level]; }
  double longest(const Cell& c) const { return longest_[c.triangle] * half_to_[c.level]; }
  std::array<Vec3, 3> corners(const Cell& c) const {
    const auto& t = domain_.triangles()[c.triangle];
    const Vec3 a = domain_.vertices()[t[0]], b = domain_.vertices()[t[1]], d = domain_.vertices()[t[2]];
    const double step = half_to_[c.level];
    const auto at = [&](std::uint32_t i, std::uint32_t j) {
      return a + (b - a) * (double(i) * step) + (d - a) * (double(j) * step);
    };
    if (c.up) return {at(c.i, c.j), at(c.i + 1, c.j), at(c.i, c.j + 1)};
    return {at(c.i + 1, c.j), at(c.i, c.j + 1), at(c.i + 1, c.j + 1)};
  }
  // The four cells of the next level that tile c (halving its edges).
  static std::array<Cell, 4> children(const Cell& c) {
    const std::uint32_t i = 2 * c.i, j = 2 * c.j, t = c.triangle;
    const auto l = static_cast<std::uint8_t>(c.level + 1);
    if (c.up) return {Cell{t, i, j, l, true}, {t, i + 1, j, l, true}, {t, i, j + 1, l, true}, {t, i, j, l, false}};
    return {Cell{t, i + 1, j, l, false}, {t, i, j + 1, l, false}, {t, i + 1, j + 1, l, false}, {t, i + 1, j + 1, l, true}};
  }
  // A point uniformly distributed over the cell.
  SurfacePoint dart(const Cell& c, Rng& rng) const {
    const double s = uniform01(rng);
    return dart(c, s, uniform01(rng));
  }
  /// The dart of the two uniform numbers s and w.
  SurfacePoint dart(const Cell& c, double s, double w) const {
    const auto p = corners(c);
    if (s + w > 1) s = 1 - s, w = 1 - w;
    return {p[0] + (p[1] - p[0]) * s + (p[2] - p[0]) * w, c.triangle};
  }

 private:
  const SurfaceDomain& domain_;
  std::vector<double> area_, longest_;
  // 2^-k, k up to twice the deepest level: a product with it is exact, as ldexp is, and
  // a tenth of its cost (ldexp was a twentieth of the sampling's time).
  std::array<double, 2 * kDeepestLevel + 1> half_to_ = [] {
    std::array<double, 2 * kDeepestLevel + 1> h{};
    for (int k = 0; k <= 2 * kDeepestLevel; ++k) h[k] = std::ldexp(1.0, -k);
    return h;
  }();
};

// True when one disk of the cell's patch holds all three corners of the cell, so all of
// it (a ball is convex). `last`: the disk that held the cell asked about before, tried
// first (cells are asked about in order of place, and one disk often holds a few),
// then set to the one found.
bool covered_by_one(const SurfacePacking& packing, const Cells& cells, const Cell& cell,
                    DiskId& last) {
  const std::array<Vec3, 3> p = cells.corners(cell);
  const PatchSet patch = packing.index().patch_of_triangle(cell.triangle);
  const auto holds = [&](DiskId id) {
    if (!packing.share_patch(packing.patches(id), patch)) return false;
    const Vec3 c = packing.center(id);
    const double r2 = packing.radius(id) * packing.radius(id);
    return squared_norm(p[0] - c) <= r2 && squared_norm(p[1] - c) <= r2 && squared_norm(p[2] - c) <= r2;
  };
  if (last != kNoDisk && packing.alive(last) && holds(last)) return true;
  const Vec3 middle = (p[0] + p[1] + p[2]) * (1.0 / 3);
  return packing.any_near(middle, packing.max_radius(),
                          [&](DiskId id) { return holds(id) && (last = id, true); });
}

// The cells that no disk covers alone, split until their longest edge is at most `side`
// (coarse cells that one disk covers dropped whole). A sliver (longer than 64 side) stops
// once it is no wider than `side`, however long it still is: splitting it further would
// make (length / side)^2 cells, where its area needs a few.
void uncovered_cells(const SurfacePacking& packing, const Cells& cells, double side, std::vector<Cell>& out) {
  const auto fill = [&](std::size_t from, std::size_t to, std::vector<Cell>& found) {
    std::vector<Cell> stack;
    DiskId last = kNoDisk;
    for (auto t = static_cast<std::uint32_t>(from); t < to; ++t) {
      stack.push_back({t, 0, 0, 0, true});
      while (!stack.empty()) {
        const Cell c = stack.back();
        stack.pop_back();
        if (covered_by_one(packing, cells, c, last)) continue;
        const bool thin_sliver =
            cells.longest(c) > 64 * side && 2 * cells.area(c) <= cells.longest(c) * side;
        if (cells.longest(c) <= side || thin_sliver || c.level == kDeepestLevel) {
          found.push_back(c);
        } else {
          for (const Cell& k : Cells::children(c)) stack.push_back(k);
        }
      }
    }
  };
  detail::ordered_chunks<std::vector<Cell>>(
      packing.domain().triangles().size(), detail::thread_count(0), fill,
      [&](const std::vector<Cell>& found) { out.insert(out.end(), found.begin(), found.end()); });
}

// Darts by area into the cells, as many as there are cells; then the cells that one
// disk now covers are dropped and the others split in four (children one disk covers
// dropped too), but for slivers longer than `side`, which go to `parked` as they are: no
// later level throws darts at them, the void filling does. Every accepted dart is
// uniform over the uncovered area of the cells darted at, because they hold all of it.
void dart_level(SurfacePacking& packing, const Cells& cells, double side, std::vector<Cell>& active,
                std::vector<Cell>& parked, Rng& rng) {
  std::vector<SurfacePoint> darts(active.size());
  std::vector<std::uint32_t> cell_of(active.size());
  {
    // Three numbers a dart, drawn in order, then made into darts on every core.
    std::vector<double> u(3 * active.size());
    for (double& x : u) x = uniform01(rng);
    const detail::WeightPicker pick(active.size(),
                                    [&](std::size_t k) { return cells.area(active[k]); });
    detail::ordered_chunks<char>(
        active.size(), detail::thread_count(0),
        [&](std::size_t from, std::size_t to, char&) {
          for (std::size_t k = from; k < to; ++k) {
            cell_of[k] = static_cast<std::uint32_t>(pick(u[3 * k]));
            darts[k] = cells.dart(active[cell_of[k]], u[3 * k + 1], u[3 * k + 2]);
          }
        },
        [](char) {});
  }
  keep_uncovered(packing, std::move(darts), cell_of, active.size());
  struct Kept {
    std::vector<Cell> next, parked;
  };
  const auto fill = [&](std::size_t from, std::size_t to, Kept& kept) {
    DiskId last = kNoDisk;
    for (std::size_t a = from; a < to; ++a) {
      const Cell& c = active[a];
      if (covered_by_one(packing, cells, c, last)) continue;
      if (c.level == kDeepestLevel || cells.longest(c) > side) {
        kept.parked.push_back(c);
        continue;
      }
      for (const Cell& k : Cells::children(c))
        if (!covered_by_one(packing, cells, k, last)) kept.next.push_back(k);
    }
  };
  std::vector<Cell> next;
  detail::ordered_chunks<Kept>(active.size(), detail::thread_count(0), fill, [&](const Kept& kept) {
    next.insert(next.end(), kept.next.begin(), kept.next.end());
    parked.insert(parked.end(), kept.parked.begin(), kept.parked.end());
  });
  active.swap(next);
}

bool has_void(const SurfacePacking& packing, const Cells& cells, const Cell& c, std::vector<SurfaceVoidPoint>& found) {
  found.clear();
  void_points_in_cell(packing, c.triangle, cells.corners(c), found);
  return !found.empty();
}

// A point of the uncovered part of cell c (which has one): darts into the cell, and
// when they all miss, the same in a child holding some of the void, down to cells a
// millionth of the smallest radius across. Only a void thinner than that gets one of
// its vertices.
SurfacePoint point_in_void(const SurfacePacking& packing, const Cells& cells, const Cell& c, double smallest,
                           Rng& rng) {
  for (int k = 0; k < 16; ++k) {
    const SurfacePoint q = cells.dart(c, rng);
    if (!packing.covered(q)) return q;
  }
  std::vector<SurfaceVoidPoint> found;
  if (c.level < kDeepestLevel && cells.longest(c) > 1e-6 * smallest) {
    std::array<Cell, 4> children = Cells::children(c);
    for (std::size_t i = children.size(); i > 1; --i) std::swap(children[i - 1], children[uniform_index(rng, i)]);
    for (const Cell& k : children)
      if (has_void(packing, cells, k, found)) return point_in_void(packing, cells, k, smallest, rng);
  }
  has_void(packing, cells, c, found);
  return found.empty() ? cells.dart(c, rng) : found.front().at;
}

// A uniform point of the void next to void point v of triangle t: darts into ever smaller
// squares around v in the triangle's plane; v itself only for a void thinner than a
// millionth of r.
SurfacePoint point_near(const SurfacePacking& packing, const SurfaceVoidPoint& v, Rng& rng) {
  const TrianglePlane& plane = packing.index().plane(v.at.triangle);
  const Vec2 x = plane.to_plane(v.at.p);
  const double r = packing.radius_at(v.at);
  for (double half = r / 4; half > 1e-6 * r; half /= 4) {
    for (int k = 0; k < 16; ++k) {
      const Vec2 z = x + Vec2{(2 * uniform01(rng) - 1) * half, (2 * uniform01(rng) - 1) * half};
      if (!plane.contains(z, 0)) continue;
      const Vec3 p = plane.to_space(z);
      if (!packing.covered({p, v.at.triangle})) return {p, v.at.triangle};
    }
  }
  return v.at;
}

// The voids of a sliver cell longer than the radius: each of its void points, and those
// each new disk makes on its circle, gets a disk near it until none is left (a disk
// covers only part of such a cell, and searching the whole cell again after each
// would cost its length squared).
void fill_sliver(SurfacePacking& packing, const Cells& cells, const Cell& c, Rng& rng) {
  std::vector<SurfaceVoidPoint> work;
  void_points_in_cell(packing, c.triangle, cells.corners(c), work);
  for (std::size_t i = work.size(); i > 1; --i) std::swap(work[i - 1], work[uniform_index(rng, i)]);
  while (!work.empty()) {
    const SurfaceVoidPoint v = work.back();
    work.pop_back();
    if (packing.conflicts(v.at)) continue;  // covered since
    const SurfacePoint q = point_near(packing, v, rng);
    if (packing.conflicts(q)) continue;
    const DiskId id = packing.insert(q);
    const std::size_t first = work.size();
    void_points_near(packing, q.p, packing.radius(id) * (1 + 1e-6), {}, work);
    for (std::size_t i = work.size(); i > first + 1; --i) std::swap(work[i - 1], work[first + uniform_index(rng, i - first)]);
  }
}

}  // namespace

SurfacePacking detail::sample_mps_unchecked(std::shared_ptr<const SurfaceDomain> domain,
                                            const SurfaceSizing& sizing, Rng& rng) {
  SurfacePacking packing(std::move(domain), sizing);
  sample_corners(packing);
  lay_out_curves(packing, rng);
  sample_curves(packing, rng);
  // Darts by area over the whole surface, as many as the count at area fraction 1 (an
  // MPS reaches about half of it); then cells small enough that a disk centered in one
  // covers it, split level by level around what is left.
  const std::size_t darts = static_cast<std::size_t>(density_unit(packing)) + 16;
  for (std::size_t k = 0; k < darts; ++k) {
    const double u1 = uniform01(rng), u2 = uniform01(rng), u3 = uniform01(rng);
    const SurfacePoint q = packing.index().point_by_area(u1, u2, u3);
    if (!packing.covered(q)) packing.insert(q);
  }
  const Cells cells(packing.domain());
  const double smallest = sizing.min_radius();
  std::vector<Cell> active;
  const double side = smallest * (1 - 1e-9);
  uncovered_cells(packing, cells, side, active);
  std::vector<Cell> parked;
  for (int level = 0; level < 6 && !active.empty(); ++level) dart_level(packing, cells, side, active, parked, rng);
  active.insert(active.end(), parked.begin(), parked.end());
  // What the darts left: each cell still holding a void gets a disk centered at a
  // uniform point of that void, which, within the cell, covers all of it; a sliver
  // longer than the radius gets disks until no void is left.
  for (std::size_t i = active.size(); i > 1; --i) std::swap(active[i - 1], active[uniform_index(rng, i)]);
  // Which cells hold a void now, on every core: a disk added below only shrinks voids,
  // so a cell without one is passed over as the loop would pass it.
  std::vector<char> holed(active.size(), 1);
  detail::ordered_chunks<std::vector<SurfaceVoidPoint>>(
      active.size(), detail::thread_count(0),
      [&](std::size_t from, std::size_t to, std::vector<SurfaceVoidPoint>& found) {
        for (std::size_t k = from; k < to; ++k)
          if (cells.longest(active[k]) <= side)
            holed[k] = has_void(packing, cells, active[k], found);
      },
      [](const std::vector<SurfaceVoidPoint>&) {});
  std::vector<SurfaceVoidPoint> found;
  for (std::size_t k = 0; k < active.size(); ++k) {
    const Cell& c = active[k];
    if (cells.longest(c) > side) {
      fill_sliver(packing, cells, c, rng);
    } else if (holed[k] && has_void(packing, cells, c, found)) {
      const SurfacePoint q = point_in_void(packing, cells, c, smallest, rng);
      if (!packing.conflicts(q)) packing.insert(q);
    }
  }
  packing.order_by_place();  // the darts' order is random over the surface
  return packing;
}

SurfacePacking sample_mps(std::shared_ptr<const SurfaceDomain> domain, const SurfaceSizing& sizing,
                          Rng& rng) {
  SurfacePacking packing = detail::sample_mps_unchecked(std::move(domain), sizing, rng);
  detail::check_sample(packing);
  return packing;
}

}  // namespace disktune
