// SPDX-License-Identifier: GPL-3.0-or-later
// The fiber RVE's finite-element mesh through Gmsh's C API (rve_mesh.h; the library loaded
// on first use, gmsh_library.h). Gmsh builds
// the geometry with OpenCASCADE: the cell's rectangle fragmented by every fiber image
// that overlaps it, the pieces outside the cell dropped, the right and top sides
// declared periodic copies of the left and bottom, then 2D frontal-Delaunay meshing.
// The mesh is read back, its sides are checked to pair up node for node and snapped
// exactly onto the cell, and its shape measured. Gmsh works in units of the fiber
// diameter: OpenCASCADE's tolerances are absolute (1e-7), and fibers of 7e-6 m are common.
#include "disktune/rve_mesh.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "../analysis/mesh_shape.h"
#include "../io/number_text.h"
#include "disktune/errors.h"
#include "disktune/resources.h"
#include "gmsh_library.h"
#include "rve_polydisperse.h"

namespace disktune {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Bytes per triangle: Gmsh's model and mesh (about 600 measured at 5.5e5 triangles)
// and this file's copy.
constexpr double kBytesPerTriangle = 700;

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}

// Gmsh has one global model: one mesh at a time in the process, in a session that
// always ends (its destructor also runs when Gmsh throws).
std::mutex gmsh_mutex;
struct GmshSession {
  const detail::GmshApi& gmsh = detail::gmsh_api();
  GmshSession() {
    detail::gmsh_call(gmsh.initialize, 0, nullptr, 0);
    detail::gmsh_call(gmsh.set_number, "General.Terminal", 0.0);  // errors come back as flags
  }
  ~GmshSession() {
    int ignored = 0;
    gmsh.finalize(&ignored);
  }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
};

// The least distance over all fibers between a fiber boundary and the line of a side
// (x = 0 and x = W are one line on the torus): |distance of the center - d/2|.
double side_clearance(const Rve& rve) {
  const double w = rve.cell.width(), h = rve.cell.height();
  double least = std::min(w, h);
  for (std::size_t k = 0; k < rve.centers.size(); ++k) {
    const Vec2 c = rve.centers[k];
    const double radius = rve.diameters[k] / 2;
    least = std::min({least, std::abs(std::min(c.x, w - c.x) - radius), std::abs(std::min(c.y, h - c.y) - radius)});
  }
  return least;
}

double element_size_of(const RveMeshSpec& spec, double diameter) {
  return spec.element_size != 0
             ? spec.element_size
             : kPi * diameter / static_cast<double>(std::max<std::size_t>(spec.fiber_segments, 1));
}

// check_rve_mesh on the cell, diameter and gap of either an RveSpec or an Rve.
void check_spec(double width, double height, double d, double gap, const RveMeshSpec& spec) {
  if (!(gap >= 1e-3 * d)) {
    throw InvalidInput("rve mesh: the gap between fibers is " + number(gap) +
                       ", under a thousandth of the diameter: fibers that (nearly) touch leave no matrix "
                       "between them to mesh; make the gap at least " + number(1e-3 * d) + " (0.02 D is usual)");
  }
  if (spec.fiber_segments < 6 || spec.fiber_segments > 10000) {
    throw InvalidInput("rve mesh: " + std::to_string(spec.fiber_segments) +
                       " segments per fiber boundary; give between 6 and 10000");
  }
  const double element_size = element_size_of(spec, d);
  if (!(std::isfinite(element_size) && element_size >= 1e-3 * d)) {
    throw InvalidInput("rve mesh: the element size must be finite and at least a thousandth of the fiber diameter (" +
                       number(1e-3 * d) + "), got " + number(element_size));
  }
  // An equilateral triangle of edge s covers sqrt(3)/4 s^2; fiber boundaries and the
  // gaps between fibers add some: a third more.
  const double triangles = 1.33 * width * height / (0.4330127 * element_size * element_size);
  const double limit = spec.max_memory > 0 ? spec.max_memory : available_memory();
  if (triangles * kBytesPerTriangle > limit) {
    throw InvalidInput("rve mesh: about " + number(triangles) + " triangles need about " +
                           detail::short_text(triangles * kBytesPerTriangle / 1073741824.0) + " GiB but " +
                           detail::short_text(limit / 1073741824.0) +
                           " GiB are allowed; make the element size larger, the cell smaller, or allow more memory",
                       InvalidInput::Remedy::memory);
  }
}

