// SPDX-License-Identifier: GPL-3.0-or-later
#include "loop_validation.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <tuple>

#include "disktune/errors.h"
#include "point_text.h"
#include "precision.h"
#include "segment_raster.h"

namespace disktune::detail {
namespace {

int orientation(Vec2 a, Vec2 b, Vec2 c) {
  const double d = cross(b - a, c - a);
  return (d > 0) - (d < 0);
}

bool in_box(Vec2 a, Vec2 b, Vec2 p) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

/// Whether the closed segments ab and cd share a point, and one such point. Collinear
/// overlaps and touching end points count: a boundary must not even touch itself.
bool segments_meet(Vec2 a, Vec2 b, Vec2 c, Vec2 d, Vec2& where) {
  const int o1 = orientation(a, b, c), o2 = orientation(a, b, d);
  const int o3 = orientation(c, d, a), o4 = orientation(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) {
    const Vec2 ab = b - a, cd = d - c;
    where = a + ab * (cross(c - a, cd) / cross(ab, cd));
    return true;
  }
  for (const auto& [o, s, e, p] : {std::tuple{o1, a, b, c}, std::tuple{o2, a, b, d},
                                   std::tuple{o3, c, d, a}, std::tuple{o4, c, d, b}}) {
    if (o == 0 && in_box(s, e, p)) {
      where = p;
      return true;
    }
  }
  return false;
}

struct SegmentRef {
  std::size_t loop, index;
  Vec2 a, b;
};

std::string segment_text(const SegmentRef& s) {
  std::ostringstream out;
  out << "segment " << s.index << " of " << loop_text(s.loop) << ", from " << point_text(s.a)
      << " to " << point_text(s.b);
  return out.str();
}

void check_vertex_counts(const std::vector<std::vector<Vec2>>& loops) {
  for (std::size_t k = 0; k < loops.size(); ++k) {
    if (loops[k].size() < 3) {
      std::ostringstream msg;
      msg << loop_text(k) << " has " << loops[k].size()
          << " vertices; a boundary loop needs at least 3";
      throw InvalidInput(msg.str());
    }
    for (std::size_t i = 0; i < loops[k].size(); ++i) {
      const Vec2 p = loops[k][i];
      if (!(std::isfinite(p.x) && std::isfinite(p.y))) {
        std::ostringstream msg;
        msg << loop_text(k) << ", vertex " << i << ": coordinates must be finite numbers, got "
            << point_text(p);
        throw InvalidInput(msg.str());
      }
    }
  }
}

// Corners so far apart that their difference overflows (x = -1e308 and 1e308) leave the
// grids below no finite cell size, and their cell indices undefined (found while fuzzing,
// #17).
void check_extent(const std::vector<std::vector<Vec2>>& loops) {
  Vec2 lo = loops[0][0], hi = lo;
  for (const auto& loop : loops) {
    for (const Vec2 p : loop) {
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
  }
  if (!std::isfinite(hi.x - lo.x) || !std::isfinite(hi.y - lo.y)) {
    std::ostringstream msg;
    msg << "the corners span from " << point_text(lo) << " to " << point_text(hi)
        << ", farther than a double can measure; scale the coordinates down";
    throw InvalidInput(msg.str());
  }
}

// Sorting all vertices finds repeats in O(n log n), across loops too.
void check_repeated_vertices(const std::vector<std::vector<Vec2>>& loops) {
  struct Entry {
    Vec2 p;
    std::size_t loop, index;
  };
  std::vector<Entry> all;
  for (std::size_t k = 0; k < loops.size(); ++k) {
    for (std::size_t i = 0; i < loops[k].size(); ++i) all.push_back({loops[k][i], k, i});
  }
  std::sort(all.begin(), all.end(), [](const Entry& u, const Entry& v) {
    return std::tie(u.p.x, u.p.y, u.loop, u.index) < std::tie(v.p.x, v.p.y, v.loop, v.index);
  });
  for (std::size_t i = 1; i < all.size(); ++i) {
    if (all[i].p == all[i - 1].p) {
      std::ostringstream msg;
      msg << loop_text(all[i - 1].loop) << ", vertex " << all[i - 1].index << ", and "
          << loop_text(all[i].loop) << ", vertex " << all[i].index << ", are the same point "
          << point_text(all[i].p) << "; each corner must appear once: remove the repeat";
      throw InvalidInput(msg.str());
    }
  }
}

// Consecutive segments share a vertex; they meet elsewhere only when the loop doubles
// back along a line there (a zero-angle spike).
void check_spikes(const std::vector<std::vector<Vec2>>& loops) {
  for (std::size_t k = 0; k < loops.size(); ++k) {
    const auto& loop = loops[k];
    const std::size_t n = loop.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 prev = loop[(i + n - 1) % n], here = loop[i], next = loop[(i + 1) % n];
      const Vec2 u = here - prev, v = next - here;
      if (cross(u, v) == 0 && dot(u, v) < 0) {
        std::ostringstream msg;
        msg << loop_text(k) << " turns back on itself at vertex " << i << ' ' << point_text(here)
            << ": segments " << (i + n - 1) % n << " and " << i
            << " overlap; remove the vertex or move it off the line";
        throw InvalidInput(msg.str());
      }
    }
  }
}

// Segments are binned in a sparse uniform grid and only segments sharing a cell are
// compared. The cell side is their mean length, so each lands in a few cells, but no
// more than the side of n equal cells over the box: long zigzags must not pile up.
void check_intersections(const std::vector<std::vector<Vec2>>& loops) {
  std::vector<SegmentRef> segs;
  Vec2 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  Vec2 hi = lo * -1.0;
  double total_length = 0;
  for (std::size_t k = 0; k < loops.size(); ++k) {
    const std::size_t n = loops[k].size();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 a = loops[k][i], b = loops[k][(i + 1) % n];
      segs.push_back({k, i, a, b});
      total_length += distance(a, b);
      lo = {std::min(lo.x, a.x), std::min(lo.y, a.y)};
      hi = {std::max(hi.x, a.x), std::max(hi.y, a.y)};
    }
  }
  CellSpec grid;
  grid.origin = lo;
  const double n = static_cast<double>(segs.size());
  // No smaller than the box's longer side / n either, so nx, ny <= n + 1: with the square
  // root alone, a box 1 wide and 7.7e121 long got 1.8e61 rows, more than an int64 holds
  // (found while fuzzing, #17).
  grid.h = std::max(std::min(total_length / n, std::sqrt((hi.x - lo.x) * (hi.y - lo.y) / n)),
                    std::max(hi.x - lo.x, hi.y - lo.y) / n);
  grid.nx = static_cast<std::int64_t>((hi.x - lo.x) / grid.h) + 1;
  grid.ny = static_cast<std::int64_t>((hi.y - lo.y) / grid.h) + 1;
  const double pad = 1e-9 * grid.h;

