// SPDX-License-Identifier: GPL-3.0-or-later
// Every mesh (periodic, planar, surface) as ASCII OFF, OBJ, PLY, legacy VTK or Gmsh MSH
// 4.1, binary VTK XML (.vtu), PLY or STL, or Triangle's .node/.ele, by one writer: a planar vertex
// is written with z = 0.
#include "disktune/mesh_io.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
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
/// as point data; `title` names the mesh in the OBJ, PLY and VTK headers. `lines` (a
/// surface's feature edges, a planar domain's boundary) go into OBJ, VTK, VTU and MSH,
/// in groups: line k in group (*line_group)[k] (all in group 0 without it), named by
/// `group_names` (Gmsh physical names, OBJ comments), the triangles by `surface_name`.
struct MeshView {
  std::vector<Vec3> vertices;
  const std::vector<DiskId>* vertex_disk;
  const std::vector<std::array<std::uint32_t, 3>>& triangles;
  std::string title;
  const std::vector<std::array<std::uint32_t, 2>>* lines = nullptr;
  const std::vector<std::uint32_t>* line_group = nullptr;
  std::vector<std::string> group_names = {};
  std::string surface_name = "surface";
  bool planar = true;  // z = 0 throughout: Triangle's files can hold it

  std::size_t line_count() const { return lines ? lines->size() : 0; }
  std::uint32_t group_of(std::size_t k) const { return line_group ? (*line_group)[k] : 0; }
  /// The lines of group g, in their order.
  std::vector<std::array<std::uint32_t, 2>> lines_in(std::uint32_t g) const {
    std::vector<std::array<std::uint32_t, 2>> out;
    for (std::size_t k = 0; k < line_count(); ++k)
      if (group_of(k) == g) out.push_back((*lines)[k]);
    return out;
  }
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

// Base64 (RFC 4648, padded) of `bytes`.
std::string base64(const std::string& bytes) {
  static const char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    std::uint32_t group = 0;
    for (std::size_t k = 0; k < 3; ++k)
      group = group << 8 | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
    for (std::size_t k = 0; k < 4; ++k) out += k <= n ? kDigits[group >> (18 - 6 * k) & 63] : '=';
  }
  return out;
}

// One inline binary DataArray of VTK XML: base64 of the byte count (UInt64, the file's
// header_type) followed by the values, little-endian as on every machine this builds for.
template <class T>
void put_binary_array(std::ostream& out, const char* type, const char* name, int components,
                      const std::vector<T>& values) {
  std::string bytes(sizeof(std::uint64_t) + values.size() * sizeof(T), '\0');
  const std::uint64_t count = values.size() * sizeof(T);
  std::memcpy(bytes.data(), &count, sizeof count);
  if (!values.empty()) std::memcpy(bytes.data() + sizeof count, values.data(), count);
  out << "<DataArray type=\"" << type << '"';
  if (name) out << " Name=\"" << name << '"';
  if (components > 1) out << " NumberOfComponents=\"" << components << '"';
  out << " format=\"binary\">\n" << base64(bytes) << "\n</DataArray>\n";
}

// VTK's XML unstructured grid, binary (base64 inline, uncompressed): triangles (type 5),
// then the lines (type 3), and the disk ids as point data.
void put_vtu(std::ostream& out, const MeshView& mesh) {
  const std::size_t nt = mesh.triangles.size(), nl = mesh.line_count();
  std::vector<double> points;
  for (const Vec3& p : mesh.vertices) points.insert(points.end(), {p.x, p.y, p.z});
  std::vector<std::int64_t> connectivity, offsets;
  std::vector<std::uint8_t> types;
  for (const auto& t : mesh.triangles) {
    connectivity.insert(connectivity.end(), {t[0], t[1], t[2]});
    offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
    types.push_back(5);
  }
  for (std::size_t k = 0; k < nl; ++k) {
    connectivity.insert(connectivity.end(), {(*mesh.lines)[k][0], (*mesh.lines)[k][1]});
    offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
    types.push_back(3);
  }
  out << "<?xml version=\"1.0\"?>\n<!-- " << mesh.title << " -->\n"
      << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt64\">\n"
      << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << mesh.vertices.size()
      << "\" NumberOfCells=\"" << nt + nl << "\">\n<Points>\n";
  put_binary_array(out, "Float64", nullptr, 3, points);
  out << "</Points>\n<Cells>\n";
  put_binary_array(out, "Int64", "connectivity", 1, connectivity);
  put_binary_array(out, "Int64", "offsets", 1, offsets);
  put_binary_array(out, "UInt8", "types", 1, types);
  out << "</Cells>\n";
  if (mesh.vertex_disk) {
    out << "<PointData Scalars=\"disk_id\">\n";
    put_binary_array(out, "UInt32", "disk_id", 1, *mesh.vertex_disk);
    out << "</PointData>\n";
  }
  out << "</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
}

