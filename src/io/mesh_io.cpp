// SPDX-License-Identifier: GPL-3.0-or-later
#include "disktune/mesh_io.h"

#include <string>
#include <vector>

#include "disktune/errors.h"
#include "disktune/io.h"
#include "file_extension.h"
#include "number_text.h"

namespace disktune {
namespace {

using detail::put_number;

void put_vertex(std::ostream& out, Vec2 p) {
  put_number(out, p.x);
  out << ' ';
  put_number(out, p.y);
  out << " 0\n";
}

/// What the three formats need of a mesh, so one writer serves TriangleMesh and
/// PlanarMesh alike. `title` names the mesh in the OBJ and VTK headers.
struct MeshView {
  const std::vector<Vec2>& vertices;
  const std::vector<DiskId>& vertex_disk;
  const std::vector<std::array<std::uint32_t, 3>>& triangles;
  std::string title;
};

void write_off(std::ostream& out, const MeshView& mesh) {
  out << "OFF\n" << mesh.vertices.size() << ' ' << mesh.triangles.size() << " 0\n";
  for (const Vec2 p : mesh.vertices) put_vertex(out, p);
  for (const auto& t : mesh.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
}

void write_obj(std::ostream& out, const MeshView& mesh) {
  out << "# " << mesh.title << ", " << mesh.triangles.size() << " triangles\n";
  for (const Vec2 p : mesh.vertices) {
    out << "v ";
    put_vertex(out, p);
  }
  for (const auto& t : mesh.triangles) {  // OBJ counts vertices from 1
    out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
  }
}

void write_vtk(std::ostream& out, const MeshView& mesh) {
  out << "# vtk DataFile Version 3.0\n"
      << mesh.title << "\nASCII\nDATASET POLYDATA\nPOINTS " << mesh.vertices.size() << " double\n";
  for (const Vec2 p : mesh.vertices) put_vertex(out, p);
  out << "POLYGONS " << mesh.triangles.size() << ' ' << 4 * mesh.triangles.size() << '\n';
  for (const auto& t : mesh.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  out << "POINT_DATA " << mesh.vertices.size() << "\nSCALARS disk_id unsigned_int 1\n"
      << "LOOKUP_TABLE default\n";
  for (const DiskId id : mesh.vertex_disk) out << id << '\n';
}

void write_view(const std::string& path, const MeshView& mesh) {
  const MeshFormat format = mesh_format_for_path(path);
  write_file_atomically(path, [&](std::ostream& out) {
    switch (format) {
      case MeshFormat::Off:
        return write_off(out, mesh);
      case MeshFormat::Obj:
        return write_obj(out, mesh);
      case MeshFormat::Vtk:
        return write_vtk(out, mesh);
    }
  });
}

}  // namespace

MeshFormat mesh_format_for_path(const std::string& path) {
  const std::string ext = detail::lower_extension(path);
  if (ext == ".off") return MeshFormat::Off;
  if (ext == ".obj") return MeshFormat::Obj;
  if (ext == ".vtk") return MeshFormat::Vtk;
  throw InvalidInput("cannot tell the mesh format of '" + path +
                     "' from its extension; supported: .off, .obj, .vtk (legacy ASCII VTK)");
}

void write_mesh(const std::string& path, const TriangleMesh& mesh) {
  write_view(path,
             {mesh.vertices, mesh.vertex_disk, mesh.triangles,
              "disktune periodic Delaunay mesh: " + std::to_string(mesh.disk_count) + " disks"});
}

void write_mesh(const std::string& path, const PlanarMesh& mesh) {
  write_view(path, {mesh.vertices, mesh.vertex_disk, mesh.triangles,
                    "disktune planar mesh: " + std::to_string(mesh.vertices.size()) + " vertices"});
}

}  // namespace disktune
