// SPDX-License-Identifier: GPL-3.0-or-later
// Internal: the points and polygons of a mesh file (OFF, OBJ, PLY, STL), in plain types.
// disktune's own readers (off_reader.h, obj_reader.h, ply_reader.h, stl_reader.h) read
// what CGAL 5.5's readers read, to the same soup, but check the file as they go (#17).
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace disktune::detail {

struct PolygonSoup {
  std::vector<std::array<double, 3>> points;
  std::vector<std::vector<std::size_t>> polygons;
};

/// The points and polygons of a mesh file, its format chosen by the extension (.off,
/// .obj, .ply, .stl, any letter case). Every polygon has 3 or more corners, every index
/// names a point, every coordinate is finite. Throws IoError when the file cannot be
/// opened or read, and InvalidInput, naming the file and the line (text) or the vertex
/// or face, when its content is wrong.
PolygonSoup read_polygon_soup(const std::string& path);

}  // namespace disktune::detail
