// SPDX-License-Identifier: GPL-3.0-or-later
// A brute-force periodic Delaunay triangulation for tests, written apart from the
// library and using none of its code: every triple of periodic images near a point
// whose circumcircle holds no image of any point strictly inside. O(N^4)-ish: for a few
// hundred points at most, in general position (no four cocircular points).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <vector>

namespace disktune::test {

inline constexpr double kBrutePi = 3.14159265358979323846;

/// A periodic image of point `index`: its position plus (ox * W, oy * H).
struct Image {
  int index, ox, oy;
  bool operator<(const Image& o) const {
    return index != o.index ? index < o.index : ox != o.ox ? ox < o.ox : oy < o.oy;
  }
  bool operator==(const Image& o) const { return index == o.index && ox == o.ox && oy == o.oy; }
};

/// A torus triangle named independently of its copy: its three images sorted, then
/// translated so that the first has offset (0, 0).
using TriangleKey = std::array<Image, 3>;

inline TriangleKey triangle_key(std::array<Image, 3> t) {
  std::sort(t.begin(), t.end());  // translation does not change the order of images
  const int ox = t[0].ox, oy = t[0].oy;
  for (Image& im : t) im.ox -= ox, im.oy -= oy;
  return t;
}

struct BrutePoint {
  double x, y;
};

struct BruteTriangle {
  std::array<BrutePoint, 3> corners;  // counterclockwise, unwrapped
  TriangleKey key;
};

/// Every torus Delaunay triangle once. `reach` bounds the edge length searched; the
/// caller checks completeness (the areas must sum to W * H).
inline std::vector<BruteTriangle> brute_periodic_delaunay(const std::vector<BrutePoint>& pts,
                                                          double W, double H, double reach) {
  std::vector<BrutePoint> pos;
  std::vector<Image> img;
  const int span = 1 + static_cast<int>(std::ceil(reach / std::min(W, H)));
  for (int i = 0; i < static_cast<int>(pts.size()); ++i) {
    for (int oy = -span; oy <= span; ++oy) {
      for (int ox = -span; ox <= span; ++ox) {
        pos.push_back({pts[i].x + ox * W, pts[i].y + oy * H});
        img.push_back({i, ox, oy});
      }
    }
  }
  std::set<TriangleKey> seen;
  std::vector<BruteTriangle> out;
  for (int i = 0; i < static_cast<int>(pts.size()); ++i) {
    const BrutePoint a = pts[i];
    std::vector<int> near;
    for (int k = 0; k < static_cast<int>(pos.size()); ++k) {
      const double dx = pos[k].x - a.x, dy = pos[k].y - a.y;
      if (!(img[k].index == i && img[k].ox == 0 && img[k].oy == 0) &&
          dx * dx + dy * dy <= reach * reach) {
        near.push_back(k);
      }
    }
    for (int u : near) {
      for (int v : near) {
        const BrutePoint b = pos[u], c = pos[v];
        const double bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y;
        const double cross = bx * cy - by * cx;
        if (cross <= 0) continue;  // counterclockwise triples only
        const TriangleKey key = triangle_key({Image{i, 0, 0}, img[u], img[v]});
        if (seen.count(key)) continue;
        const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
        const double ux = (cy * b2 - by * c2) / (2 * cross);
        const double uy = (bx * c2 - cx * b2) / (2 * cross);
        const double rho2 = ux * ux + uy * uy;
        bool empty = true;
        for (std::size_t k = 0; k < pos.size() && empty; ++k) {
          const double dx = pos[k].x - (a.x + ux), dy = pos[k].y - (a.y + uy);
          empty = dx * dx + dy * dy >= rho2 * (1 - 1e-9);
        }
        if (!empty) continue;
        seen.insert(key);
        out.push_back({{a, b, c}, key});
      }
    }
  }
  return out;
}

/// The three angles of a triangle in degrees, by the law of cosines (the library
/// uses a different formula).
inline std::array<double, 3> brute_angles_degrees(const std::array<BrutePoint, 3>& t) {
  std::array<double, 3> out;
  for (int k = 0; k < 3; ++k) {
    const BrutePoint p = t[k], q = t[(k + 1) % 3], s = t[(k + 2) % 3];
    const double a2 = (q.x - s.x) * (q.x - s.x) + (q.y - s.y) * (q.y - s.y);
    const double b2 = (p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y);
    const double c2 = (p.x - s.x) * (p.x - s.x) + (p.y - s.y) * (p.y - s.y);
    out[k] = std::acos((b2 + c2 - a2) / (2 * std::sqrt(b2 * c2))) * 180 / kBrutePi;
  }
  return out;
}

}  // namespace disktune::test
