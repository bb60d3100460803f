// SPDX-License-Identifier: GPL-3.0-or-later
// The periodic Delaunay triangulation by replication: the centers and their periodic
// copies within a margin of the box are triangulated with CGAL's
// Delaunay_triangulation_2, and each torus triangle is kept once, as the copy whose
// centroid lies in the box. (CGAL 5.5's Periodic_2_Delaunay_triangulation_2 requires a
// square domain, a precondition of its constructor, so it cannot serve a W x H box.)
//
// Two facts make the copies agree with each other, which keeping "one copy per torus
// triangle" needs:
// - every copy is an exact translate: the centers are snapped to integers in units of
//   a power of two, so adding a multiple of the (snapped) box side is exact;
// - the exact predicates decide every in-circle test, and CGAL breaks cocircular ties
//   by a symbolic perturbation that depends on the lexicographic order of the points,
//   which a translation does not change. Two copies of a cocircular cell (every cell of
//   a lattice) are therefore triangulated alike.
// One of the few CGAL translation units of the library: each costs ~40 s to compile.
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "disktune/errors.h"
#include "disktune/mesh.h"

namespace disktune {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase>;
using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, Tds>;

/// A periodic copy of a disk center; positions in grid units (exact integers).
struct Copy {
  std::int64_t x, y;
  std::uint32_t disk;  // index into the live ids
  std::int32_t ox, oy;
};

/// The copies of all centers within `margin` of the box, on a grid fine enough that
/// every coordinate is an integer below 2^52 units (so sums of three fit an int64 and
/// every coordinate and difference is an exact double).
struct Replica {
  double unit = 1;            // grid spacing
  std::int64_t w = 0, h = 0;  // the box sides in units
  std::vector<Copy> copies;   // copies[k] for k < disk count: the disks themselves
};

Replica replicate(const Packing& packing, const std::vector<DiskId>& ids, double margin) {
  const Frame& frame = packing.frame();
  const double W = frame.extent.x, H = frame.extent.y;
  Replica rep;
  rep.unit = std::ldexp(1.0, std::ilogb(std::max(W, H) + 2 * margin) + 1 - 52);
  rep.w = std::llround(W / rep.unit);
  rep.h = std::llround(H / rep.unit);
  const std::int64_t m = std::llround(margin / rep.unit);
  const int kx = static_cast<int>(std::ceil(margin / W)) + 1;
  const int ky = static_cast<int>(std::ceil(margin / H)) + 1;
  std::vector<std::pair<std::int64_t, std::int64_t>> home(ids.size());
  for (std::size_t i = 0; i < ids.size(); ++i) {
    const Vec2 c = packing.center(ids[i]) - frame.origin;
    home[i] = {std::llround(c.x / rep.unit), std::llround(c.y / rep.unit)};
    rep.copies.push_back({home[i].first, home[i].second, static_cast<std::uint32_t>(i), 0, 0});
  }
  for (std::size_t i = 0; i < ids.size(); ++i) {
    for (int oy = -ky; oy <= ky; ++oy) {
      const std::int64_t y = home[i].second + oy * rep.h;
      if (y < -m || y > rep.h + m) continue;
      for (int ox = -kx; ox <= kx; ++ox) {
        const std::int64_t x = home[i].first + ox * rep.w;
        if ((ox == 0 && oy == 0) || x < -m || x > rep.w + m) continue;
        rep.copies.push_back({x, y, static_cast<std::uint32_t>(i), ox, oy});
      }
    }
  }
  return rep;
}

[[noreturn]] void throw_coinciding(const Replica& rep, const Packing& packing,
                                   const std::vector<DiskId>& ids) {
  std::vector<std::size_t> order(rep.copies.size());
  std::iota(order.begin(), order.end(), 0);
  auto key = [&](std::size_t k) { return std::make_pair(rep.copies[k].x, rep.copies[k].y); };
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return key(a) < key(b); });
  for (std::size_t k = 1; k < order.size(); ++k) {
    if (key(order[k]) != key(order[k - 1])) continue;
    const DiskId a = ids[rep.copies[order[k - 1]].disk], b = ids[rep.copies[order[k]].disk];
    std::ostringstream msg;
    msg.precision(17);
    msg << "disks " << std::min(a, b) << " and " << std::max(a, b) << " coincide on the torus ("
        << packing.center(a).x << ", " << packing.center(a).y << ") and (" << packing.center(b).x
        << ", " << packing.center(b).y
        << "), closer than 1e-15 of the box: a triangulation needs distinct centers";
    throw InvalidInput(msg.str());
  }
  throw std::logic_error("periodic_delaunay: CGAL merged vertices that are not equal");
}