struct Box {
  double x0, y0, z0, x1, y1, z1;
};
Box bounding_box(int dim, int tag) {
  Box b{};
  detail::gmsh_call(detail::gmsh_api().bounding_box, dim, tag, &b.x0, &b.y0, &b.z0, &b.x1, &b.y1,
                    &b.z1);
  return b;
}

// (dim, tag) pairs as Gmsh's C API lists them: dim, tag, dim, tag, ...
using DimTags = std::vector<int>;

// The curves lying on the segment (x0, y0)..(x1, y1) of the cell's boundary.
std::vector<int> side_curves(double x0, double y0, double x1, double y1) {
  constexpr double eps = 1e-6;  // Gmsh's boxes of OpenCASCADE shapes are 1e-7 wider
  int* found = nullptr;
  std::size_t n = 0;
  detail::gmsh_call(detail::gmsh_api().entities_in_box, x0 - eps, y0 - eps, -eps, x1 + eps,
                    y1 + eps, eps, &found, &n, 1);
  const DimTags curves = detail::gmsh_take(found, n);
  std::vector<int> tags;
  for (std::size_t i = 1; i < curves.size(); i += 2) tags.push_back(curves[i]);
  return tags;
}

// Declares each curve of `copies` the translate by (dx, dy) of the curve of `masters`
// whose box matches, so Gmsh meshes both alike.
void make_periodic(const std::vector<int>& copies, const std::vector<int>& masters, double dx, double dy) {
  std::vector<int> copy_tags, master_tags;
  for (const int c : copies) {
    const Box a = bounding_box(1, c);
    for (const int m : masters) {
      const Box b = bounding_box(1, m);
      if (std::abs(a.x0 - dx - b.x0) < 1e-5 && std::abs(a.x1 - dx - b.x1) < 1e-5 && std::abs(a.y0 - dy - b.y0) < 1e-5 &&
          std::abs(a.y1 - dy - b.y1) < 1e-5) {
        copy_tags.push_back(c);
        master_tags.push_back(m);
        break;
      }
    }
  }
  if (copy_tags.size() != copies.size() || masters.size() != copies.size()) {
    throw std::runtime_error("Gmsh: the curves on opposite sides of the cell do not pair up (" +
                             std::to_string(copies.size()) + " against " + std::to_string(masters.size()) + ")");
  }
  double affine[16] = {1, 0, 0, dx, 0, 1, 0, dy, 0, 0, 1, 0, 0, 0, 0, 1};
  detail::gmsh_call(detail::gmsh_api().set_periodic, 1, copy_tags.data(), copy_tags.size(),
                    master_tags.data(), master_tags.size(), affine, std::size_t{16});
}

// Where a fiber's circle should begin (OpenCASCADE puts a vertex there, and Gmsh a node):
// in the middle of the widest arc between the points where the cell's sides cross the
// circle, so the vertex is not a hair from a crossing. Angles from the +x axis; (dx, dy)
// are the offsets from the center to the nearest vertical and horizontal sides.
double seam_angle(double dx, double dy, double radius) {
  std::vector<double> crossings;
  if (std::abs(dx) < radius) {
    const double a = std::acos(dx / radius);
    crossings.insert(crossings.end(), {a, -a});
  }
  if (std::abs(dy) < radius) {
    const double a = std::asin(dy / radius);
    crossings.insert(crossings.end(), {a, kPi - a});
  }
  if (crossings.empty()) return 0;
  for (double& a : crossings) a -= 2 * kPi * std::floor(a / (2 * kPi));
  std::sort(crossings.begin(), crossings.end());
  double widest = crossings.front() + 2 * kPi - crossings.back(), at = crossings.back() + widest / 2;
  for (std::size_t i = 1; i < crossings.size(); ++i) {
    if (crossings[i] - crossings[i - 1] > widest) widest = crossings[i] - crossings[i - 1], at = crossings[i - 1] + widest / 2;
  }
  return at;
}

