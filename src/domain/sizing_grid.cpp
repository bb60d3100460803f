// SPDX-License-Identifier: GPL-3.0-or-later
// Sizing functions read from a gridded text file (e.g. exported by another tool) and
// bilinearly interpolated between the grid's nodes.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "disktune/errors.h"
#include "../io/word_lines.h"
#include "disktune/sizing.h"

namespace disktune {
namespace {

// A grid's nodes: values[j * nx + i] at (x0 + i dx, y0 + j dy).
struct Grid {
  long long nx = 0, ny = 0;
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  std::vector<double> values;

  double operator()(Vec2 p) const {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return std::numeric_limits<double>::quiet_NaN();
    const auto [i, fx] = locate(p.x, x0, x1, nx);
    const auto [j, fy] = locate(p.y, y0, y1, ny);
    const double* row0 = &values[static_cast<std::size_t>(j * nx + i)];
    const double* row1 = row0 + nx;
    const double bottom = row0[0] + fx * (row0[1] - row0[0]);
    const double top = row1[0] + fx * (row1[1] - row1[0]);
    return bottom + fy * (top - bottom);
  }

  // The cell index along one axis and the fraction within it; outside the grid the
  // point is clamped to its edge, so r continues constant there.
  static std::pair<long long, double> locate(double v, double lo, double hi, long long n) {
    const double u = std::clamp((v - lo) / (hi - lo) * static_cast<double>(n - 1), 0.0,
                                static_cast<double>(n - 1));
    const long long k = std::min(static_cast<long long>(u), n - 2);
    return {k, u - static_cast<double>(k)};
  }
};

constexpr long long kMaxNodes = 100'000'000;  // 800 MB of radii; more is surely a mistake
const char* kFormat =
    "; a sizing grid file is a line 'nx ny x0 y0 x1 y1' (nx, ny >= 2, x0 < x1, y0 < y1), "
    "then ny lines of nx positive radii, row j at y = y0 + j (y1 - y0) / (ny - 1)";

Grid read_grid(std::istream& in, const std::string& path) {
  detail::WordLines reader(in, path);
  std::vector<std::string> words;
  if (!reader.next(words)) reader.fail(std::string("the file has no header line") + kFormat);
  if (words.size() != 6) {
    reader.fail("expected the header 'nx ny x0 y0 x1 y1' (6 numbers), got " +
                std::to_string(words.size()) + " words" + kFormat);
  }
  Grid g;
  g.nx = reader.integer(words[0], "nx");
  g.ny = reader.integer(words[1], "ny");
  g.x0 = reader.number(words[2], "x0");
  g.y0 = reader.number(words[3], "y0");
  g.x1 = reader.number(words[4], "x1");
  g.y1 = reader.number(words[5], "y1");
  if (g.nx < 2 || g.ny < 2) reader.fail("nx and ny must be at least 2" + std::string(kFormat));
  if (g.nx > kMaxNodes / g.ny) {
    reader.fail("nx * ny is above " + std::to_string(kMaxNodes) + " nodes; use a coarser grid");
  }
  if (!(g.x0 < g.x1) || !(g.y0 < g.y1)) {
    reader.fail("the grid's rectangle is empty: x0 < x1 and y0 < y1 are needed" +
                std::string(kFormat));
  }
  // Points are placed by (x - x0) / (x1 - x0): an infinite width made that NaN, and its
  // cell index undefined (found while fuzzing, #17).
  if (!std::isfinite(g.x1 - g.x0) || !std::isfinite(g.y1 - g.y0)) {
    reader.fail("the grid's rectangle is too large: x1 - x0 and y1 - y0 must be finite" +
                std::string(kFormat));
  }
  for (long long j = 0; j < g.ny; ++j) {
    if (!reader.next(words)) {
      reader.fail("the file ends after " + std::to_string(j) +
                  " rows of radii; the header asks for ny = " + std::to_string(g.ny));
    }
    if (static_cast<long long>(words.size()) != g.nx) {
      reader.fail("row " + std::to_string(j) + " has " + std::to_string(words.size()) +
                  (words.size() == 1 ? " radius" : " radii") + "; the header asks for nx = " +
                  std::to_string(g.nx));
    }
    for (const auto& w : words) {
      const double r = reader.number(w, "a radius");
      if (!(r > 0)) reader.fail("radius " + w + " in row " + std::to_string(j) + " is not positive");
      g.values.push_back(r);
    }
  }
  if (reader.next(words)) {
    reader.fail("unexpected content after the " + std::to_string(g.ny) +
                " rows of radii the header asks for");
  }
  return g;
}

}  // namespace

Sizing grid_sizing(const std::string& path) {
  std::ifstream in(path);
  if (!in) {
    throw IoError("cannot read the sizing grid file '" + path +
                  "': check that it exists and is readable");
  }
  auto grid = std::make_shared<const Grid>(read_grid(in, path));
  if (in.bad()) throw IoError("reading the sizing grid file '" + path + "' failed");
  return Sizing([grid](Vec2 p) { return (*grid)(p); }, "grid " + path);
}

}  // namespace disktune
