// SPDX-License-Identifier: GPL-3.0-or-later
// Internal to polygon_soup.cpp: the OFF reader. It reads what CGAL 5.5's OFF reader read,
// to the same points and faces: '#' comments before and between records, the keyword
// with its prefixes (ST, C, N, 4, n: COFF, NOFF, 4OFF, ...), the counts, then one vertex
// and one face per line, extra numbers on a line (colours, normals) ignored. Unlike
// CGAL's it checks the counts against the file size before allocating, and refuses
// non-finite coordinates, faces of fewer than 3 corners and indices out of range, naming
// the line.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "mesh_text.h"
#include "polygon_soup.h"

namespace disktune::detail {

inline PolygonSoup read_off(const std::string& path, std::string_view bytes) {
  MeshText in(path, bytes);
  in.skip_space_and_comments();
  if (in.at_end()) in.fail("the file is empty; an OFF file starts with the keyword OFF");

  // The keyword: optional prefixes ST (texture), C (colour), N (normal), 4 (homogeneous
  // coordinates), n (a dimension before the counts), then OFF.
  const std::string_view keyword = in.alnum_word();
  std::size_t j = 0;
  const auto prefix = [&](std::string_view p) {
    const bool has = keyword.substr(j, p.size()) == p;
    if (has) j += p.size();
    return has;
  };
  prefix("ST");
  prefix("C");
  prefix("N");
  const bool homogeneous = prefix("4");
  const bool dimensional = prefix("n");
  if (keyword.substr(j) == "SKEL") {
    in.fail("a SKEL file holds a skeleton (lines), not a surface; give a mesh in OFF");
  }
  if (keyword.empty() || keyword.substr(j) != "OFF") {
    in.fail("expected the keyword OFF (or a variant such as COFF, NOFF, 4OFF), found " +
            in_quotes(keyword.empty() ? in.word() : keyword) + "; is this an OFF file?");
  }
  in.skip_space_and_comments();
  if (in.peek() == 'B' && bytes.substr(in.position(), 6) == "BINARY") {
    in.fail("binary OFF is not supported; save the mesh as text OFF (or PLY)");
  }

  // The counts (the edge count is required, as by CGAL, and not used).
  std::size_t counts_line = 0;
  const auto too_large = [](std::string_view w) {
    return w.size() > 18 && w.find_first_not_of("+0123456789") == std::string_view::npos;
  };
  const auto count = [&](const char* what) -> std::uint64_t {
    in.skip_space_and_comments();
    if (!counts_line) counts_line = in.line();
    const std::string_view w = in.word();
    if (w.empty()) {
      in.fail(std::string("the file ends before the ") + what +
              "; an OFF header gives the numbers of vertices, faces and edges");
    }
    long long v = 0;
    if (!parse_integer(w, v) || v < 0) {
      in.fail(std::string("expected the ") + what + ", a whole number of 0 or more, found " +
              in_quotes(w) + (too_large(w) ? " (too large)" : "") +
              "; the header gives the numbers of vertices, faces and edges");
    }
    return static_cast<std::uint64_t>(v);
  };
  if (dimensional) {
    const std::uint64_t dimension = count("dimension");
    if (dimension < 3) {
      in.fail("the vertices have dimension " + std::to_string(dimension) +
              "; disktune reads meshes in 3D");
    }
  }
  const std::uint64_t nv = count("number of vertices");
  const std::uint64_t nf = count("number of faces");
  count("number of edges");

  // Each vertex line holds at least "x y z\n", each face line "3 a b c\n" (the last line
  // may lack its line end): refuse counts the file cannot hold before reserving room.
  const std::uint64_t need = add_product(add_product(0, nv, 6), nf, 8);
  if (need > 0 && need - 1 > in.bytes_left()) {
    in.fail("the header promises " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
                " faces, which take at least " + std::to_string(need - 1) + " bytes, but only " +
                std::to_string(in.bytes_left()) +
                " bytes follow; the counts are wrong or the file is truncated",
            counts_line);
  }

  PolygonSoup soup;
  soup.points.reserve(nv);
  soup.polygons.reserve(nf);
  const std::size_t coordinates = homogeneous ? 4 : 3;
  for (std::uint64_t v = 0; v < nv; ++v) {
    in.skip_space_and_comments();
    if (in.at_end()) {
      in.fail("the file ends after " + std::to_string(v) + " of the " + std::to_string(nv) +
              " vertices the header promises; it is truncated or the count is wrong");
    }
    const std::size_t line = in.line();
    const auto words = words_of(before_comment(in.line_rest()));
    const std::string name = "vertex " + std::to_string(v);
    double c[4] = {0, 0, 0, 1};
    for (std::size_t k = 0; k < coordinates; ++k) {
      if (k >= words.size()) {
        in.fail(name + " has " + std::to_string(words.size()) + " numbers; a vertex line holds " +
                    (homogeneous ? "x y z w" : "x y z") + " (is the vertex count right?)",
                line);
      }
      if (!parse_double(words[k], c[k]) || !std::isfinite(c[k])) {
        in.fail(name + ": " + in_quotes(words[k]) + " is not a finite number; fix the coordinate",
                line);
      }
    }
    // CGAL divides by w (1 unless homogeneous): the same operation, the same doubles.
    const std::array<double, 3> p = {c[0] / c[3], c[1] / c[3], c[2] / c[3]};
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
      in.fail(name + " has the homogeneous coordinate w = " + in_quotes(words[3]) +
                  ", which puts it at no finite point; fix w",
              line);
    }
    soup.points.push_back(p);
  }

  for (std::uint64_t f = 0; f < nf; ++f) {
    in.skip_space_and_comments();
    if (in.at_end()) {
      in.fail("the file ends after " + std::to_string(f) + " of the " + std::to_string(nf) +
              " faces the header promises; it is truncated or the count is wrong");
    }
    const std::size_t line = in.line();
    const auto words = words_of(before_comment(in.line_rest()));
    const std::string name = "face " + std::to_string(f);
    long long corners = 0;
    if (words.empty() || !parse_index(words[0], corners)) {
      in.fail(name + " starts with " + in_quotes(words.empty() ? "" : words[0]) +
                  ", not its number of corners (is the vertex count right?)",
              line);
    }
    if (corners < 3) {
      in.fail(name + " has " + std::to_string(corners) + " corners; a face needs at least 3", line);
    }
    // The line is in memory already: comparing with its words allocates nothing.
    if (static_cast<unsigned long long>(corners) > words.size() - 1) {
      in.fail(name + " declares " + std::to_string(corners) + " corners but lists " +
                  std::to_string(words.size() - 1) +
                  " vertex indices; fix the count at the start of the line",
              line);
    }
    std::vector<std::size_t> polygon;
    polygon.reserve(static_cast<std::size_t>(corners));
    for (long long k = 1; k <= corners; ++k) {
      const std::string_view w = words[static_cast<std::size_t>(k)];
      long long index = 0;
      if (!parse_index(w, index)) {
        in.fail(name + ": " + in_quotes(w) + " is not a vertex index", line);
      }
      if (index < 0 || static_cast<unsigned long long>(index) >= nv) {
        in.fail(name + " names vertex " + std::to_string(index) + ", but the file has " +
                    vertex_range(nv) + "; fix the index or the vertex count in the header",
                line);
      }
      polygon.push_back(static_cast<std::size_t>(index));
    }
    soup.polygons.push_back(std::move(polygon));
  }
  return soup;
}

}  // namespace disktune::detail