// Builds and meshes the cell in units of the diameter; returns, per surface, its
// material (0 matrix, k + 1 fiber k).
std::unordered_map<int, std::uint32_t> build_and_mesh(const Rve& rve, const RveMeshSpec& spec, double element_size) {
  const detail::GmshApi& gmsh = detail::gmsh_api();
  using detail::gmsh_call;
  const double unit = rve.diameter, w = rve.cell.width() / unit, h = rve.cell.height() / unit;
  gmsh_call(gmsh.add_model, "rve");
  DimTags cell{2, gmsh_call(gmsh.add_rectangle, 0.0, 0.0, 0.0, w, h, -1, 0.0)};
  DimTags disks;
  std::vector<std::uint32_t> fiber_of_disk;
  for (std::size_t k = 0; k < rve.centers.size(); ++k) {
    const double cx = rve.centers[k].x / unit, cy = rve.centers[k].y / unit, radius = rve.diameters[k] / 2 / unit;
    const double seam = seam_angle(cx < w / 2 ? -cx : w - cx, cy < h / 2 ? -cy : h - cy, radius);
    for (const double x : {cx - w, cx, cx + w}) {
      for (const double y : {cy - h, cy, cy + h}) {
        if (x + radius <= 0 || x - radius >= w || y + radius <= 0 || y - radius >= h) continue;
        int disk[2] = {2, gmsh_call(gmsh.add_disk, x, y, 0.0, radius, radius, -1)};
        if (seam != 0) gmsh_call(gmsh.rotate, disk, std::size_t{2}, x, y, 0.0, 0.0, 0.0, 1.0, seam);
        disks.insert(disks.end(), disk, disk + 2);
        fiber_of_disk.push_back(static_cast<std::uint32_t>(k + 1));
      }
    }
  }
  int* pieces = nullptr;
  int** pieces_of_data = nullptr;
  std::size_t pieces_n = 0, *pieces_of_n = nullptr, inputs = 0;
  gmsh_call(gmsh.fragment, cell.data(), cell.size(), disks.data(), disks.size(), &pieces, &pieces_n,
            &pieces_of_data, &pieces_of_n, &inputs, -1, 1, 1);
  detail::gmsh_take(pieces, pieces_n);
  // [0]: the cell's pieces, [1 + i]: disk i's.
  const std::vector<DimTags> pieces_of = detail::gmsh_take(pieces_of_data, pieces_of_n, inputs);
  if (pieces_of.size() != 1 + fiber_of_disk.size())
    throw std::runtime_error("Gmsh: fragments of unexpected inputs");
  // A piece is in the cell when it is one of the cell's pieces; a fiber's when it is
  // also one of a disk's; the disks' other pieces lie outside and go.
  std::unordered_map<int, std::uint32_t> material;
  for (std::size_t j = 1; j < pieces_of[0].size(); j += 2) material[pieces_of[0][j]] = 0;
  DimTags outside;
  for (std::size_t i = 0; i < fiber_of_disk.size(); ++i) {
    const DimTags& of_disk = pieces_of[i + 1];
    for (std::size_t j = 1; j < of_disk.size(); j += 2) {
      const auto in_cell = material.find(of_disk[j]);
      if (in_cell != material.end()) {
        in_cell->second = fiber_of_disk[i];
      } else {
        outside.insert(outside.end(), {of_disk[j - 1], of_disk[j]});
      }
    }
  }
  gmsh_call(gmsh.remove, outside.data(), outside.size(), 1);
  gmsh_call(gmsh.synchronize);
  make_periodic(side_curves(w, 0, w, h), side_curves(0, 0, 0, h), w, 0);
  make_periodic(side_curves(0, h, w, h), side_curves(0, 0, w, 0), 0, h);
  // Elements no longer than the smallest fiber's segment give every fiber its segments;
  // only larger ones need Gmsh's sizing from curvature (which costs a third more time).
  const double smallest = *std::min_element(rve.diameters.begin(), rve.diameters.end());
  const double segment = kPi * smallest / unit / static_cast<double>(spec.fiber_segments);
  if (element_size / unit > segment * (1 + 1e-9)) {
    gmsh_call(gmsh.set_number, "Mesh.MeshSizeFromCurvature",
              static_cast<double>(spec.fiber_segments));
  }
  gmsh_call(gmsh.set_number, "Mesh.MeshSizeMax", element_size / unit);
  gmsh_call(gmsh.set_number, "Mesh.Algorithm", 6.0);  // frontal-Delaunay: the best shaped triangles
  gmsh_call(gmsh.generate, 2);
  return material;
}

