// SPDX-License-Identifier: GPL-3.0-or-later
// Maximal Poisson-disk sampling on a surface, unbiased as Ebeida et al.'s sampler of the
// box is: the open boundary curves first (1D darts into the uncovered parts of the
// boundary edges, as fixed disks), then darts by area over the surface and over ever
// smaller cells around the uncovered part, then each remaining void gets a disk at a
// uniform point of it (never at its vertices, which would bias the spacing).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "disktune/errors.h"
#include "disktune/surface_sampling.h"
#include "disktune/surface_voids.h"
#include "disktune/tolerance.h"
#include "../voids/final_check.h"

namespace disktune {
namespace {

void sample_boundary(SurfacePacking& packing, Rng& rng) {
  const SurfaceDomain& d = packing.domain();
  if (d.is_closed()) return;
  // The gaps of each boundary edge, in loop and edge order, measured once; a new disk
  // changes only those of the edges it reaches.
  struct Edge {
    std::size_t loop, edge;
    Vec3 a, b;
    std::vector<BoundaryGap> gaps;
  };
  std::vector<Edge> edges;
  for (std::size_t l = 0; l < d.boundary_loops().size(); ++l) {
    const auto& loop = d.boundary_loops()[l];
    for (std::size_t e = 0; e < loop.size(); ++e) {
      edges.push_back({l, e, d.vertices()[loop[e]], d.vertices()[loop[(e + 1) % loop.size()]], {}});
      uncovered_on_boundary_edge(packing, l, e, true, edges.back().gaps);
    }
  }
  std::vector<double> cumulative;
  std::vector<const BoundaryGap*> gaps;
  for (;;) {
    // A dart uniform over the uncovered length.
    cumulative.clear();
    gaps.clear();
    double total = 0;
    for (const Edge& e : edges) {
      for (const BoundaryGap& g : e.gaps) {
        total += (g.t1 - g.t0) * norm(e.b - e.a);
        cumulative.push_back(total);
        gaps.push_back(&g);
      }
    }
    if (gaps.empty()) return;
    const std::size_t k = std::min<std::size_t>(
        std::upper_bound(cumulative.begin(), cumulative.end(), uniform01(rng) * total) - cumulative.begin(),
        gaps.size() - 1);
    const BoundaryGap g = *gaps[k];
    const DiskId id =
        packing.insert(packing.index().on_boundary(g.loop, g.edge, g.t0 + (g.t1 - g.t0) * uniform01(rng)), kFixed);
    // The new disk covers one interval of each edge it reaches: cut it out of the gaps
    // there (measuring such an edge again would cost its length over r per disk).
    for (Edge& e : edges) {
      const auto in = segment_in_ball(e.a, e.b, packing.center(id), packing.radius(id) * (1 + kRelTol));
      if (!in) continue;
      std::vector<BoundaryGap> left;
      for (const BoundaryGap& g : e.gaps) {
        if (g.t1 <= (*in)[0] || g.t0 >= (*in)[1]) {
          left.push_back(g);
          continue;
        }
        if (g.t0 < (*in)[0]) left.push_back({g.loop, g.edge, g.t0, (*in)[0]});
        if ((*in)[1] < g.t1) left.push_back({g.loop, g.edge, (*in)[1], g.t1});
      }
      e.gaps.swap(left);
    }
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
  double area(const Cell& c) const { return std::ldexp(area_[c.triangle], -2 * c.level); }
  double longest(const Cell& c) const { return std::ldexp(longest_[c.triangle], -c.level); }
  std::array<Vec3, 3> corners(const Cell& c) const {
    const auto& t = domain_.triangles()[c.triangle];
    const Vec3 a = domain_.vertices()[t[0]], b = domain_.vertices()[t[1]], d = domain_.vertices()[t[2]];
    const auto at = [&](std::uint32_t i, std::uint32_t j) {
      return a + (b - a) * std::ldexp(double(i), -c.level) + (d - a) * std::ldexp(double(j), -c.level);
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
    const auto p = corners(c);
    double s = uniform01(rng), w = uniform01(rng);
    if (s + w > 1) s = 1 - s, w = 1 - w;
    return {p[0] + (p[1] - p[0]) * s + (p[2] - p[0]) * w, c.triangle};
  }

 private:
  const SurfaceDomain& domain_;
  std::vector<double> area_, longest_;
};

// True when one disk holds all three corners of the cell, so all of it (a ball is convex).
bool covered_by_one(const SurfacePacking& packing, const std::array<Vec3, 3>& p) {
  const Vec3 middle = (p[0] + p[1] + p[2]) * (1.0 / 3);
  return packing.any_near(middle, packing.max_radius(), [&](DiskId id) {
    const Vec3 c = packing.center(id);
    const double r2 = packing.radius(id) * packing.radius(id);
    return squared_norm(p[0] - c) <= r2 && squared_norm(p[1] - c) <= r2 && squared_norm(p[2] - c) <= r2;
  });
}

// The cells of at most `side` (longest edge) that no disk covers alone, coarse cells that
// one disk covers dropped whole.
void uncovered_cells(const SurfacePacking& packing, const Cells& cells, double side, std::vector<Cell>& out) {
  std::vector<Cell> stack;
  for (std::uint32_t t = 0; t < packing.domain().triangles().size(); ++t) {
    stack.push_back({t, 0, 0, 0, true});
    while (!stack.empty()) {
      const Cell c = stack.back();
      stack.pop_back();
      if (covered_by_one(packing, cells.corners(c))) continue;
      if (cells.longest(c) <= side || c.level == kDeepestLevel) {
        out.push_back(c);
      } else {
        for (const Cell& k : Cells::children(c)) stack.push_back(k);
      }
    }
  }
}

// Darts by area into the cells, as many as there are cells; then the cells that one
// disk now covers are dropped and the others split in four (children one disk covers
// dropped too). Every accepted dart is uniform over the uncovered area, because the
// cells hold all of it.
void dart_level(SurfacePacking& packing, const Cells& cells, std::vector<Cell>& active, Rng& rng) {
  std::vector<double> cumulative;
  cumulative.reserve(active.size());
  double total = 0;
  for (const Cell& c : active) cumulative.push_back(total += cells.area(c));
  for (std::size_t k = 0; k < active.size(); ++k) {
    const std::size_t at = std::min<std::size_t>(
        std::upper_bound(cumulative.begin(), cumulative.end(), uniform01(rng) * total) - cumulative.begin(),
        active.size() - 1);
    const SurfacePoint q = cells.dart(active[at], rng);
    if (!packing.covered(q.p)) packing.insert(q);
  }
  std::vector<Cell> next;
  for (const Cell& c : active) {
    if (covered_by_one(packing, cells.corners(c))) continue;
    if (c.level == kDeepestLevel) {
      next.push_back(c);
      continue;
    }
    for (const Cell& k : Cells::children(c))
      if (!covered_by_one(packing, cells.corners(k))) next.push_back(k);
  }
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
    if (!packing.covered(q.p)) return q;
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

}  // namespace

SurfacePacking sample_mps(std::shared_ptr<const SurfaceDomain> domain, const SurfaceSizing& sizing, Rng& rng) {
  SurfacePacking packing(std::move(domain), sizing);
  sample_boundary(packing, rng);
  // Darts by area over the whole surface, as many as the count at area fraction 1 (an
  // MPS reaches about half of it); then cells small enough that a disk centered in one
  // covers it, split level by level around what is left.
  const std::size_t darts = static_cast<std::size_t>(density_unit(packing)) + 16;
  for (std::size_t k = 0; k < darts; ++k) {
    const double u1 = uniform01(rng), u2 = uniform01(rng), u3 = uniform01(rng);
    const SurfacePoint q = packing.index().point_by_area(u1, u2, u3);
    if (!packing.covered(q.p)) packing.insert(q);
  }
  const Cells cells(packing.domain());
  const double smallest = sizing.min_radius();
  std::vector<Cell> active;
  uncovered_cells(packing, cells, smallest * (1 - 1e-9), active);
  for (int level = 0; level < 6 && !active.empty(); ++level) dart_level(packing, cells, active, rng);
  // What the darts left: each cell still holding a void gets one disk, centered at a
  // uniform point of that void; being within the cell, it covers all of the cell.
  for (std::size_t i = active.size(); i > 1; --i) std::swap(active[i - 1], active[uniform_index(rng, i)]);
  std::vector<SurfaceVoidPoint> found;
  for (const Cell& c : active) {
    if (!has_void(packing, cells, c, found)) continue;
    const SurfacePoint q = point_in_void(packing, cells, c, smallest, rng);
    if (!packing.conflicts(q.p)) packing.insert(q);
  }
  detail::check_sample(packing);
  return packing;
}

}  // namespace disktune
