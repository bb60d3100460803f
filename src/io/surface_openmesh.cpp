// SPDX-License-Identifier: GPL-3.0-or-later
// The only place OpenMesh's readers are compiled (read_surface_openmesh).
// GCC 12 warns inside OpenMesh's property vectors (VectorT's default constructor leaves
// its elements unset on purpose): a false positive from inlined library code.
// (GCC only: clang has no such warning and would warn about the pragma.)
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>

#include "disktune/errors.h"
#include "disktune/openmesh/surface_from_openmesh.h"
#include "disktune/surface_domain.h"
#include "file_extension.h"

namespace disktune {
namespace {

// OpenMesh's OFF reader wants "OFF" on the first line; CGAL's accepts comments first.
bool starts_with_comment(std::ifstream& in) {
  char c;
  while (in.get(c)) {
    if (!std::isspace(static_cast<unsigned char>(c))) return c == '#';
  }
  return false;
}

// Double points, so the mesh adds no rounding of its own (OpenMesh 9's OFF reader still
// parses coordinates as float).
struct DoubleTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};

}  // namespace

SurfaceDomain read_surface_openmesh(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw IoError("cannot open the mesh file " + path + ": check the path and permissions");
  if (detail::lower_extension(path) == ".off" && starts_with_comment(in)) {
    throw IoError("OpenMesh cannot read " + path +
                  ": the OFF file starts with a '#' comment, which OpenMesh's OFF reader "
                  "rejects; read it with read_surface (CGAL) or move the comment after the "
                  "OFF line");
  }
  // A polygon mesh, not a TriMesh: a TriMesh would triangulate quads silently.
  OpenMesh::PolyMesh_ArrayKernelT<DoubleTraits> mesh;
  if (!OpenMesh::IO::read_mesh(mesh, path)) {
    throw IoError("OpenMesh cannot read " + path +
                  " as a mesh: the file is malformed or its extension does not match its "
                  "format (.off, .obj, .ply, .stl)");
  }
  try {
    return surface_domain_from(mesh);
  } catch (const InvalidInput& e) {
    throw InvalidInput(path + ": " + e.what());
  }
}

}  // namespace disktune