// Reads Gmsh's mesh (coordinates back in the caller's units) into `out`.
void read_mesh(const std::unordered_map<int, std::uint32_t>& material, double unit, RveMesh& out) {
  const detail::GmshApi& gmsh = detail::gmsh_api();
  std::size_t *tags_data = nullptr, tags_n = 0, xyz_n = 0, parametric_n = 0;
  double *xyz_data = nullptr, *parametric_data = nullptr;
  detail::gmsh_call(gmsh.nodes, &tags_data, &tags_n, &xyz_data, &xyz_n, &parametric_data,
                    &parametric_n, -1, -1, 0, 0);
  const std::vector<std::size_t> node_tags = detail::gmsh_take(tags_data, tags_n);
  const std::vector<double> xyz = detail::gmsh_take(xyz_data, xyz_n);
  detail::gmsh_take(parametric_data, parametric_n);
  if (xyz.size() != 3 * node_tags.size())
    throw std::runtime_error("Gmsh: node coordinates do not match the nodes");
  std::unordered_map<std::size_t, std::uint32_t> index_of;
  std::vector<Vec2> gmsh_nodes(node_tags.size());
  for (std::size_t i = 0; i < node_tags.size(); ++i) {
    index_of[node_tags[i]] = static_cast<std::uint32_t>(i);
    gmsh_nodes[i] = {xyz[3 * i] * unit, xyz[3 * i + 1] * unit};
  }
  // Only the nodes triangles use, in the order they first appear.
  std::vector<std::uint32_t> renumber(node_tags.size(), UINT32_MAX);
  int* surfaces_data = nullptr;
  std::size_t surfaces_n = 0;
  detail::gmsh_call(gmsh.entities, &surfaces_data, &surfaces_n, 2);
  const DimTags surfaces = detail::gmsh_take(surfaces_data, surfaces_n);
  for (std::size_t s = 1; s < surfaces.size(); s += 2) {
    const int tag = surfaces[s];
    const std::uint32_t kind = material.at(tag);
    int* types_data = nullptr;
    std::size_t types_n = 0, **element_tags_data = nullptr, *element_tags_n = nullptr,
                element_tags_nn = 0;
    std::size_t **element_nodes_data = nullptr, *element_nodes_n = nullptr, element_nodes_nn = 0;
    detail::gmsh_call(gmsh.elements, &types_data, &types_n, &element_tags_data, &element_tags_n,
                      &element_tags_nn, &element_nodes_data, &element_nodes_n, &element_nodes_nn, 2,
                      tag);
    const std::vector<int> types = detail::gmsh_take(types_data, types_n);
    detail::gmsh_take(element_tags_data, element_tags_n, element_tags_nn);
    const std::vector<std::vector<std::size_t>> element_nodes =
        detail::gmsh_take(element_nodes_data, element_nodes_n, element_nodes_nn);
    if (element_nodes.size() != types.size())
      throw std::runtime_error("Gmsh: elements do not match their types");
    for (std::size_t t = 0; t < types.size(); ++t) {
      if (types[t] != 2) throw std::runtime_error("Gmsh: a surface element that is not a 3-node triangle");
      const std::vector<std::size_t>& corners = element_nodes[t];
      for (std::size_t e = 0; e + 2 < corners.size(); e += 3) {
        std::array<std::uint32_t, 3> tri{};
        for (int c = 0; c < 3; ++c) {
          const std::uint32_t gmsh_index = index_of.at(corners[e + c]);
          std::uint32_t& at = renumber[gmsh_index];
          if (at == UINT32_MAX) {
            at = static_cast<std::uint32_t>(out.nodes.size());
            out.nodes.push_back(gmsh_nodes[gmsh_index]);
          }
          tri[c] = at;
        }
        const Vec2 a = out.nodes[tri[0]], b = out.nodes[tri[1]], c = out.nodes[tri[2]];
        if (cross(b - a, c - a) < 0) std::swap(tri[1], tri[2]);
        out.triangles.push_back(tri);
        out.material.push_back(kind);
      }
    }
  }
  if (out.triangles.empty()) throw std::runtime_error("Gmsh made no triangles");
}