/// The margin this triangulation needs to be right near the box: each face that meets
/// the box must have its circumdisk inside the replicated region (then no copy left out
/// could lie in it), and no face meeting the box may be infinite. Faces meeting the box
/// cover it, so then every torus triangle's copy with its centroid in the box is there.
double needed_margin(const Delaunay& dt, const Replica& rep, double margin) {
  if (dt.dimension() < 2) return 2 * margin;
  const double w = static_cast<double>(rep.w), h = static_cast<double>(rep.h);
  auto meets_box = [&](double x0, double x1, double y0, double y1) {
    return x1 >= 0 && x0 <= w && y1 >= 0 && y0 <= h;
  };
  double needed = 0;
  for (auto f = dt.all_faces_begin(); f != dt.all_faces_end(); ++f) {
    if (dt.is_infinite(f)) {
      const int i = f->index(dt.infinite_vertex());
      const auto& p = f->vertex((i + 1) % 3)->point();
      const auto& q = f->vertex((i + 2) % 3)->point();
      if (meets_box(std::min(p.x(), q.x()), std::max(p.x(), q.x()), std::min(p.y(), q.y()),
                    std::max(p.y(), q.y()))) {
        needed = std::max(needed, 2 * margin);  // the hull cuts the box: replicate farther
      }
      continue;
    }
    const auto& a = f->vertex(0)->point();
    const auto& b = f->vertex(1)->point();
    const auto& c = f->vertex(2)->point();
    if (!meets_box(std::min({a.x(), b.x(), c.x()}), std::max({a.x(), b.x(), c.x()}),
                   std::min({a.y(), b.y(), c.y()}), std::max({a.y(), b.y(), c.y()}))) {
      continue;
    }
    // Circumcircle relative to a (differences of integers below 2^53 are exact).
    const double bx = b.x() - a.x(), by = b.y() - a.y();
    const double cx = c.x() - a.x(), cy = c.y() - a.y();
    const double d = 2 * (bx * cy - by * cx);
    const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
    const double ux = (cy * b2 - by * c2) / d, uy = (bx * c2 - cx * b2) / d;
    const double rho = std::sqrt(ux * ux + uy * uy);
    const double ox = a.x() + ux, oy = a.y() + uy;
    const double reach = std::max({rho - ox, ox + rho - w, rho - oy, oy + rho - h});
    // Slack for the rounded circumcircle: far above its error, far below any spacing.
    const double reach_with_slack = reach * rep.unit * (1 + 1e-6);
    if (reach_with_slack < margin) continue;
    // A sliver along the hull of the copies can round to an infinite circle: grow.
    needed =
        std::max(needed, std::isfinite(reach_with_slack) ? reach_with_slack * 1.01 : 2 * margin);
  }
  return needed;
}

