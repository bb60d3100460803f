// SPDX-License-Identifier: GPL-3.0-or-later
// Every mesh (periodic, planar, surface) as ASCII OFF, OBJ, PLY or legacy VTK, by one
// writer: a planar vertex is written with z = 0.
#include "disktune/mesh_io.h"

#include <string>
#include <vector>

#include "disktune/errors.h"
#include "disktune/io.h"
#include "disktune/surface_mesh.h"
#include "file_extension.h"
#include "number_text.h"

namespace disktune {
namespace {

using detail::put_number;

/// What the formats need of a mesh. `vertex_disk`, when given, goes into the VTK file
/// as point data; `title` names the mesh in the OBJ, PLY and VTK headers.
struct MeshView {
  std::vector<Vec3> vertices;
  const std::vector<DiskId>* vertex_disk;
  const std::vector<std::array<std::uint32_t, 3>>& triangles;
  std::string title;
  const std::vector<std::array<std::uint32_t, 2>>* lines = nullptr;  // OBJ and VTK only
};

std::vector<Vec3> in_plane(const std::vector<Vec2>& points) {
  std::vector<Vec3> out;
  out.reserve(points.size());
  for (const Vec2 p : points) out.push_back({p.x, p.y, 0});
  return out;
}

void put_vertices(std::ostream& out, const MeshView& mesh, const char* prefix) {
  for (const Vec3& p : mesh.vertices) {
    out << prefix;
    put_number(out, p.x);
    out << ' ';
    put_number(out, p.y);
    out << ' ';
    put_number(out, p.z);
    out << '\n';
  }
}

// `base` is the first vertex's number: 1 in OBJ, 0 elsewhere.
void put_triangles(std::ostream& out, const MeshView& mesh, const char* prefix, std::uint32_t base) {
  for (const auto& t : mesh.triangles) out << prefix << t[0] + base << ' ' << t[1] + base << ' ' << t[2] + base << '\n';
}

void write_view(const std::string& path, const MeshView& mesh) {
  const MeshFormat format = mesh_format_for_path(path);
  const std::size_t nv = mesh.vertices.size(), nt = mesh.triangles.size();
  write_file_atomically(path, [&](std::ostream& out) {
    switch (format) {
      case MeshFormat::Off:
        out << "OFF\n" << nv << ' ' << nt << " 0\n";
        put_vertices(out, mesh, "");
        return put_triangles(out, mesh, "3 ", 0);
      case MeshFormat::Obj:
        out << "# " << mesh.title << ", " << nt << " triangles\n";
        put_vertices(out, mesh, "v ");
        put_triangles(out, mesh, "f ", 1);
        if (mesh.lines && !mesh.lines->empty()) {
          out << "# feature edges\n";
          for (const auto& l : *mesh.lines) out << "l " << l[0] + 1 << ' ' << l[1] + 1 << '\n';
        }
        return;
      case MeshFormat::Ply:
        out << "ply\nformat ascii 1.0\ncomment " << mesh.title << "\nelement vertex " << nv
            << "\nproperty double x\nproperty double y\nproperty double z\nelement face " << nt
            << "\nproperty list uchar int vertex_indices\nend_header\n";
        put_vertices(out, mesh, "");
        return put_triangles(out, mesh, "3 ", 0);
      case MeshFormat::Vtk: {
        // An unstructured grid, not polygonal data: both read the same in VTK and
        // ParaView, and meshio reads only this one. Triangles (cell type 5), then the
        // feature edges as lines (type 3).
        const std::size_t nl = mesh.lines ? mesh.lines->size() : 0;
        out << "# vtk DataFile Version 3.0\n" << mesh.title << "\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS " << nv
            << " double\n";
        put_vertices(out, mesh, "");
        out << "CELLS " << nt + nl << ' ' << 4 * nt + 3 * nl << '\n';
        put_triangles(out, mesh, "3 ", 0);
        for (std::size_t k = 0; k < nl; ++k) out << "2 " << (*mesh.lines)[k][0] << ' ' << (*mesh.lines)[k][1] << '\n';
        out << "CELL_TYPES " << nt + nl << '\n';
        for (std::size_t k = 0; k < nt + nl; ++k) out << (k < nt ? "5\n" : "3\n");
        if (!mesh.vertex_disk) return;
        out << "POINT_DATA " << nv << "\nSCALARS disk_id unsigned_int 1\nLOOKUP_TABLE default\n";
        for (const DiskId id : *mesh.vertex_disk) out << id << '\n';
        return;
      }
    }
  });
}

}  // namespace

MeshFormat mesh_format_for_path(const std::string& path) {
  const std::string ext = detail::lower_extension(path);
  if (ext == ".off") return MeshFormat::Off;
  if (ext == ".obj") return MeshFormat::Obj;
  if (ext == ".ply") return MeshFormat::Ply;
  if (ext == ".vtk") return MeshFormat::Vtk;
  throw InvalidInput("cannot tell the mesh format of '" + path +
                     "' from its extension; supported: .off, .obj, .ply, .vtk (all ASCII; .vtk is legacy VTK)");
}

void write_mesh(const std::string& path, const TriangleMesh& mesh) {
  write_view(path, {in_plane(mesh.vertices), &mesh.vertex_disk, mesh.triangles,
                    "disktune periodic Delaunay mesh: " + std::to_string(mesh.disk_count) + " disks"});
}

void write_mesh(const std::string& path, const PlanarMesh& mesh) {
  write_view(path, {in_plane(mesh.vertices), &mesh.vertex_disk, mesh.triangles,
                    "disktune planar mesh: " + std::to_string(mesh.vertices.size()) + " vertices"});
}

void write_surface_mesh(const std::string& path, const SurfaceMesh& mesh) {
  write_view(path, {mesh.vertices, nullptr, mesh.triangles,
                    "disktune surface mesh: " + std::to_string(mesh.vertices.size()) + " vertices",
                    &mesh.feature_edges});
}

void check_surface_mesh_path(const std::string& path) { mesh_format_for_path(path); }

}  // namespace disktune