// Finds the nodes on the cell's sides from the mesh's boundary edges, checks that
// opposite sides pair up and every boundary edge lies on a side (the mesh covers the
// cell without holes), and snaps them exactly onto the sides.
void pair_sides(RveMesh& m) {
  const double w = m.width, h = m.height, tol = 1e-9 * std::max(w, h);
  std::unordered_map<std::uint64_t, int> edge_uses;
  for (const auto& t : m.triangles) {
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = std::min(t[i], t[(i + 1) % 3]), b = std::max(t[i], t[(i + 1) % 3]);
      ++edge_uses[(std::uint64_t{a} << 32) | b];
    }
  }
  enum Side { kLeft = 1, kRight = 2, kBottom = 4, kTop = 8 };
  const auto sides_of = [&](std::uint32_t n) {
    const Vec2 p = m.nodes[n];
    return (std::abs(p.x) <= tol ? kLeft : 0) | (std::abs(p.x - w) <= tol ? kRight : 0) |
           (std::abs(p.y) <= tol ? kBottom : 0) | (std::abs(p.y - h) <= tol ? kTop : 0);
  };
  std::unordered_set<std::uint32_t> on_boundary;
  for (const auto& [key, uses] : edge_uses) {
    if (uses > 2) throw std::runtime_error("Gmsh: an edge of three or more triangles");
    if (uses == 2) continue;
    const auto a = static_cast<std::uint32_t>(key >> 32), b = static_cast<std::uint32_t>(key & 0xffffffffu);
    if ((sides_of(a) & sides_of(b)) == 0) throw std::runtime_error("Gmsh: a boundary edge inside the cell (a hole)");
    on_boundary.insert(a);
    on_boundary.insert(b);
  }
  int corners_found = 0;
  for (const std::uint32_t n : on_boundary) {
    const int s = sides_of(n);
    const bool corner = (s & (kLeft | kRight)) && (s & (kBottom | kTop));
    if (corner) {
      m.corners[(s & kLeft) ? ((s & kBottom) ? 0 : 3) : ((s & kBottom) ? 1 : 2)] = n;
      ++corners_found;
    } else {
      (s & kLeft ? m.left : s & kRight ? m.right : s & kBottom ? m.bottom : m.top).push_back(n);
    }
  }
  if (corners_found != 4) throw std::runtime_error("Gmsh: the mesh has " + std::to_string(corners_found) + " corner nodes");
  const auto by = [&](double Vec2::*along) {
    return [&m, along](std::uint32_t a, std::uint32_t b) { return m.nodes[a].*along < m.nodes[b].*along; };
  };
  for (auto* side : {&m.left, &m.right}) std::sort(side->begin(), side->end(), by(&Vec2::y));
  for (auto* side : {&m.bottom, &m.top}) std::sort(side->begin(), side->end(), by(&Vec2::x));
  const auto pair_up = [&](std::vector<std::uint32_t>& masters, std::vector<std::uint32_t>& copies, double Vec2::*along,
                           const char* what) {
    bool match = masters.size() == copies.size();
    for (std::size_t i = 0; match && i < masters.size(); ++i) {
      match = std::abs(m.nodes[masters[i]].*along - m.nodes[copies[i]].*along) <= tol;
    }
    if (!match) throw std::runtime_error(std::string("Gmsh: the nodes on the ") + what + " sides do not pair up");
    for (std::size_t i = 0; i < masters.size(); ++i) m.nodes[copies[i]].*along = m.nodes[masters[i]].*along;
  };
  pair_up(m.left, m.right, &Vec2::y, "left and right");
  pair_up(m.bottom, m.top, &Vec2::x, "bottom and top");
  for (const std::uint32_t n : m.left) m.nodes[n].x = 0;
  for (const std::uint32_t n : m.right) m.nodes[n].x = w;
  for (const std::uint32_t n : m.bottom) m.nodes[n].y = 0;
  for (const std::uint32_t n : m.top) m.nodes[n].y = h;
  const Vec2 corner_at[4] = {{0, 0}, {w, 0}, {w, h}, {0, h}};
  for (int c = 0; c < 4; ++c) m.nodes[m.corners[c]] = corner_at[c];
}

