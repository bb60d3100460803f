// SPDX-License-Identifier: GPL-3.0-or-later
#include "disktune/quality.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

#include "disktune/density.h"
#include "disktune/errors.h"
#include "disktune/tolerance.h"
#include "disktune/voids.h"
#include "mesh_shape.h"

namespace disktune {
namespace {

using detail::add;
using detail::make_histogram;
using detail::statistics;

// Angles this close to a threshold (degrees) count as on it: a square lattice's right
// angles are not obtuse, an angle of 70 - 1e-14 is within [50, 70].
constexpr double kAngleTolDeg = 1e-9;
constexpr double kBinSnap = 1e-9;
constexpr double kInf = std::numeric_limits<double>::infinity();

/// The angle at corner a of triangle (a, b, c), in degrees.
double angle_at(Vec2 a, Vec2 b, Vec2 c) {
  const Vec2 u = b - a, v = c - a;
  return detail::corner_angle_deg(std::abs(cross(u, v)), dot(u, v));
}

QualityReport::Edges edge_statistics(const std::vector<double>& lengths_over_r) {
  QualityReport::Edges E;
  E.histogram = make_histogram(0, 0.01, 300);
  E.min_over_r = lengths_over_r.empty() ? 0 : kInf;
  for (const double l : lengths_over_r) {
    E.min_over_r = std::min(E.min_over_r, l);
    E.max_over_r = std::max(E.max_over_r, l);
    add(E.histogram, l);
  }
  return E;
}

QualityReport::LocalBeta beta_statistics(const std::vector<double>& betas) {
  QualityReport::LocalBeta B;
  B.histogram = make_histogram(0, 0.01, 200);
  for (const double b : betas) add(B.histogram, b);
  const Statistics st = statistics(betas);
  B.min = st.min;
  B.mean = st.mean;
  B.max = st.max;
  return B;
}

/// Each triangle's angles (atan2 form) and circumradius, in the plane.
std::vector<detail::TriangleShape> planar_shapes(
    const std::vector<Vec2>& vertices, const std::vector<std::array<std::uint32_t, 3>>& triangles) {
  std::vector<detail::TriangleShape> out;
  out.reserve(triangles.size());
  for (const auto& t : triangles) {
    const Vec2 p[3] = {vertices[t[0]], vertices[t[1]], vertices[t[2]]};
    detail::TriangleShape s;
    for (int k = 0; k < 3; ++k) s.angles_deg[k] = angle_at(p[k], p[(k + 1) % 3], p[(k + 2) % 3]);
    s.circumradius = distance(circumcenter(p[0], p[1], p[2]), p[0]);
    out.push_back(s);
  }
  return out;
}

void check_mesh_of(const Packing& packing, const TriangleMesh& mesh) {
  if (packing.empty()) throw InvalidInput("cannot measure an empty packing: it has no disks");
  bool ok = mesh.disk_count == packing.size() && mesh.vertex_disk.size() == mesh.vertices.size() &&
            mesh.vertex_offset.size() == mesh.vertices.size();
  for (std::size_t v = 0; ok && v < mesh.vertex_disk.size(); ++v)
    ok = packing.alive(mesh.vertex_disk[v]);
  for (std::size_t t = 0; ok && t < mesh.triangles.size(); ++t) {
    for (std::uint32_t v : mesh.triangles[t]) ok = ok && v < mesh.vertices.size();
  }
  if (!ok) {
    throw InvalidInput(
        "measure_quality: the mesh is not the packing's (build it with "
        "periodic_delaunay from the same packing)");
  }
}

void check_uniform_radius(const Packing& packing, double r) {
  for (const DiskId id : packing.ids()) {
    if (std::abs(packing.radius(id) - r) > kRelTol * r) {
      std::ostringstream msg;
      msg << "measure_quality: disk " << id << " has radius " << packing.radius(id)
          << ", not r = " << r << "; the report is for packings of one radius";
      throw InvalidInput(msg.str());
    }
  }
}

}  // namespace

namespace detail {

Histogram make_histogram(double lo, double bin_width, std::size_t bins) {
  Histogram h;
  h.lo = lo;
  h.bin_width = bin_width;
  h.counts.assign(bins, 0);
  return h;
}

void add(Histogram& h, double v) {
  const double k = std::floor((v - h.lo) / h.bin_width + kBinSnap);
  if (k >= static_cast<double>(h.counts.size())) {
    ++h.overflow;
  } else {
    ++h.counts[static_cast<std::size_t>(std::max(k, 0.0))];
  }
}

Statistics statistics(const std::vector<double>& values) {
  Statistics s;
  if (values.empty()) return s;
  s.min = *std::min_element(values.begin(), values.end());
  s.max = *std::max_element(values.begin(), values.end());
  double sum = 0;
  for (double v : values) sum += v;
  s.mean = sum / static_cast<double>(values.size());
  double var = 0;
  for (double v : values) var += (v - s.mean) * (v - s.mean);
  s.stddev = std::sqrt(var / static_cast<double>(values.size()));
  return s;
}


QualityReport::Angles angle_statistics(const std::vector<TriangleShape>& shapes) {
  if (shapes.empty()) throw InvalidInput("cannot measure the angles of a mesh without triangles");
  QualityReport::Angles A;
  A.histogram = make_histogram(0, 1, 180);
  A.min = kInf;
  std::size_t in_50_70 = 0, obtuse = 0;
  double abs_dev_sum = 0;
  for (const TriangleShape& t : shapes) {
    double largest = 0;
    for (const double deg : t.angles_deg) {
      add(A.histogram, deg);
      A.min = std::min(A.min, deg);
      A.max = std::max(A.max, deg);
      largest = std::max(largest, deg);
      abs_dev_sum += std::abs(deg - 60);
      if (deg >= 50 - kAngleTolDeg && deg <= 70 + kAngleTolDeg) ++in_50_70;
    }
    if (largest > 90 + kAngleTolDeg) ++obtuse;
  }
  const double angle_count = 3.0 * static_cast<double>(shapes.size());
  A.mean_abs_dev_60 = abs_dev_sum / angle_count;
  A.fraction_50_70 = static_cast<double>(in_50_70) / angle_count;
  A.fraction_obtuse_triangles = static_cast<double>(obtuse) / static_cast<double>(shapes.size());
  return A;
}

MeshShape measure_mesh_shape(std::size_t vertex_count,
                             const std::vector<std::array<std::uint32_t, 3>>& triangles,
                             const std::vector<TriangleShape>& shapes,
                             const std::function<double(std::uint32_t, std::uint32_t)>& edge_length,
                             const std::vector<double>& vertex_radius) {
  MeshShape m;
  m.angles = angle_statistics(shapes);
  // Each edge with the number of triangles on it: one triangle means a boundary edge.
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edge_uses;
  std::vector<double> outradius(vertex_count, 0), nearest(vertex_count, kInf);
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const auto& t = triangles[i];
    for (int k = 0; k < 3; ++k) {
      outradius[t[k]] = std::max(outradius[t[k]], shapes[i].circumradius);
      ++edge_uses[std::minmax(t[k], t[(k + 1) % 3])];
    }
  }
  std::vector<bool> on_boundary(vertex_count, false);
  std::vector<double> lengths_over_r;
  for (const auto& [e, uses] : edge_uses) {
    const double len = edge_length(e.first, e.second);
    lengths_over_r.push_back(2 * len / (vertex_radius[e.first] + vertex_radius[e.second]));
    for (const std::uint32_t v : {e.first, e.second}) {
      nearest[v] = std::min(nearest[v], len);
      if (uses == 1) on_boundary[v] = true;
    }
  }
  m.edges = edge_statistics(lengths_over_r);
  std::vector<double> betas;
  for (std::size_t v = 0; v < vertex_count; ++v) {
    if (!on_boundary[v] && outradius[v] > 0) betas.push_back(outradius[v] / nearest[v]);
  }
  m.interior_vertex_count = betas.size();
  m.local_beta = beta_statistics(betas);
  return m;
}

}  // namespace detail

