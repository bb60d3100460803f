// SPDX-License-Identifier: GPL-3.0-or-later
// Internal to polygon_soup.cpp: the OBJ reader. It keeps the vertices ("v x y z [w]", w
// ignored as CGAL 5.5 ignores it) and faces ("f a b c ...", each corner "i", "i/t",
// "i//n" or "i/t/n", negative indices counting back from the latest vertex), and skips
// every other record (vt, vn, g, usemtl, ...) and '#' comments. It refuses what CGAL
// accepted as garbage or failed on without saying why: non-finite coordinates, index 0,
// indices out of range, faces of fewer than 3 corners, lines that are no OBJ record.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "mesh_text.h"
#include "polygon_soup.h"

namespace disktune::detail {

inline PolygonSoup read_obj(const std::string& path, std::string_view bytes) {
  MeshText in(path, bytes);
  PolygonSoup soup;
  std::vector<std::size_t> face_lines;  // to name the line of a face whose index is too large
  // A record's keyword is a word of letters, digits and '_'; anything else is not OBJ.
  const auto is_keyword = [](std::string_view w) {
    for (const char c : w) {
      if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
            c == '_')) {
        return false;
      }
    }
    return true;
  };
  while (!in.at_end()) {
    const std::size_t line = in.line();
    const auto words = words_of(before_comment(in.line_rest()));
    if (words.empty()) continue;
    if (words[0] == "v") {
      const std::string name = "vertex " + std::to_string(soup.points.size()) + " (OBJ index " +
                               std::to_string(soup.points.size() + 1) + ")";
      if (words.size() < 4) {
        in.fail(name + " has " + std::to_string(words.size() - 1) +
                    " coordinates; a 'v' line holds x y z",
                line);
      }
      std::array<double, 3> p{};
      for (std::size_t k = 0; k < 3; ++k) {
        if (!parse_double(words[k + 1], p[k]) || !std::isfinite(p[k])) {
          in.fail(
              name + ": " + in_quotes(words[k + 1]) + " is not a finite number; fix the coordinate",
              line);
        }
      }
      soup.points.push_back(p);
    } else if (words[0] == "f") {
      const std::string name = "face " + std::to_string(soup.polygons.size());
      if (words.size() < 4) {
        in.fail(
            name + " has " + std::to_string(words.size() - 1) + " corners; a face needs at least 3",
            line);
      }
      std::vector<std::size_t> polygon;
      polygon.reserve(words.size() - 1);
      for (std::size_t k = 1; k < words.size(); ++k) {
        // "i/t/n": the vertex index is the part before the first '/'.
        const std::string_view w = words[k].substr(0, words[k].find('/'));
        long long i = 0;
        if (!parse_integer(w, i)) {
          in.fail(name + ": " + in_quotes(words[k]) + " is not a vertex index", line);
        }
        const long long before = static_cast<long long>(soup.points.size());
        if (i == 0) {
          in.fail(name + " names vertex 0; OBJ numbers vertices from 1 (or back from -1)", line);
        }
        if (i < -before) {
          in.fail(name + " names vertex " + std::to_string(i) + ", counting back from the " +
                      std::to_string(before) +
                      " vertices before this line: too far back; fix "
                      "the index",
                  line);
        }
        polygon.push_back(static_cast<std::size_t>(i < 0 ? before + i : i - 1));
      }
      soup.polygons.push_back(std::move(polygon));
      face_lines.push_back(line);
    } else if (!is_keyword(words[0])) {
      in.fail(in_quotes(words[0]) + " starts no OBJ record; is this an OBJ file?", line);
    }
  }
  if (soup.points.empty()) {
    throw InvalidInput(path + ": no vertices ('v' lines); is this an OBJ mesh?");
  }
  if (soup.polygons.empty()) {
    throw InvalidInput(path + ": no faces ('f' lines); disktune needs the mesh's triangles");
  }
  // Faces may name vertices given later in the file: check once all are read.
  const std::size_t n = soup.points.size();
  for (std::size_t f = 0; f < soup.polygons.size(); ++f) {
    for (const std::size_t i : soup.polygons[f]) {
      if (i >= n) {
        in.fail("face " + std::to_string(f) + " names vertex " + std::to_string(i + 1) +
                    ", but the file has " + std::to_string(n) + " vertices (OBJ indices 1 to " +
                    std::to_string(n) + "); fix the index",
                face_lines[f]);
      }
    }
  }
  return soup;
}

}  // namespace disktune::detail