  std::vector<std::pair<std::uint64_t, std::uint32_t>> binned;
  binned.reserve(4 * segs.size());
  for (std::size_t s = 0; s < segs.size(); ++s) {
    for_cells_of_segment(grid, segs[s].a, segs[s].b, pad, [&](std::int64_t i, std::int64_t j) {
      binned.emplace_back(static_cast<std::uint64_t>(j * grid.nx + i),
                          static_cast<std::uint32_t>(s));
    });
  }
  std::sort(binned.begin(), binned.end());

  auto adjacent = [&](const SegmentRef& u, const SegmentRef& v) {
    if (u.loop != v.loop) return false;
    const std::size_t n = loops[u.loop].size();
    return (u.index + 1) % n == v.index || (v.index + 1) % n == u.index;
  };
  // Keep the first offending pair in input order, so the message does not depend on
  // the grid.
  std::pair<std::size_t, std::size_t> worst{segs.size(), segs.size()};
  Vec2 worst_at{0, 0};
  for (std::size_t g = 0; g < binned.size();) {
    std::size_t end = g;
    while (end < binned.size() && binned[end].first == binned[g].first) ++end;
    for (std::size_t u = g; u < end; ++u) {
      for (std::size_t v = u + 1; v < end; ++v) {
        const std::size_t s = binned[u].second, t = binned[v].second;  // s < t: sorted
        if (std::pair{s, t} >= worst || adjacent(segs[s], segs[t])) continue;
        Vec2 at;
        if (segments_meet(segs[s].a, segs[s].b, segs[t].a, segs[t].b, at)) {
          worst = {s, t};
          worst_at = at;
        }
      }
    }
    g = end;
  }
  if (worst.first < segs.size()) {
    std::ostringstream msg;
    msg << segment_text(segs[worst.first]) << ", meets " << segment_text(segs[worst.second])
        << ", at " << point_text(worst_at)
        << "; boundary loops must not cross or touch themselves or each other";
    throw InvalidInput(msg.str());
  }
}

// Segments no longer meet, so one vertex of a hole tells on which side of every other
// loop the whole hole lies. Bounding boxes skip most point-in-polygon tests.
void check_nesting(const std::vector<std::vector<Vec2>>& loops) {
  struct Box {
    Vec2 lo, hi;
  };
  std::vector<Box> boxes;
  for (const auto& loop : loops) {
    Box b{loop[0], loop[0]};
    for (const Vec2 p : loop) {
      b.lo = {std::min(b.lo.x, p.x), std::min(b.lo.y, p.y)};
      b.hi = {std::max(b.hi.x, p.x), std::max(b.hi.y, p.y)};
    }
    boxes.push_back(b);
  }
  for (std::size_t k = 1; k < loops.size(); ++k) {
    const Vec2 p = loops[k][0];
    if (!inside_loop(p, loops[0])) {
      std::ostringstream msg;
      msg << loop_text(k) << " is not inside the outer boundary (loop 0): its vertex 0 "
          << point_text(p) << " lies outside loop 0; every hole must lie inside the outer loop";
      throw InvalidInput(msg.str());
    }
    for (std::size_t m = 1; m < loops.size(); ++m) {
      const Box& b = boxes[m];
      if (m == k || p.x < b.lo.x || p.x > b.hi.x || p.y < b.lo.y || p.y > b.hi.y) continue;
      if (inside_loop(p, loops[m])) {
        std::ostringstream msg;
        msg << loop_text(k) << " lies inside " << loop_text(m) << ": its vertex 0 " << point_text(p)
            << " is in that hole; holes must not be nested, remove one";
        throw InvalidInput(msg.str());
      }
    }
  }
}

}  // namespace

