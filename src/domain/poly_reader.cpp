// SPDX-License-Identifier: GPL-3.0-or-later
// Triangle's .poly format (https://www.cs.cmu.edu/~quake/triangle.poly.html): vertices,
// segments, holes. The segments are chained into loops; the largest loop is the outer
// boundary, every other one must hold a hole point.
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "disktune/errors.h"
#include "disktune/planar_domain.h"
#include "loop_validation.h"
#include "point_text.h"
#include "../io/word_lines.h"

namespace disktune {
namespace {

using detail::point_text;

// The .poly file's lines: WordLines, plus "the next line, with at least `count` words".
class PolyLines : public detail::WordLines {
 public:
  using WordLines::WordLines;

  /// `what` says what was expected.
  std::vector<std::string> expect(std::size_t count, const std::string& what) {
    std::vector<std::string> words;
    if (!next(words)) fail("the file ends where " + what + " was expected");
    if (words.size() < count) fail("expected " + what + ", got too few numbers");
    return words;
  }
};

struct PolyFile {
  long long base = 0;  // the first vertex's number: 0 or 1 in practice
  std::vector<Vec2> vertices;
  std::vector<std::size_t> vertex_line;
  std::vector<std::array<std::size_t, 2>> segments;  // 0-based vertex indices
  std::vector<std::size_t> segment_line;
  std::vector<Vec2> holes;
  std::vector<std::size_t> hole_line;
};

PolyFile parse(PolyLines& lines) {
  PolyFile f;
  auto header = lines.expect(1, "the header 'vertex_count 2 attribute_count marker_flag'");
  const long long n = lines.integer(header[0]);
  if (header.size() > 1 && lines.integer(header[1]) != 2) {
    lines.fail("the dimension must be 2, got " + header[1]);
  }
  if (n == 0) {
    lines.fail(
        "the file lists 0 vertices, which means they are in a separate .node file; "
        "that form is not supported: copy the vertices into the .poly file");
  }
  if (n < 0) lines.fail("the vertex count must be positive, got " + header[0]);
  for (long long i = 0; i < n; ++i) {
    auto w = lines.expect(3, "vertex line 'number x y'");
    const long long id = lines.integer(w[0]);
    if (i == 0) f.base = id;
    if (id != f.base + i) {
      lines.fail("vertex numbers must be consecutive: expected " + std::to_string(f.base + i) +
                 ", got " + w[0]);
    }
    f.vertices.push_back({lines.number(w[1]), lines.number(w[2])});
    f.vertex_line.push_back(lines.line());
  }
  auto seg_header = lines.expect(1, "the segment header 'segment_count marker_flag'");
  const long long m = lines.integer(seg_header[0]);
  if (m < 3) lines.fail("a domain needs at least 3 segments, got " + seg_header[0]);
  for (long long s = 0; s < m; ++s) {
    auto w = lines.expect(3, "segment line 'number vertex vertex'");
    std::array<std::size_t, 2> ends{};
    for (int e = 0; e < 2; ++e) {
      const long long v = lines.integer(w[1 + e]) - f.base;
      if (v < 0 || v >= n) {
        lines.fail("segment " + w[0] + " names vertex " + w[1 + e] + ", but the vertices are " +
                   std::to_string(f.base) + " to " + std::to_string(f.base + n - 1));
      }
      ends[e] = static_cast<std::size_t>(v);
    }
    if (ends[0] == ends[1]) lines.fail("segment " + w[0] + " joins vertex " + w[1] + " to itself");
    f.segments.push_back(ends);
    f.segment_line.push_back(lines.line());
  }
  std::vector<std::string> w;
  if (!lines.next(w)) return f;  // no hole section: no holes
  const long long h = lines.integer(w[0]);
  for (long long i = 0; i < h; ++i) {
    w = lines.expect(3, "hole line 'number x y'");
    f.holes.push_back({lines.number(w[1]), lines.number(w[2])});
    f.hole_line.push_back(lines.line());
  }
  return f;  // regional attributes, if any, are not needed
}

struct Loop {
  std::vector<std::size_t> vertices;  // 0-based
  std::size_t first_line;             // of its first segment
};

// Each vertex must end exactly two segments; walking from segment to segment through
// them then closes every loop.
std::vector<Loop> chain_loops(const PolyFile& f, const PolyLines& lines) {
  const std::size_t none = f.segments.size();
  std::vector<std::array<std::size_t, 2>> at(f.vertices.size(), {none, none});
  for (std::size_t s = 0; s < f.segments.size(); ++s) {
    for (const std::size_t v : f.segments[s]) {
      auto& slot = at[v];
      if (slot[1] != none) {
        lines.fail("vertex " + std::to_string(f.base + static_cast<long long>(v)) +
                       " ends a third segment (the others are on lines " +
                       std::to_string(f.segment_line[slot[0]]) + " and " +
                       std::to_string(f.segment_line[slot[1]]) +
                       "); each vertex must join exactly two segments of one loop",
                   f.segment_line[s]);
      }
      slot[slot[0] == none ? 0 : 1] = s;
    }
  }
  for (std::size_t v = 0; v < at.size(); ++v) {
    const std::string id = std::to_string(f.base + static_cast<long long>(v));
    if (at[v][0] == none) {
      lines.fail("vertex " + id +
                     " is in no segment; every vertex must be a corner of a "
                     "boundary loop: remove it or add its segments",
                 f.vertex_line[v]);
    }
    if (at[v][1] == none) {
      lines.fail("vertex " + id + " ends only one segment (line " +
                     std::to_string(f.segment_line[at[v][0]]) +
                     "), so the boundary is not closed there; each vertex must join exactly "
                     "two segments of one loop",
                 f.vertex_line[v]);
    }
  }
  std::vector<Loop> loops;
  std::vector<bool> used(f.segments.size(), false);
  for (std::size_t first = 0; first < f.segments.size(); ++first) {
    if (used[first]) continue;
    Loop loop{{f.segments[first][0]}, f.segment_line[first]};
    std::size_t s = first, v = f.segments[first][1];
    used[first] = true;
    while (v != loop.vertices.front()) {
      loop.vertices.push_back(v);
      s = at[v][0] == s ? at[v][1] : at[v][0];
      used[s] = true;
      v = f.segments[s][0] == v ? f.segments[s][1] : f.segments[s][0];
    }
    if (loop.vertices.size() < 3) {
      lines.fail("the segments on lines " + std::to_string(loop.first_line) + " and " +
                     std::to_string(f.segment_line[s]) + " join the same two vertices",
                 f.segment_line[s]);
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

std::string describe(const Loop& loop, const PolyFile& f) {
  std::ostringstream out;
  out << "the loop through vertices ";
  for (std::size_t i = 0; i < std::min<std::size_t>(loop.vertices.size(), 4); ++i) {
    out << (i ? ", " : "") << f.base + static_cast<long long>(loop.vertices[i]);
  }
  if (loop.vertices.size() > 4) out << ", ... (" << loop.vertices.size() << " in all)";
  out << ", starting with the segment on line " << loop.first_line;
  return out.str();
}

std::vector<Vec2> positions(const Loop& loop, const PolyFile& f) {
  std::vector<Vec2> out;
  for (const std::size_t v : loop.vertices) out.push_back(f.vertices[v]);
  return out;
}

}  // namespace

PlanarDomain read_poly(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw IoError("cannot open the .poly file " + path + ": check the path and permissions");
  PolyLines lines(in, path);
  const PolyFile f = parse(lines);
  if (in.bad()) throw IoError("reading " + path + " failed");
  std::vector<Loop> loops = chain_loops(f, lines);

  // The outer loop encloses all others, so it has the largest area; the domain checks
  // that it really encloses them. The others keep file order.
  std::vector<double> area;
  for (const Loop& loop : loops) {
    area.push_back(std::abs(detail::twice_signed_area(positions(loop, f))));
  }
  const auto outer = std::max_element(area.begin(), area.end()) - area.begin();
  std::rotate(loops.begin(), loops.begin() + outer, loops.begin() + outer + 1);
  std::vector<std::vector<Vec2>> holes;
  for (std::size_t k = 1; k < loops.size(); ++k) holes.push_back(positions(loops[k], f));

  auto domain = [&]() {
    try {
      return PlanarDomain(positions(loops[0], f), holes);
    } catch (const InvalidInput& e) {
      std::ostringstream msg;  // say which loops of the file the domain's numbers mean
      msg << path << ": " << e.what() << ". Here loop 0 is " << describe(loops[0], f);
      for (std::size_t k = 1; k < std::min<std::size_t>(loops.size(), 6); ++k) {
        msg << "; loop " << k << " is " << describe(loops[k], f);
      }
      msg << (loops.size() > 6 ? "; and so on in file order" : "");
      throw InvalidInput(msg.str());
    }
  }();

  // Triangle clears the region around each hole point: each hole loop needs one, and
  // a point in the domain itself would clear part of it.
  for (std::size_t i = 0; i < f.holes.size(); ++i) {
    if (domain.contains(f.holes[i])) {
      lines.fail("the hole point " + point_text(f.holes[i]) +
                     " lies inside the domain, not in a hole loop; move it into a hole or remove "
                     "it",
                 f.hole_line[i]);
    }
  }
  for (std::size_t k = 1; k < loops.size(); ++k) {
    const auto& loop = domain.loops()[k];
    // The loop's bounding box (plain pairs: C++17 lambdas cannot capture structured
    // bindings, which only g++ accepts).
    const auto x_range =
        std::minmax_element(loop.begin(), loop.end(), [](Vec2 a, Vec2 b) { return a.x < b.x; });
    const auto y_range =
        std::minmax_element(loop.begin(), loop.end(), [](Vec2 a, Vec2 b) { return a.y < b.y; });
    const bool marked = std::any_of(f.holes.begin(), f.holes.end(), [&](Vec2 p) {
      return p.x >= x_range.first->x && p.x <= x_range.second->x && p.y >= y_range.first->y &&
             p.y <= y_range.second->y && detail::inside_loop(p, loop);
    });
    if (!marked) {
      std::ostringstream msg;
      msg << path << ": " << describe(loops[k], f)
          << ", lies inside the outer loop but no hole point lies inside it; list a point "
             "inside every hole in the holes section (an island inside a hole is not supported)";
      throw InvalidInput(msg.str());
    }
  }
  return domain;
}

}  // namespace disktune
