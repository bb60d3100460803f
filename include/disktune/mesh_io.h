// SPDX-License-Identifier: GPL-3.0-or-later
// Writing a TriangleMesh or PlanarMesh (and, through surface_mesh.h, a SurfaceMesh): ASCII
// OFF, OBJ, PLY, legacy VTK or Gmsh MSH 4.1, VTK XML (.vtu, binary: base64 inline; both
// VTK files unstructured grids, which ParaView, VTK and meshio read), binary PLY or STL,
// chosen by the file's extension,
// and an SVG picture of the mesh over its packing. Every writer goes through
// write_file_atomically: a failure leaves no partial file.
#pragma once

#include <string>

#include "disktune/mesh.h"
#include "disktune/packing.h"
#include "disktune/surface_mesh.h"

namespace disktune {

enum class MeshFormat { Off, Obj, Ply, PlyBinary, Vtk, Vtu, Msh, Stl, Triangle };

/// The format named by the extension of `path` (.off, .obj, .ply, .vtk, .vtu, .msh, .stl,
/// and .node or .ele for Triangle's pair of files; any letter case).
/// Throws InvalidInput, listing the supported extensions, for any other.
MeshFormat mesh_format_for_path(const std::string& path);
/// The format called `name`: off, obj, ply, ply-binary (little-endian), vtk, vtu, msh,
/// stl or triangle, for an output whose extension does not say (standard output; not for
/// triangle, which is two files). Throws
/// InvalidInput, listing the names, for any other.
MeshFormat mesh_format_named(const std::string& name);

/// Writes the mesh's vertices (z = 0) and triangles in the format of `path`'s
/// extension. The VTK files also carry each vertex's disk id (point data `disk_id`),
/// which tells the copies across the seam from the disks themselves; OBJ, VTK, VTU and
/// MSH files carry a surface mesh's feature edges and a planar mesh's boundary edges as
/// lines, which MSH puts in named physical groups ("feature edges"; "outer boundary",
/// "hole 1", ...; the triangles in "surface", "domain" or "torus"); STL (binary, 32-bit
/// floats) has no shared vertices, so it keeps only the triangles' shape. Triangle's
/// format (J. R. Shewchuk's mesh generator) is a pair of ASCII files, NAME.node (x y and a
/// boundary marker: 0 inside, 1 + the loop's number on a planar domain's boundary loop)
/// and NAME.ele (triangles), numbered from 1, for a planar or periodic mesh; written
/// together (an OutputTransaction of their own where none is open), from a path ending
/// in .node or .ele.
void write_mesh(const std::string& path, const TriangleMesh& mesh);
void write_mesh(const std::string& path, const TriangleMesh& mesh, MeshFormat format);
/// The same for a planar mesh; its VTK `disk_id` is kNoDisk for a vertex that is no disk.
void write_mesh(const std::string& path, const PlanarMesh& mesh);
void write_mesh(const std::string& path, const PlanarMesh& mesh, MeshFormat format);
/// write_surface_mesh (surface_mesh.h) in the format given, whatever the extension (not
/// Triangle's, which is planar: InvalidInput).
void write_surface_mesh(const std::string& path, const SurfaceMesh& mesh, MeshFormat format);

struct MeshSvgStyle {
  double pixels = 800;  ///< width of the picture in pixels
};
/// The packing's disks at half their radius (as write_packing_svg draws them) with the
/// mesh's edges over them, every periodic image that reaches into the box.
void write_mesh_svg(const std::string& path, const TriangleMesh& mesh, const Packing& packing,
                    const MeshSvgStyle& style = {});
/// The same for a planar mesh over its packing; fixed disks (boundary samples) stand out
/// in their own color, in either picture.
void write_mesh_svg(const std::string& path, const PlanarMesh& mesh, const Packing& packing,
                    const MeshSvgStyle& style = {});

}  // namespace disktune
