// SPDX-License-Identifier: GPL-3.0-or-later
#include "disktune/mesh_io.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "disktune/errors.h"
#include "disktune/io.h"
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

void write_off(std::ostream& out, const TriangleMesh& mesh) {
  out << "OFF\n" << mesh.vertices.size() << ' ' << mesh.triangles.size() << " 0\n";
  for (const Vec2 p : mesh.vertices) put_vertex(out, p);
  for (const auto& t : mesh.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
}

void write_obj(std::ostream& out, const TriangleMesh& mesh) {
  out << "# disktune periodic Delaunay mesh: " << mesh.disk_count << " disks, "
      << mesh.triangles.size() << " triangles\n";
  for (const Vec2 p : mesh.vertices) {
    out << "v ";
    put_vertex(out, p);
  }
  for (const auto& t : mesh.triangles) {  // OBJ counts vertices from 1
    out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
  }
}

void write_vtk(std::ostream& out, const TriangleMesh& mesh) {
  out << "# vtk DataFile Version 3.0\n"
      << "disktune periodic Delaunay mesh: " << mesh.disk_count << " disks\n"
      << "ASCII\nDATASET POLYDATA\nPOINTS " << mesh.vertices.size() << " double\n";
  for (const Vec2 p : mesh.vertices) put_vertex(out, p);
  out << "POLYGONS " << mesh.triangles.size() << ' ' << 4 * mesh.triangles.size() << '\n';
  for (const auto& t : mesh.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  out << "POINT_DATA " << mesh.vertices.size() << "\nSCALARS disk_id unsigned_int 1\n"
      << "LOOKUP_TABLE default\n";
  for (const DiskId id : mesh.vertex_disk) out << id << '\n';
}

}  // namespace

MeshFormat mesh_format_for_path(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".off") return MeshFormat::Off;
  if (ext == ".obj") return MeshFormat::Obj;
  if (ext == ".vtk") return MeshFormat::Vtk;
  throw InvalidInput("cannot tell the mesh format of '" + path +
                     "' from its extension; supported: .off, .obj, .vtk (legacy ASCII VTK)");
}

void write_mesh(const std::string& path, const TriangleMesh& mesh) {
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

}  // namespace disktune
