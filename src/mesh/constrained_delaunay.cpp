// SPDX-License-Identifier: GPL-3.0-or-later
// The constrained Delaunay triangulation of a packing in a domain bounded by loops of
// disks. CGAL builds the triangulation of all centers (range insertion: spatially
// sorted, fast for millions of points), then inserts each boundary segment as a
// constraint between existing vertices. The domain is found by nesting level: from
// the infinite face, every crossing of a constrained edge goes one level deeper, and
// odd levels are inside (inside the outer loop, outside the holes).
//
// Crossing constraints are refused, not resolved: with Exact_predicates_tag CGAL would
// insert their intersection point, a vertex that is no disk, so a vertex count that
// grows while constraints go in names the crossing.
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <cstdint>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "disktune/errors.h"
#include "disktune/mesh.h"

namespace disktune {
namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

/// A vertex's index into the live ids; kNone for a point CGAL made (a crossing).
struct VertexIndex {
  std::uint32_t index = kNone;
};
/// A face's nesting level; -1 until the flood reaches it.
struct FaceLevel {
  int level = -1;
};

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<VertexIndex, Kernel>;
using FaceInfoBase = CGAL::Triangulation_face_base_with_info_2<FaceLevel, Kernel>;
using FaceBase = CGAL::Constrained_triangulation_face_base_2<Kernel, FaceInfoBase>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;
using VertexHandle = Cdt::Vertex_handle;
using FaceHandle = Cdt::Face_handle;

std::string position(Vec2 p) {
  std::ostringstream s;
  s.precision(17);
  s << '(' << p.x << ", " << p.y << ')';
  return s.str();
}

/// Each loop long enough, each id alive and on one loop only.
void validate_loops(const Packing& packing, const std::vector<std::vector<DiskId>>& loops) {
  if (loops.empty()) {
    throw InvalidInput(
        "constrained_delaunay: no boundary loops given; pass at least the outer boundary "
        "as loop 0");
  }
  // Where each id was seen first: loop and position.
  std::vector<std::pair<std::size_t, std::size_t>> seen(packing.id_bound(), {kNone, kNone});
  for (std::size_t k = 0; k < loops.size(); ++k) {
    if (loops[k].size() < 3) {
      throw InvalidInput("constrained_delaunay: boundary loop " + std::to_string(k) + " has " +
                         std::to_string(loops[k].size()) +
                         " disks; a closed loop needs at least 3");
    }
    for (std::size_t i = 0; i < loops[k].size(); ++i) {
      const DiskId id = loops[k][i];
      if (!packing.alive(id)) {
        throw InvalidInput("constrained_delaunay: disk " + std::to_string(id) + " (loop " +
                           std::to_string(k) + ", position " + std::to_string(i) +
                           ") is not a live disk of the packing; list only live ids");
      }
      if (seen[id].first != kNone) {
        throw InvalidInput("constrained_delaunay: disk " + std::to_string(id) +
                           " appears twice on the boundary (loop " +
                           std::to_string(seen[id].first) + ", position " +
                           std::to_string(seen[id].second) + ", and loop " + std::to_string(k) +
                           ", position " + std::to_string(i) +
                           "); boundary loops must be simple and share no disk");
      }
      seen[id] = {k, i};
    }
  }
}

[[noreturn]] void throw_coinciding(const Packing& packing, const std::vector<DiskId>& ids,
                                   const std::vector<VertexHandle>& handle) {
  for (std::size_t i = 0; i < ids.size(); ++i) {
    if (handle[i] != VertexHandle()) continue;
    // Disk i lost its vertex to another disk at the same point.
    for (std::size_t j = 0; j < ids.size(); ++j) {
      if (j != i && packing.center(ids[j]) == packing.center(ids[i])) {
        throw InvalidInput("constrained_delaunay: disks " + std::to_string(ids[std::min(i, j)]) +
                           " and " + std::to_string(ids[std::max(i, j)]) +
                           " have the same center " + position(packing.center(ids[i])) +
                           "; a triangulation needs distinct centers");
      }
    }
  }
  throw std::logic_error("constrained_delaunay: CGAL merged vertices that are not equal");
}

[[noreturn]] void throw_crossing(const Cdt& cdt, std::size_t loop, DiskId a, DiskId b) {
  Vec2 at{0, 0};
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    if (v->info().index == kNone) at = {v->point().x(), v->point().y()};
  }
  throw InvalidInput("constrained_delaunay: boundary loops cross: the segment from disk " +
                     std::to_string(a) + " to disk " + std::to_string(b) + " of loop " +
                     std::to_string(loop) + " crosses an earlier boundary segment near " +
                     position(at) + "; boundary loops must not intersect");
}