// Gmsh's MSH 4.1, ASCII: the vertices as nodes 1..n of surface 1, the triangles
// (element type 2) on it, each group of lines (type 1) on a curve of its own (group g
// on curve g + 1); the surface is physical group 1 and curve g + 1 physical group
// g + 2, named. Gmsh wants every entity an element names declared ($Entities, with its
// bounding box), not only those that hold nodes.
void put_msh(std::ostream& out, const MeshView& mesh) {
  const std::size_t nv = mesh.vertices.size(), nt = mesh.triangles.size(), nl = mesh.line_count();
  const std::size_t groups = nl ? mesh.group_names.size() : 0;
  Vec3 lo{0, 0, 0}, hi{0, 0, 0};
  for (std::size_t k = 0; k < nv; ++k) {
    const Vec3 p = mesh.vertices[k];
    lo = k ? Vec3{std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)} : p;
    hi = k ? Vec3{std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)} : p;
  }
  // "<tag> <box> 1 <physical> 0": one physical group, no boundary entities.
  const auto entity = [&](std::size_t tag, std::size_t physical) {
    out << tag << ' ';
    for (const double x : {lo.x, lo.y, lo.z, hi.x, hi.y, hi.z}) put_number(out, x), out << ' ';
    out << "1 " << physical << " 0\n";
  };
  const auto quoted = [](const std::string& name) { return '"' + name + '"'; };
  out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n"
      << groups + 1 << "\n2 1 " << quoted(mesh.surface_name) << '\n';
  for (std::size_t g = 0; g < groups; ++g)
    out << "1 " << g + 2 << ' ' << quoted(mesh.group_names[g]) << '\n';
  out << "$EndPhysicalNames\n$Entities\n0 " << groups << " 1 0\n";
  for (std::size_t g = 0; g < groups; ++g) entity(g + 1, g + 2);
  entity(1, 1);
  out << "$EndEntities\n$Nodes\n1 " << nv << " 1 " << nv << "\n2 1 0 " << nv << '\n';
  for (std::size_t k = 1; k <= nv; ++k) out << k << '\n';
  put_vertices(out, mesh, "");
  const std::size_t elements = nt + nl;
  out << "$EndNodes\n$Elements\n"
      << groups + 1 << ' ' << elements << " 1 " << elements << "\n2 1 2 " << nt << '\n';
  for (std::size_t k = 0; k < nt; ++k) {
    const auto& t = mesh.triangles[k];
    out << k + 1 << ' ' << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
  }
  std::size_t tag = nt;
  for (std::size_t g = 0; g < groups; ++g) {
    const auto lines = mesh.lines_in(static_cast<std::uint32_t>(g));
    out << "1 " << g + 1 << " 1 " << lines.size() << '\n';
    for (const auto& l : lines) out << ++tag << ' ' << l[0] + 1 << ' ' << l[1] + 1 << '\n';
  }
  out << "$EndElements\n";
}

// Binary STL: an 80-byte header, the count, then per triangle its unit normal and
// corners as 32-bit floats (little-endian, as on every machine this builds for) and
// two zero bytes. STL has no shared vertices and no lines.
void put_stl(std::ostream& out, const MeshView& mesh) {
  char header[80] = {};
  std::strncpy(header, ("binary STL, " + mesh.title).c_str(), sizeof header - 1);
  out.write(header, sizeof header);
  const auto count = static_cast<std::uint32_t>(mesh.triangles.size());
  out.write(reinterpret_cast<const char*>(&count), sizeof count);
  for (const auto& t : mesh.triangles) {
    const Vec3 a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
    Vec3 n = cross(b - a, c - a);
    const double length = norm(n);
    n = length > 0 ? n * (1 / length) : Vec3{0, 0, 0};
    const float record[12] = {float(n.x), float(n.y), float(n.z), float(a.x), float(a.y), float(a.z),
                              float(b.x), float(b.y), float(b.z), float(c.x), float(c.y), float(c.z)};
    out.write(reinterpret_cast<const char*>(record), sizeof record);
    out.write("\0\0", 2);
  }
}