double twice_signed_area(const std::vector<Vec2>& loop) {
  double sum = 0;  // relative to the first vertex, for accuracy far from the origin
  for (std::size_t i = 1; i + 1 < loop.size(); ++i) {
    sum += cross(loop[i] - loop[0], loop[i + 1] - loop[0]);
  }
  return sum;
}

bool inside_loop(Vec2 p, const std::vector<Vec2>& loop) {
  bool inside = false;
  const std::size_t n = loop.size();
  for (std::size_t i = 0; i < n; ++i) {
    Vec2 a = loop[i], b = loop[(i + 1) % n];
    if ((a.y > p.y) == (b.y > p.y)) continue;  // half-open: each crossing counted once
    if (a.y > b.y) std::swap(a, b);
    if (orientation(a, b, p) > 0) inside = !inside;  // the crossing is right of p
  }
  return inside;
}

// Geometry a domain's own size apart must be exact where the domain lies.
static void check_precision(const std::vector<std::vector<Vec2>>& loops) {
  Vec2 lo = loops[0][0], hi = lo;
  for (const auto& loop : loops) {
    for (const Vec2 p : loop) {
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
  }
  const double size = std::max(hi.x - lo.x, hi.y - lo.y);
  const double reach = std::max({std::abs(lo.x), std::abs(lo.y), std::abs(hi.x), std::abs(hi.y)});
  std::ostringstream what;
  what << "its size " << size;
  if (size > 0) check_coordinates_for_scale(reach, size, what.str());
}

void validate_loops(const std::vector<std::vector<Vec2>>& loops) {
  if (loops.empty()) throw InvalidInput("a planar domain needs an outer boundary loop");
  check_vertex_counts(loops);
  check_extent(loops);
  check_precision(loops);
  check_repeated_vertices(loops);
  check_spikes(loops);
  check_intersections(loops);
  for (std::size_t k = 0; k < loops.size(); ++k) {
    if (twice_signed_area(loops[k]) == 0) {
      std::ostringstream msg;
      msg << loop_text(k) << " encloses no area; check its vertices";
      throw InvalidInput(msg.str());
    }
  }
  check_nesting(loops);
}

}  // namespace disktune::detail
