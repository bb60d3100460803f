// SPDX-License-Identifier: GPL-3.0-or-later
// The only place CGAL's file readers are compiled.
#include "polygon_soup.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>

#include <fstream>

#include "disktune/errors.h"

namespace disktune::detail {

PolygonSoup read_polygon_soup(const std::string& path) {
  if (!std::ifstream(path)) {
    throw IoError("cannot open the mesh file " + path + ": check the path and permissions");
  }
  using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  std::vector<Point> points;
  PolygonSoup soup;
  if (!CGAL::IO::read_polygon_soup(path, points, soup.polygons)) {
    throw IoError("cannot read " + path +
                  " as a polygon mesh: the file is malformed or its extension does not match "
                  "its format (.off, .obj, .stl, .ply)");
  }
  soup.points.reserve(points.size());
  for (const Point& p : points) soup.points.push_back({p.x(), p.y(), p.z()});
  return soup;
}

}  // namespace disktune::detail
