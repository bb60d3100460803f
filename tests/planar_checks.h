// SPDX-License-Identifier: GPL-3.0-or-later
// Checks of planar-domain meshes shared by the tests, written apart from the library:
// the oracle's even-odd test and shoelace area, and plain segment geometry.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "disktune/mesh.h"
#include "disktune/packing.h"
#include "disktune/planar_domain.h"
#include "oracle/planar_oracle.h"

namespace disktune::test {

/// The domain as the oracle sees it: plain coordinates.
inline oracle::Domain oracle_domain(const PlanarDomain& d) {
  oracle::Domain out;
  for (const auto& loop : d.loops()) {
    out.loops.emplace_back();
    for (const Vec2 v : loop) out.loops.back().push_back({v.x, v.y});
  }
  return out;
}

/// The independent oracle's verdict on a packing in a planar domain: each disk with its
/// own radius, its boundary flag as the packing marks it.
inline oracle::PlanarReport check_with_oracle(const Packing& p, const PlanarDomain& d) {
  oracle::Points centers;
  std::vector<double> radii;
  oracle::PlanarOptions opt;
  for (const DiskId id : p.ids()) {
    centers.push_back({p.center(id).x, p.center(id).y});
    radii.push_back(p.radius(id));
    opt.boundary_flags.push_back((p.flags(id) & kFixed) != 0);
  }
  return oracle::check_planar(oracle_domain(d), centers, radii, opt);
}

/// The mesh must tile the domain exactly: triangle areas sum to the shoelace area
/// (1e-9 relative), every triangle counterclockwise with its centroid inside, and every
/// boundary segment made of mesh edges (vertices within `on` of the segment count).
inline void expect_mesh_tiles(const PlanarMesh& mesh, const oracle::Domain& od, double on) {
  double area = 0;
  std::size_t outside = 0, flipped = 0;
  for (const auto& t : mesh.triangles) {
    const Vec2 a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
    const double twice = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    flipped += twice <= 0;
    area += twice / 2;
    const Vec2 g = (a + b + c) * (1.0 / 3);
    outside += !oracle::even_odd_inside(od, g.x, g.y);
  }
  const double expected = oracle::domain_area(od);
  EXPECT_NEAR(area, expected, 1e-9 * expected);
  EXPECT_EQ(flipped, 0u) << "triangles not counterclockwise";
  EXPECT_EQ(outside, 0u) << "triangle centroids outside the domain";

  // Mesh edges, each once.
  std::vector<std::array<std::uint32_t, 2>> edges;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) edges.push_back({std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])});
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::size_t bare_segments = 0;
  for (const auto& loop : od.loops)
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const Vec2 a{loop[k][0], loop[k][1]}, b{loop[(k + 1) % loop.size()][0], loop[(k + 1) % loop.size()][1]};
      const Vec2 ab = b - a;
      const double len2 = squared_norm(ab);
      auto param = [&](Vec2 p, double& t) {  // t of p along ab, if p lies on the segment
        t = dot(p - a, ab) / len2;
        return t >= -1e-9 && t <= 1 + 1e-9 && distance(p, a + ab * t) <= on;
      };
      std::vector<std::array<double, 2>> cover;
      for (const auto& e : edges) {
        double t0, t1;
        if (param(mesh.vertices[e[0]], t0) && param(mesh.vertices[e[1]], t1))
          cover.push_back({std::min(t0, t1), std::max(t0, t1)});
      }
      std::sort(cover.begin(), cover.end());
      double done = 0;
      bool gap = false;
      for (const auto& iv : cover) {
        gap |= iv[0] > done + 1e-9;
        done = std::max(done, iv[1]);
      }
      gap |= done < 1 - 1e-9;
      if (gap) {
        ++bare_segments;
        ADD_FAILURE() << "segment " << k << " of a loop from (" << a.x << ", " << a.y << ") to (" << b.x
                      << ", " << b.y << ") is not covered by mesh edges";
      }
    }
  EXPECT_EQ(bare_segments, 0u);
}

}  // namespace disktune::test