QualityReport::Angles measure_angles(const std::vector<Vec2>& vertices,
                                     const std::vector<std::array<std::uint32_t, 3>>& triangles) {
  return detail::angle_statistics(planar_shapes(vertices, triangles));
}

PlanarMeshQuality measure_planar_mesh(const PlanarMesh& mesh, double r) {
  return measure_planar_mesh(mesh, std::vector<double>(mesh.vertices.size(), r));
}

PlanarMeshQuality measure_planar_mesh(const PlanarMesh& mesh, const std::vector<double>& vertex_radius) {
  const auto length = [&](std::uint32_t a, std::uint32_t b) {
    return distance(mesh.vertices[a], mesh.vertices[b]);
  };
  return detail::mesh_quality<PlanarMeshQuality>(
      mesh.vertices.size(), mesh.triangles.size(),
      detail::measure_mesh_shape(mesh.vertices.size(), mesh.triangles,
                                 planar_shapes(mesh.vertices, mesh.triangles), length, vertex_radius));
}

QualityReport measure_quality(const Packing& packing, const TriangleMesh& mesh, double r) {
  check_mesh_of(packing, mesh);
  check_uniform_radius(packing, r);
  QualityReport q;
  q.radius = r;
  q.width = packing.frame().extent.x;
  q.height = packing.frame().extent.y;
  q.count = packing.size();
  q.triangle_count = mesh.triangles.size();
  q.area_fraction = area_fraction(q.count, r, q.width * q.height);
  q.relative_radius = relative_radius(q.count, r, q.width * q.height);

  // Exact checks through the packing itself, apart from the mesh.
  q.maximal = is_maximal(packing);
  q.conflict_free = is_conflict_free(packing);

  // Per disk: Voronoi outradius (largest circumradius around it), nearest-neighbour
  // distance (shortest incident edge) and cell area.
  const std::size_t ids = packing.id_bound();
  std::vector<double> outradius(ids, 0), nearest(ids, kInf), cell_area(ids, 0);

  q.angles = measure_angles(mesh.vertices, mesh.triangles);
  double max_circumradius = 0;
  for (const auto& t : mesh.triangles) {
    const Vec2 p[3] = {mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]};
    // The circumcenter is the Voronoi vertex the three cells share; it is at the
    // circumradius from each corner. Each corner's share of the triangle is its
    // quadrilateral (corner, edge midpoint, circumcenter, edge midpoint), signed, so
    // the shares add up to the Voronoi cell even when the circumcenter lies outside.
    const Vec2 o = circumcenter(p[0], p[1], p[2]);
    const double rho = distance(o, p[0]);
    max_circumradius = std::max(max_circumradius, rho);
    for (int k = 0; k < 3; ++k) {
      const DiskId d = mesh.vertex_disk[t[k]];
      outradius[d] = std::max(outradius[d], rho);
      const Vec2 a = p[k], next = (a + p[(k + 1) % 3]) * 0.5, prev = (a + p[(k + 2) % 3]) * 0.5;
      cell_area[d] += 0.5 * (cross(next - a, o - a) + cross(o - a, prev - a));
    }
  }
  q.max_coverage_over_r = max_circumradius / r;

  const auto edges = unique_edges(mesh);
  q.edge_count = edges.size();
  std::vector<double> lengths_over_r;
  for (const auto& e : edges) {
    const double len = distance(mesh.vertices[e[0]], mesh.vertices[e[1]]);
    lengths_over_r.push_back(len / r);
    for (const std::uint32_t v : e) {
      nearest[mesh.vertex_disk[v]] = std::min(nearest[mesh.vertex_disk[v]], len);
    }
  }
  q.edges = edge_statistics(lengths_over_r);
  // The nearest other center of any disk is a Delaunay neighbour.
  q.min_distance_over_r = q.edges.min_over_r;

  std::vector<double> betas, aspects, areas;
  for (const DiskId id : packing.ids()) {
    const double beta = outradius[id] / nearest[id];
    betas.push_back(beta);
    aspects.push_back(2 * beta);  // the cell's inradius about its site is nearest / 2
    areas.push_back(cell_area[id]);
  }
  q.local_beta = beta_statistics(betas);
  q.voronoi.aspect_ratio = statistics(aspects);
  q.voronoi.cell_area = statistics(areas);
  q.order = bond_order(packing);
  q.voronoi.cell_area_cv = q.voronoi.cell_area.stddev / q.voronoi.cell_area.mean;
  return q;
}