TriangleMesh extract(const Delaunay& dt, const Replica& rep, const Packing& packing,
                     const std::vector<DiskId>& ids) {
  const Frame& frame = packing.frame();
  TriangleMesh mesh;
  mesh.disk_count = ids.size();
  mesh.period = frame.extent;
  for (const DiskId id : ids) {
    mesh.vertices.push_back(packing.center(id));
    mesh.vertex_disk.push_back(id);
    mesh.vertex_offset.push_back({0, 0});
  }
  constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> vertex_of_copy(rep.copies.size(), kNone);
  std::iota(vertex_of_copy.begin(), vertex_of_copy.begin() + ids.size(), 0u);
  auto vertex = [&](std::uint32_t k) {
    if (vertex_of_copy[k] == kNone) {
      const Copy& c = rep.copies[k];
      vertex_of_copy[k] = static_cast<std::uint32_t>(mesh.vertices.size());
      mesh.vertices.push_back(packing.center(ids[c.disk]) +
                              Vec2{c.ox * frame.extent.x, c.oy * frame.extent.y});
      mesh.vertex_disk.push_back(ids[c.disk]);
      mesh.vertex_offset.push_back({c.ox, c.oy});
    }
    return vertex_of_copy[k];
  };
  mesh.triangles.reserve(2 * ids.size());
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
    const std::uint32_t k0 = f->vertex(0)->info(), k1 = f->vertex(1)->info(),
                        k2 = f->vertex(2)->info();
    const Copy &a = rep.copies[k0], &b = rep.copies[k1], &c = rep.copies[k2];
    // The centroid in the half-open box, exactly: 0 <= x_a + x_b + x_c < 3w.
    const std::int64_t sx = a.x + b.x + c.x, sy = a.y + b.y + c.y;
    if (sx < 0 || sx >= 3 * rep.w || sy < 0 || sy >= 3 * rep.h) continue;
    mesh.triangles.push_back({vertex(k0), vertex(k1), vertex(k2)});
  }
  if (mesh.triangles.size() != 2 * ids.size()) {
    std::ostringstream msg;
    msg << "periodic_delaunay: " << mesh.triangles.size() << " triangles for " << ids.size()
        << " disks (a torus triangulation has twice as many)";
    throw std::logic_error(msg.str());
  }
  return mesh;
}

}  // namespace

TriangleMesh periodic_delaunay(const Packing& packing) {
  if (!packing.frame().periodic) {
    throw InvalidInput("periodic_delaunay: the packing's frame is not periodic");
  }
  const std::vector<DiskId> ids = packing.ids();
  if (ids.empty()) throw InvalidInput("cannot triangulate an empty packing: it has no disks");
  // In a maximal packing every empty circle has radius <= r, so a face meeting the box
  // reaches at most 2r beyond it: one pass. Sparser inputs grow the margin, at most
  // eightfold a round (a sliver along the hull of the copies can have a huge circle)
  // and never past what any input needs: no empty circle is wider than the diagonal,
  // since every point is within half of it from some image of any center.
  const Vec2 box = packing.frame().extent;
  const double enough = 1.01 * std::hypot(box.x, box.y);
  double margin = std::min(enough, 2.1 * packing.max_radius());
  for (int attempt = 0; attempt < 60; ++attempt) {
    const Replica rep = replicate(packing, ids, margin);
    std::vector<std::pair<Kernel::Point_2, std::uint32_t>> points;
    points.reserve(rep.copies.size());
    for (std::size_t k = 0; k < rep.copies.size(); ++k) {
      points.emplace_back(Kernel::Point_2(static_cast<double>(rep.copies[k].x),
                                          static_cast<double>(rep.copies[k].y)),
                          static_cast<std::uint32_t>(k));
    }
    const Delaunay dt(points.begin(), points.end());
    if (dt.number_of_vertices() != points.size()) throw_coinciding(rep, packing, ids);
    const double needed = needed_margin(dt, rep, margin);
    if (needed == 0) return extract(dt, rep, packing, ids);
    margin = std::min(enough, std::max(2 * margin, std::min(needed, 8 * margin)));
  }
  throw std::logic_error("periodic_delaunay: the replication margin did not converge");
}

}  // namespace disktune