// Binary PLY, little-endian (as on every machine this builds for): double coordinates,
// faces as a byte count and three 32-bit indices.
void put_binary_ply(std::ostream& out, const MeshView& mesh) {
  out << "ply\nformat binary_little_endian 1.0\ncomment " << mesh.title << "\nelement vertex " << mesh.vertices.size()
      << "\nproperty double x\nproperty double y\nproperty double z\nelement face " << mesh.triangles.size()
      << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const Vec3& p : mesh.vertices) {
    const double xyz[3] = {p.x, p.y, p.z};
    out.write(reinterpret_cast<const char*>(xyz), sizeof xyz);
  }
  for (const auto& t : mesh.triangles) {
    const std::int32_t corners[3] = {static_cast<std::int32_t>(t[0]), static_cast<std::int32_t>(t[1]),
                                     static_cast<std::int32_t>(t[2])};
    out.put(3);
    out.write(reinterpret_cast<const char*>(corners), sizeof corners);
  }
}

// Triangle's NAME.node (vertices, numbered from 1, with a boundary marker: 1 + the
// number of the line group a vertex ends a line of, else 0) and NAME.ele (triangles),
// both or neither: in an OutputTransaction.
void put_triangle_files(const std::string& path, const MeshView& mesh) {
  const std::string ext = detail::lower_extension(path);
  if (ext != ".node" && ext != ".ele") {
    throw InvalidInput(
        "Triangle's mesh format is two files, NAME.node and NAME.ele: give a path ending in .node "
        "or "
        ".ele, not '" +
        path + "'");
  }
  if (!mesh.planar) {
    throw InvalidInput(
        "Triangle's .node/.ele files hold planar meshes, and this one is a surface: write it as "
        ".off, "
        ".obj, .ply, .vtk, .vtu, .msh or .stl");
  }
  const std::string stem = path.substr(0, path.size() - ext.size());
  std::vector<std::uint32_t> marker(mesh.vertices.size(), 0);
  for (std::size_t k = 0; k < mesh.line_count(); ++k)
    for (const std::uint32_t v : (*mesh.lines)[k]) marker[v] = mesh.group_of(k) + 1;
  std::optional<OutputTransaction> own;
  if (!OutputTransaction::open_here()) own.emplace();
  write_file_atomically(stem + ".node", [&](std::ostream& out) {
    out << "# " << mesh.title << "\n" << mesh.vertices.size() << " 2 0 1\n";
    for (std::size_t k = 0; k < mesh.vertices.size(); ++k) {
      out << k + 1 << ' ';
      put_number(out, mesh.vertices[k].x);
      out << ' ';
      put_number(out, mesh.vertices[k].y);
      out << ' ' << marker[k] << '\n';
    }
  });
  write_file_atomically(stem + ".ele", [&](std::ostream& out) {
    out << "# " << mesh.title << "\n" << mesh.triangles.size() << " 3 0\n";
    for (std::size_t k = 0; k < mesh.triangles.size(); ++k) {
      const auto& t = mesh.triangles[k];
      out << k + 1 << ' ' << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
    }
  });
  if (own) own->commit();
}

