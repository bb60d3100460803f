// SPDX-License-Identifier: GPL-3.0-or-later
// The edge and vertex indexes of triangle meshes (src/domain/half_edges.h), which the
// surface domain, the mesh check and the restricted Delaunay mesh's mending read: each
// against a plain computation over random triangle sets (manifold or not, dense or
// sparse vertex numbers).
#include "../src/domain/half_edges.h"

#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <random>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

namespace disktune {
namespace {

using Tris = std::vector<std::array<std::size_t, 3>>;

// `count` triangles of three distinct vertices below `vertices`.
Tris random_triangles(std::mt19937& rng, std::size_t count, std::size_t vertices) {
  std::uniform_int_distribution<std::size_t> pick(0, vertices - 1);
  Tris out;
  while (out.size() < count) {
    const std::array<std::size_t, 3> t{pick(rng), pick(rng), pick(rng)};
    if (t[0] != t[1] && t[1] != t[2] && t[2] != t[0]) out.push_back(t);
  }
  return out;
}

TEST(HalfEdges, SortedAsAPlainSortOfEveryTrianglesEdgesWouldBe) {
  std::mt19937 rng(7);
  for (int round = 0; round < 200; ++round) {
    // Few vertices (edges in many triangles), many, and far apart (the plain-sort path).
    const std::size_t vertices = round % 3 == 0 ? 6 : round % 3 == 1 ? 300 : 1000000;
    const Tris tris = random_triangles(rng, 1 + round % 97, vertices);
    std::vector<std::tuple<std::size_t, std::size_t, std::size_t, bool>> expected;
    for (std::size_t t = 0; t < tris.size(); ++t)
      for (int k = 0; k < 3; ++k) {
        const std::size_t a = tris[t][k], b = tris[t][(k + 1) % 3];
        expected.emplace_back(std::min(a, b), std::max(a, b), t, a < b);
      }
    std::sort(expected.begin(), expected.end());
    const std::vector<detail::HalfEdge> half = detail::sorted_half_edges(tris);
    ASSERT_EQ(half.size(), expected.size());
    for (std::size_t i = 0; i < half.size(); ++i) {
      EXPECT_EQ(std::make_tuple(half[i].lo, half[i].hi, half[i].tri, half[i].forward), expected[i])
          << "round " << round << ", half-edge " << i;
    }
  }
}

TEST(HalfEdges, VertexTrianglesAndEdgesInThreeAsCountedPlainly) {
  std::mt19937 rng(11);
  int with_three = 0;
  for (int round = 0; round < 200; ++round) {
    const std::size_t vertices = 4 + round % 60;
    const std::vector<std::array<std::uint32_t, 3>> tris = [&] {
      std::vector<std::array<std::uint32_t, 3>> out;
      for (const auto& t : random_triangles(rng, 1 + round % 23, vertices))
        out.push_back({static_cast<std::uint32_t>(t[0]), static_cast<std::uint32_t>(t[1]),
                       static_cast<std::uint32_t>(t[2])});
      return out;
    }();
    const detail::VertexTriangles around = detail::triangles_by_vertex(tris, vertices);
    ASSERT_EQ(around.start.size(), vertices + 1);
    for (std::size_t v = 0; v < vertices; ++v) {
      std::vector<std::size_t> expected;
      for (std::size_t t = 0; t < tris.size(); ++t)
        if (tris[t][0] == v || tris[t][1] == v || tris[t][2] == v) expected.push_back(t);
      const std::vector<std::size_t> got(
          around.by_vertex.begin() + static_cast<std::ptrdiff_t>(around.start[v]),
          around.by_vertex.begin() + static_cast<std::ptrdiff_t>(around.start[v + 1]));
      EXPECT_EQ(got, expected) << "round " << round << ", vertex " << v;
    }
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
    for (const auto& t : tris)
      for (int k = 0; k < 3; ++k) ++uses[std::minmax(t[k], t[(k + 1) % 3])];
    bool three = false;
    for (const auto& [edge, n] : uses) three = three || n >= 3;
    with_three += three;
    EXPECT_EQ(detail::some_edge_in_three(tris, vertices), three) << "round " << round;
  }
  EXPECT_GT(with_three, 20);  // both answers were asked for
  EXPECT_LT(with_three, 180);
}

TEST(HalfEdges, FansAroundAVertexCountedAsPiecesOfItsLink) {
  // Vertex 0 with a closed fan of four triangles (1 2 3 4), then a second fan (5 6 7)
  // touching it only at 0: a bow tie.
  const Tris tris{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 1}, {0, 5, 6}, {0, 6, 7}};
  const std::vector<std::size_t> one{0, 1, 2, 3}, both{0, 1, 2, 3, 4, 5}, apart{0, 2};
  EXPECT_EQ(detail::fan_count(0, one, tris), 1u);
  EXPECT_EQ(detail::fan_count(0, both, tris), 2u);
  EXPECT_EQ(detail::fan_count(0, apart, tris), 2u);  // 1-2 and 3-4 share no vertex
  // The scratch kept between calls does not leak: the same answers again, in any order.
  EXPECT_EQ(detail::fan_count(0, both.data() + 4, 2, tris), 1u);
  EXPECT_EQ(detail::fan_count(0, one, tris), 1u);
}

}  // namespace
}  // namespace disktune
