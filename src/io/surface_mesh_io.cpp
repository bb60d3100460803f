// SPDX-License-Identifier: GPL-3.0-or-later
// A surface mesh as ASCII OFF, OBJ or PLY, written atomically.
#include <string>

#include "disktune/errors.h"
#include "disktune/io.h"
#include "disktune/surface_mesh.h"
#include "file_extension.h"
#include "number_text.h"

namespace disktune {
namespace {

enum class Format { Off, Obj, Ply };

Format format_for(const std::string& path) {
  const std::string ext = detail::lower_extension(path);
  if (ext == ".off") return Format::Off;
  if (ext == ".obj") return Format::Obj;
  if (ext == ".ply") return Format::Ply;
  throw InvalidInput("cannot write the surface mesh '" + path +
                     "': unknown extension; supported on a surface: .off, .obj, .ply (all ASCII)");
}

void put_point(std::ostream& out, Vec3 p) {
  detail::put_number(out, p.x);
  out << ' ';
  detail::put_number(out, p.y);
  out << ' ';
  detail::put_number(out, p.z);
  out << '\n';
}

// `base` is the first vertex's number: 1 in OBJ, 0 elsewhere.
void put_faces(std::ostream& out, const SurfaceMesh& mesh, const char* prefix, std::uint32_t base) {
  for (const auto& t : mesh.triangles) {
    out << prefix << t[0] + base << ' ' << t[1] + base << ' ' << t[2] + base << '\n';
  }
}

}  // namespace

void check_surface_mesh_path(const std::string& path) { format_for(path); }

void write_surface_mesh(const std::string& path, const SurfaceMesh& mesh) {
  const Format format = format_for(path);
  write_file_atomically(path, [&](std::ostream& out) {
    switch (format) {
      case Format::Off:
        out << "OFF\n" << mesh.vertices.size() << ' ' << mesh.triangles.size() << " 0\n";
        for (const Vec3& p : mesh.vertices) put_point(out, p);
        return put_faces(out, mesh, "3 ", 0);
      case Format::Obj:
        out << "# disktune surface mesh, " << mesh.triangles.size() << " triangles\n";
        for (const Vec3& p : mesh.vertices) put_point(out << "v ", p);
        return put_faces(out, mesh, "f ", 1);
      case Format::Ply:
        out << "ply\nformat ascii 1.0\ncomment disktune surface mesh\nelement vertex "
            << mesh.vertices.size()
            << "\nproperty double x\nproperty double y\nproperty double z\nelement face "
            << mesh.triangles.size() << "\nproperty list uchar int vertex_indices\nend_header\n";
        for (const Vec3& p : mesh.vertices) put_point(out, p);
        return put_faces(out, mesh, "3 ", 0);
    }
  });
}

}  // namespace disktune
