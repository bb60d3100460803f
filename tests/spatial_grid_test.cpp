// SPDX-License-Identifier: GPL-3.0-or-later
// The neighbour grid against a brute force over every disk and every periodic image:
// bounded frames with centers outside them, crowded cells, removals, and disks at
// exactly the query distance.
#include "disktune/spatial_grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iterator>
#include <map>
#include <set>
#include <tuple>
#include <vector>

#include "disktune/random.h"

namespace disktune {
namespace {

using Hit = std::tuple<DiskId, long, long>;  // id and image offset in whole periods

struct Registered {
  std::map<DiskId, Vec2> centers;  // as given to insert
};

std::set<Hit> brute_near(const Registered& reg, const Frame& f, Vec2 q, double R) {
  std::set<Hit> out;
  const int k =
      f.periodic ? static_cast<int>(std::ceil(R / std::min(f.extent.x, f.extent.y))) + 2 : 0;
  for (const auto& [id, c] : reg.centers) {
    for (int a = -k; a <= k; ++a) {
      for (int b = -k; b <= k; ++b) {
        const Vec2 im = c + Vec2{a * f.extent.x, b * f.extent.y};
        if (squared_distance(im, q) <= R * R) out.insert({id, a, b});
      }
    }
  }
  return out;
}

std::set<Hit> grid_near(const SpatialGrid& g, const Registered& reg, const Frame& f, Vec2 q,
                        double R) {
  std::set<Hit> out;
  g.for_each_near(q, R, [&](const Neighbor& n) {
    const Vec2 c = reg.centers.at(n.id);
    const Vec2 off = n.image - c;
    const Hit hit{n.id, std::lround(off.x / f.extent.x), std::lround(off.y / f.extent.y)};
    EXPECT_TRUE(out.insert(hit).second) << "image reported twice";
    EXPECT_EQ(n.d2, squared_distance(n.image, q));
    EXPECT_LE(n.d2, R * R);
  });
  return out;
}

// A bounded frame away from the origin: centers inside, on its edges and outside it
// (the grid clamps those into its border cells); queries inside and far outside.
TEST(SpatialGrid, BoundedFrameQueriesMatchBruteForceWithCentersOutside) {
  const Frame f{{-3.7, 2.1}, {2.3, 1.4}, false};
  for (const double cell : {0.05, 0.13, 0.9}) {
    SpatialGrid g(f, cell);
    Registered reg;
    Rng rng(11);
    for (DiskId id = 0; id < 400; ++id) {
      const Vec2 c{f.origin.x + (uniform01(rng) * 1.4 - 0.2) * f.extent.x,
                   f.origin.y + (uniform01(rng) * 1.4 - 0.2) * f.extent.y};
      g.insert(id, c, cell), reg.centers[id] = c;
    }
    for (int t = 0; t < 400; ++t) {
      const Vec2 q{f.origin.x + (uniform01(rng) * 1.8 - 0.4) * f.extent.x,
                   f.origin.y + (uniform01(rng) * 1.8 - 0.4) * f.extent.y};
      const double R = uniform01(rng) * 6 * cell;
      ASSERT_EQ(grid_near(g, reg, f, q, R), brute_near(reg, f, q, R))
          << "cell " << cell << " query " << t;
    }
  }
}

// Many disks per cell make the grid grow; removals leave empty slots behind, which no
// query may report.
TEST(SpatialGrid, CrowdedCellsAndRemovalsMatchBruteForce) {
  const Frame f{{0, 0}, {1.5, 0.8}, true};
  SpatialGrid g(f, 0.1);
  Registered reg;
  Rng rng(5);
  DiskId next = 0;
  for (int step = 0; step < 3000; ++step) {
    if (!reg.centers.empty() && uniform01(rng) < 0.4) {
      auto it = reg.centers.begin();
      std::advance(it, uniform_index(rng, reg.centers.size()));
      g.remove(it->first, it->second), reg.centers.erase(it);
    } else {
      // Half the disks crowd into a small spot.
      const Vec2 c = uniform01(rng) < 0.5
                         ? Vec2{0.72 + 0.03 * uniform01(rng), 0.41 + 0.03 * uniform01(rng)}
                         : f.wrap({uniform01(rng) * 1.5, uniform01(rng) * 0.8});
      g.insert(next, c, 0.1), reg.centers[next++] = c;
    }
    if (step % 10 == 0) {
      const Vec2 q{uniform01(rng) * 4.5 - 1.5, uniform01(rng) * 2.4 - 0.8};
      const double R = uniform01(rng) * (step % 100 == 0 ? 2.0 : 0.35);  // some beyond a period
      ASSERT_EQ(grid_near(g, reg, f, q, R), brute_near(reg, f, q, R)) << "step " << step;
    }
  }
}

// Centers on the grid's lines and query points at exactly the query distance from them
// (3-4-5 triangles in cell units, so every distance is exact): all are reported.
TEST(SpatialGrid, DisksAtExactlyTheQueryDistanceAreFound) {
  for (const bool periodic : {true, false}) {
    const Frame f{{0, 0}, {1, 1}, periodic};
    const double h = 1.0 / 64;  // the cells' width too
    SpatialGrid g(f, h);
    Registered reg;
    DiskId id = 0;
    for (int i = 0; i < 64; i += 3) {
      for (int j = 0; j < 64; j += 5) {
        const Vec2 c{i * h, j * h};
        g.insert(id, c, h), reg.centers[id++] = c;
      }
    }
    for (int i = 0; i < 64; i += 7) {
      for (int j = 0; j < 64; j += 4) {
        for (const double R : {3 * h, 5 * h, 10 * h, 0.5}) {
          const Vec2 q{i * h, j * h};
          const auto want = brute_near(reg, f, q, R);
          ASSERT_EQ(grid_near(g, reg, f, q, R), want)
              << periodic << " " << i << " " << j << " " << R;
        }
      }
    }
  }
}

// any_near visits the neighbours in for_each_near's order and stops at the first the
// predicate accepts.
TEST(SpatialGrid, AnyNearStopsAtTheFirstAcceptedNeighbourInOrder) {
  const Frame f{{0, 0}, {1, 1}, true};
  SpatialGrid g(f, 0.05);
  Rng rng(3);
  for (DiskId id = 0; id < 300; ++id) g.insert(id, {uniform01(rng), uniform01(rng)}, 0.05);
  for (int t = 0; t < 100; ++t) {
    const Vec2 q{uniform01(rng), uniform01(rng)};
    std::vector<DiskId> all;
    g.for_each_near(q, 0.2, [&](const Neighbor& n) { all.push_back(n.id); });
    ASSERT_FALSE(all.empty());
    const std::size_t stop = uniform_index(rng, all.size());
    std::vector<DiskId> seen;
    const bool found = g.any_near(q, 0.2, [&](const Neighbor& n) {
      seen.push_back(n.id);
      return seen.size() == stop + 1;
    });
    EXPECT_TRUE(found);
    EXPECT_EQ(seen, std::vector<DiskId>(all.begin(), all.begin() + stop + 1));
    EXPECT_FALSE(g.any_near(q, 0.2, [](const Neighbor&) { return false; }));
  }
}

}  // namespace
}  // namespace disktune
