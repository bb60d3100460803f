// SPDX-License-Identifier: GPL-3.0-or-later
// Internal: a polygon soup read by CGAL's readers (OFF, OBJ, STL, PLY, ...), handed on
// in plain types so CGAL's IO templates compile in one translation unit only.
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

/// The points and polygons of a mesh file, chosen by extension. Throws IoError when the
/// file cannot be opened or parsed.
PolygonSoup read_polygon_soup(const std::string& path);

}  // namespace disktune::detail