void write_view(const std::string& path, const MeshView& mesh, std::optional<MeshFormat> given = {}) {
  const MeshFormat format = given ? *given : mesh_format_for_path(path);
  if (format == MeshFormat::Triangle) return put_triangle_files(path, mesh);
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
        for (std::size_t g = 0; mesh.line_count() && g < mesh.group_names.size(); ++g) {
          out << "# " << mesh.group_names[g] << '\n';
          for (const auto& l : mesh.lines_in(static_cast<std::uint32_t>(g)))
            out << "l " << l[0] + 1 << ' ' << l[1] + 1 << '\n';
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
      case MeshFormat::PlyBinary: return put_binary_ply(out, mesh);
      case MeshFormat::Vtu: return put_vtu(out, mesh);
      case MeshFormat::Msh: return put_msh(out, mesh);
      case MeshFormat::Stl: return put_stl(out, mesh);
      case MeshFormat::Triangle:
        return;  // two files: put_triangle_files
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
  if (ext == ".vtu") return MeshFormat::Vtu;
  if (ext == ".msh") return MeshFormat::Msh;
  if (ext == ".stl") return MeshFormat::Stl;
  if (ext == ".node" || ext == ".ele") return MeshFormat::Triangle;
  throw InvalidInput("cannot tell the mesh format of '" + path +
                     "' from its extension; supported: .off, .obj, .ply, .vtk, .vtu, .msh, .stl, "
                     ".node/.ele (.vtk is legacy "
                     "VTK, .vtu VTK XML, .msh Gmsh 4.1, .node/.ele Triangle's pair; .vtu and .stl "
                     "binary, the others "
                     "ASCII), or name the format (binary PLY: "
                     "ply-binary)");
}

MeshFormat mesh_format_named(const std::string& name) {
  static const std::pair<const char*, MeshFormat> kNames[] = {
      {"off", MeshFormat::Off},          {"obj", MeshFormat::Obj},
      {"ply", MeshFormat::Ply},          {"ply-binary", MeshFormat::PlyBinary},
      {"vtk", MeshFormat::Vtk},          {"vtu", MeshFormat::Vtu},
      {"msh", MeshFormat::Msh},          {"stl", MeshFormat::Stl},
      {"triangle", MeshFormat::Triangle}};
  for (const auto& [known, format] : kNames)
    if (name == known) return format;
  throw InvalidInput("mesh format '" + name +
                     "': give off, obj, ply, ply-binary, vtk, vtu, msh, stl or triangle");
}

namespace {

MeshView view_of(const TriangleMesh& mesh) {
  MeshView view{in_plane(mesh.vertices), &mesh.vertex_disk, mesh.triangles,
                "disktune periodic Delaunay mesh: " + std::to_string(mesh.disk_count) + " disks"};
  view.surface_name = "torus";
  return view;
}
MeshView view_of(const PlanarMesh& mesh) {
  MeshView view{in_plane(mesh.vertices),
                &mesh.vertex_disk,
                mesh.triangles,
                "disktune planar mesh: " + std::to_string(mesh.vertices.size()) + " vertices",
                &mesh.boundary_edges,
                &mesh.boundary_loop};
  view.surface_name = "domain";
  std::uint32_t loops = 0;
  for (const std::uint32_t k : mesh.boundary_loop) loops = std::max(loops, k + 1);
  for (std::uint32_t k = 0; k < loops; ++k)
    view.group_names.push_back(k == 0 ? "outer boundary" : "hole " + std::to_string(k));
  return view;
}
MeshView view_of(const SurfaceMesh& mesh) {
  MeshView view{mesh.vertices, nullptr, mesh.triangles,
                "disktune surface mesh: " + std::to_string(mesh.vertices.size()) + " vertices",
                &mesh.feature_edges};
  view.group_names = {"feature edges"};
  view.planar = false;
  return view;
}

}  // namespace

void write_mesh(const std::string& path, const TriangleMesh& mesh) { write_view(path, view_of(mesh)); }
void write_mesh(const std::string& path, const TriangleMesh& mesh, MeshFormat format) {
  write_view(path, view_of(mesh), format);
}
void write_mesh(const std::string& path, const PlanarMesh& mesh) { write_view(path, view_of(mesh)); }
void write_mesh(const std::string& path, const PlanarMesh& mesh, MeshFormat format) {
  write_view(path, view_of(mesh), format);
}
void write_surface_mesh(const std::string& path, const SurfaceMesh& mesh) { write_view(path, view_of(mesh)); }
void write_surface_mesh(const std::string& path, const SurfaceMesh& mesh, MeshFormat format) {
  write_view(path, view_of(mesh), format);
}

void check_surface_mesh_path(const std::string& path) { mesh_format_for_path(path); }

}  // namespace disktune
