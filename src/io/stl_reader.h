// SPDX-License-Identifier: GPL-3.0-or-later
// Internal to polygon_soup.cpp: the STL reader, ascii ("solid ... facet ... outer loop
// vertex x y z ... endloop endfacet ... endsolid") and binary (an 80-byte header, a
// little-endian uint32 triangle count, 50 bytes per triangle). As CGAL 5.5's reader does,
// a file that starts with "solid" and a blank is read as ascii first and as binary if that
// fails (binary files may start with "solid" too), and corners with equal coordinates
// become one point, numbered in order of first appearance, so every triangle i is
// {a, b, c} of those points. Unlike CGAL's it refuses non-finite coordinates and checks
// the binary count against the file size before allocating.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "mesh_text.h"
#include "polygon_soup.h"

namespace disktune::detail {

namespace stl {

// Corners with equal coordinates share one point (CGAL's STL reader merges them so).
class Corners {
 public:
  explicit Corners(PolygonSoup& soup) : soup_(soup) {}
  std::size_t index(const std::array<double, 3>& p) {
    const auto [it, added] = seen_.emplace(p, soup_.points.size());
    if (added) soup_.points.push_back(p);
    return it->second;
  }

 private:
  PolygonSoup& soup_;
  std::map<std::array<double, 3>, std::size_t> seen_;
};

inline PolygonSoup read_ascii(const std::string& path, std::string_view bytes) {
  MeshText in(path, bytes);
  PolygonSoup soup;
  Corners corners(soup);
  bool in_solid = false;
  std::size_t solid_line = 0;
  for (std::string_view w = in.word(); !w.empty(); w = in.word()) {
    if (w == "solid") {
      if (in_solid) {
        in.fail("a second 'solid' inside the solid that starts on line " +
                std::to_string(solid_line) + "; an 'endsolid' is missing");
      }
      in_solid = true;
      solid_line = in.line();
    } else if (w == "endsolid") {
      in_solid = false;
    } else if (w == "facet") {
      // Between "facet" and "endfacet" only the vertices count (the normal is ignored).
      const std::string name = "facet " + std::to_string(soup.polygons.size());
      const std::size_t facet_line = in.line();
      std::vector<std::size_t> triangle;
      for (w = in.word(); w != "endfacet"; w = in.word()) {
        if (w.empty()) {
          in.fail("the file ends inside " + name + ", which starts on line " +
                  std::to_string(facet_line) + "; it is truncated");
        }
        if (w != "vertex") continue;
        if (triangle.size() == 3) {
          in.fail(name + " has more than 3 vertices; STL facets are triangles");
        }
        std::array<double, 3> p{};
        for (double& c : p) {
          const std::string_view number = in.word();
          if (!parse_double(number, c) || !std::isfinite(c)) {
            in.fail(name + ": " + in_quotes(number) +
                    " is not a finite number; a vertex line reads 'vertex x y z'");
          }
        }
        triangle.push_back(corners.index(p));
      }
      if (triangle.size() != 3) {
        in.fail(name + " has " + std::to_string(triangle.size()) +
                " vertices; STL facets are triangles");
      }
      soup.polygons.push_back(std::move(triangle));
    }
    // Any other word (names, "normal", "outer loop", ...) is passed, as CGAL passes it.
  }
  if (in_solid) {
    in.fail("the solid that starts on line " + std::to_string(solid_line) +
            " has no 'endsolid'; the file is truncated");
  }
  return soup;
}

inline PolygonSoup read_binary(const std::string& path, std::string_view bytes) {
  const auto le32 = [&](std::size_t at) {
    std::uint32_t u = 0;
    for (int k = 3; k >= 0; --k) u = (u << 8) | static_cast<unsigned char>(bytes[at + k]);
    return u;
  };
  if (bytes.size() < 84) {
    throw InvalidInput(path + ": " + std::to_string(bytes.size()) +
                       " bytes, too short for a binary STL (its header and triangle count take "
                       "84) and not an ascii STL (which starts with 'solid'); is this an STL "
                       "file?");
  }
  const std::uint32_t n = le32(80);
  const std::uint64_t need = 84 + 50 * std::uint64_t{n};
  // Bytes after the last triangle are ignored, as CGAL ignores them.
  if (need > bytes.size()) {
    throw InvalidInput(path + ": the binary STL header counts " + std::to_string(n) +
                       " triangles, which take " + std::to_string(need) +
                       " bytes, but the file has " + std::to_string(bytes.size()) +
                       "; it is truncated or not an STL file");
  }
  PolygonSoup soup;
  soup.polygons.reserve(n);
  Corners corners(soup);
  for (std::uint32_t t = 0; t < n; ++t) {
    std::vector<std::size_t> triangle;
    for (std::size_t k = 0; k < 3; ++k) {
      std::array<double, 3> p{};
      for (std::size_t c = 0; c < 3; ++c) {
        const std::uint32_t bits = le32(84 + 50 * std::size_t{t} + 12 * (k + 1) + 4 * c);
        float f = 0;
        std::memcpy(&f, &bits, sizeof f);
        if (!std::isfinite(f)) {
          throw InvalidInput(path + ": triangle " + std::to_string(t) + ", corner " +
                             std::to_string(k) +
                             " has a coordinate that is not a finite number; the file is damaged");
        }
        p[c] = f;
      }
      triangle.push_back(corners.index(p));
    }
    soup.polygons.push_back(std::move(triangle));
  }
  return soup;
}

}  // namespace stl

inline PolygonSoup read_stl(const std::string& path, std::string_view bytes) {
  // CGAL's test (a tab added): the first word, after a byte order mark and blanks, is
  // "solid" followed by a blank or a line end.
  std::size_t first = bytes.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0;
  while (first < bytes.size() && (is_blank(bytes[first]) || bytes[first] == '\n')) ++first;
  if (first == bytes.size()) throw InvalidInput(path + ": the file is empty");
  const std::string_view start = bytes.substr(first, 6);
  const bool solid = start.size() == 6 && start.substr(0, 5) == "solid" &&
                     (start[5] == ' ' || start[5] == '\t' || start[5] == '\n' || start[5] == '\r');
  if (!solid) return stl::read_binary(path, bytes);
  try {
    return stl::read_ascii(path, bytes);
  } catch (const InvalidInput&) {
    // A binary file may start with "solid": read it as one when it holds one, and when it
    // holds a zero byte, which text has not, say what is wrong with it as binary.
    if (bytes.size() >= 84) {
      std::uint32_t n = 0;
      for (int k = 3; k >= 0; --k) n = (n << 8) | static_cast<unsigned char>(bytes[80 + k]);
      if (84 + 50 * std::uint64_t{n} <= bytes.size()) return stl::read_binary(path, bytes);
    }
    if (bytes.find('\0') != std::string_view::npos) return stl::read_binary(path, bytes);
    throw;
  }
}

}  // namespace disktune::detail