void measure_shape(RveMesh& m) {
  m.angles = measure_angles(m.nodes, m.triangles);
  std::vector<double> ratios;
  ratios.reserve(m.triangles.size());
  for (const auto& t : m.triangles) {
    const Vec2 a = m.nodes[t[0]], b = m.nodes[t[1]], c = m.nodes[t[2]];
    const double la = distance(b, c), lb = distance(c, a), lc = distance(a, b), area = cross(b - a, c - a) / 2;
    // circumradius abc / (4 A) over twice the inradius A / s
    ratios.push_back(area > 0 ? la * lb * lc * (la + lb + lc) / (16 * area * area) : INFINITY);
  }
  m.radius_ratio = detail::statistics(ratios);
}

}  // namespace

void check_rve_mesh(const RveSpec& rve, const RveMeshSpec& mesh) {
  const double smallest = rve.diameter_cv != 0 || !rve.diameter_list.empty() ? detail::diameter_law(rve).smallest
                                                                             : rve.diameter;
  check_spec(rve.width, rve.height, smallest, rve.gap, mesh);
  detail::gmsh_api();  // a missing Gmsh fails the job now, not after the fibers are made
}

RveMesh mesh_rve(const Rve& rve, const RveMeshSpec& spec) {
  if (rve.centers.empty()) throw InvalidInput("rve mesh: there are no fibers to mesh");
  if (rve.diameters.size() != rve.centers.size()) {
    throw InvalidInput("rve mesh: " + std::to_string(rve.centers.size()) + " fibers but " +
                       std::to_string(rve.diameters.size()) + " diameters; give one diameter per fiber");
  }
  const double smallest = *std::min_element(rve.diameters.begin(), rve.diameters.end());
  check_spec(rve.cell.width(), rve.cell.height(), smallest, rve.gap, spec);
  const double clearance = side_clearance(rve);
  if (clearance < 1e-5 * rve.diameter) {
    throw InvalidInput("rve mesh: a fiber boundary touches a side of the cell (within " + number(clearance) +
                       "), where the mesh would need slivers; translate the fibers (make_rve places the sides "
                       "clear of them)");
  }
  const double element_size = element_size_of(spec, smallest);
  RveMesh out;
  out.width = rve.cell.width();
  out.height = rve.cell.height();
  out.side_clearance = clearance;
  {
    const std::lock_guard<std::mutex> lock(gmsh_mutex);
    const GmshSession session;
    read_mesh(build_and_mesh(rve, spec, element_size), rve.diameter, out);
  }
  pair_sides(out);
  measure_shape(out);
  return out;
}

}  // namespace disktune