/// Floods the faces level by level: a face gets the level of its neighbour across an
/// unconstrained edge, one more across a constrained one.
void mark_levels(Cdt& cdt) {
  std::vector<FaceHandle> seeds{cdt.infinite_face()}, next, stack;
  for (int level = 0; !seeds.empty(); ++level) {
    for (const FaceHandle seed : seeds) {
      if (seed->info().level != -1) continue;
      seed->info().level = level;
      stack.push_back(seed);
      while (!stack.empty()) {
        const FaceHandle f = stack.back();
        stack.pop_back();
        for (int i = 0; i < 3; ++i) {
          const FaceHandle g = f->neighbor(i);
          if (g->info().level != -1) continue;
          if (f->is_constrained(i)) {
            next.push_back(g);
          } else {
            g->info().level = level;
            stack.push_back(g);
          }
        }
      }
    }
    seeds.swap(next);
    next.clear();
  }
}

}  // namespace

PlanarMesh constrained_delaunay(const Packing& packing,
                                const std::vector<std::vector<DiskId>>& loops) {
  validate_loops(packing, loops);
  const std::vector<DiskId> ids = packing.ids();
  std::vector<std::uint32_t> index_of(packing.id_bound(), kNone);
  std::vector<std::pair<Kernel::Point_2, VertexIndex>> points;
  points.reserve(ids.size());
  for (std::size_t i = 0; i < ids.size(); ++i) {
    index_of[ids[i]] = static_cast<std::uint32_t>(i);
    const Vec2 c = packing.center(ids[i]);
    points.emplace_back(Kernel::Point_2(c.x, c.y), VertexIndex{static_cast<std::uint32_t>(i)});
  }

  Cdt cdt;
  cdt.insert(points.begin(), points.end());
  std::vector<VertexHandle> handle(ids.size());
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    handle[v->info().index] = v;
  }
  if (cdt.number_of_vertices() != ids.size()) throw_coinciding(packing, ids, handle);

  for (std::size_t k = 0; k < loops.size(); ++k) {
    const std::vector<DiskId>& loop = loops[k];
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const DiskId a = loop[i], b = loop[(i + 1) % loop.size()];
      cdt.insert_constraint(handle[index_of[a]], handle[index_of[b]]);
      if (cdt.number_of_vertices() != ids.size()) throw_crossing(cdt, k, a, b);
    }
  }
  // A segment through a third center is split there by CGAL: the boundary would then
  // run through a disk that is not on it.
  for (std::size_t k = 0; k < loops.size(); ++k) {
    const std::vector<DiskId>& loop = loops[k];
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const DiskId a = loop[i], b = loop[(i + 1) % loop.size()];
      if (cdt.is_edge(handle[index_of[a]], handle[index_of[b]])) continue;
      throw InvalidInput("constrained_delaunay: the boundary segment from disk " +
                         std::to_string(a) + " to disk " + std::to_string(b) + " of loop " +
                         std::to_string(k) +
                         " passes through the center of another disk or along another "
                         "segment; put that disk on the loop or move it off the boundary");
    }
  }

  PlanarMesh mesh;
  mesh.vertices.reserve(ids.size());
  mesh.vertex_disk = ids;
  for (const DiskId id : ids) mesh.vertices.push_back(packing.center(id));
  for (std::size_t k = 0; k < loops.size(); ++k) {
    for (std::size_t i = 0; i < loops[k].size(); ++i) {
      mesh.boundary_edges.push_back(
          {index_of[loops[k][i]], index_of[loops[k][(i + 1) % loops[k].size()]]});
      mesh.boundary_loop.push_back(static_cast<std::uint32_t>(k));
    }
  }
  if (cdt.dimension() < 2) return mesh;  // all centers on one line: no triangles
  mark_levels(cdt);
  mesh.triangles.reserve(2 * ids.size());
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (f->info().level % 2 == 0) continue;  // outside, or in a hole
    // CGAL's faces are counterclockwise.
    mesh.triangles.push_back(
        {f->vertex(0)->info().index, f->vertex(1)->info().index, f->vertex(2)->info().index});
  }
  return mesh;
}

}  // namespace disktune