PlanarQualityReport measure_planar_quality(const Packing& packing, const PlanarMesh& mesh, double area) {
  if (packing.empty()) throw InvalidInput("cannot measure an empty packing: it has no disks");
  PlanarQualityReport q;
  q.radius = packing.sizing() ? 0 : packing.max_radius();
  q.area = area;
  q.count = packing.size();
  q.area_fraction = static_cast<double>(q.count) / density_unit(packing, area);
  q.relative_radius = relative_radius_for(q.area_fraction);
  q.maximal = is_maximal(packing);
  q.conflict_free = is_conflict_free(packing);
  // The nearest pair need not be a mesh edge (a constraint may cut it): ask the grid.
  q.min_distance_over_r = kInf;
  for (const DiskId id : packing.ids()) {
    if (packing.flags(id) & kFixed) ++q.boundary_count;
    const double r = packing.radius(id);
    packing.for_each_near(packing.center(id), 2 * packing.max_radius(), [&](const Neighbor& n) {
      if (n.id != id) q.min_distance_over_r = std::min(q.min_distance_over_r, std::sqrt(n.d2) / std::min(r, n.radius));
    });
  }
  std::vector<double> vertex_radius;
  for (const DiskId d : mesh.vertex_disk) vertex_radius.push_back(d == kNoDisk ? 0 : packing.radius(d));
  q.all = measure_planar_mesh(mesh, vertex_radius);
  PlanarMesh interior{mesh.vertices, mesh.vertex_disk, {}}, boundary = interior;
  for (const auto& t : mesh.triangles) {
    const bool on_boundary = std::any_of(t.begin(), t.end(), [&](std::uint32_t v) {
      return mesh.vertex_disk[v] != kNoDisk && (packing.flags(mesh.vertex_disk[v]) & kFixed);
    });
    (on_boundary ? boundary : interior).triangles.push_back(t);
  }
  if (!interior.triangles.empty()) q.interior = measure_planar_mesh(interior, vertex_radius);
  if (!boundary.triangles.empty()) q.boundary = measure_planar_mesh(boundary, vertex_radius);
  q.order = bond_order(packing);
  return q;
}

}  // namespace disktune
