// SPDX-License-Identifier: GPL-3.0-or-later
// cell_inside (src/voids/surface_cell.h), the quick test of a relaxation move: where it
// says a disk's cell lies in the ball at x, every probe of the surface that only that disk
// covers, and every probe nearer to it than to any other disk counting there, must lie
// in that ball; and a DiskCell asked of three places in turn answers as cell_inside. Probes are a
// barycentric grid and random points on every triangle near the disk, the patches are the test's
// own (surface_checks.h), distances plain geometry.
#include "../src/voids/surface_cell.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "disktune/surface_features.h"
#include "disktune/surface_sampling.h"
#include "disktune/surface_sizing.h"
#include "surface_checks.h"

namespace disktune {
namespace {

struct Probe {
  Vec3 at;
  std::size_t patch;
};

// Probes on every triangle with a corner within `reach` of c (a triangle meeting the
// ball around c of radius `ball` has one when reach is ball plus the longest edge).
std::vector<Probe> probes_near(const SurfaceDomain& d, const std::vector<std::size_t>& label,
                               Vec3 c, double reach, std::mt19937_64& gen) {
  std::vector<Probe> out;
  std::uniform_real_distribution<double> u(0, 1);
  for (std::size_t t = 0; t < d.triangles().size(); ++t) {
    const Vec3 a = d.vertices()[d.triangles()[t][0]], b = d.vertices()[d.triangles()[t][1]],
               e = d.vertices()[d.triangles()[t][2]];
    if (squared_norm(a - c) > reach * reach && squared_norm(b - c) > reach * reach &&
        squared_norm(e - c) > reach * reach)
      continue;
    constexpr int kSteps = 16;
    for (int i = 0; i <= kSteps; ++i)
      for (int j = 0; i + j <= kSteps; ++j)
        out.push_back(
            {a + (b - a) * (double(i) / kSteps) + (e - a) * (double(j) / kSteps), label[t]});
    for (int k = 0; k < 60; ++k) {
      double s = u(gen), w = u(gen);
      if (s + w > 1) s = 1 - s, w = 1 - w;
      out.push_back({a + (b - a) * s + (e - a) * w, label[t]});
    }
  }
  return out;
}

// Two unit squares (4 x 4 cells, two triangles each) folded along the x axis to
// `degrees` apart: an acute wedge, where disks of the other face come nearer to a point
// than any of its own face.
std::shared_ptr<const SurfaceDomain> wedge(double degrees) {
  constexpr int kCells = 4;
  const double a = degrees * M_PI / 180;
  std::vector<Vec3> vertices;
  std::vector<SurfaceDomain::Triangle> triangles;
  // Vertex (i, j) of a face; face 1 shares face 0's crease (row 0).
  const auto at = [](int face, int i, int j) {
    const int row = face == 0 || j == 0 ? j : kCells + j;
    return static_cast<std::size_t>(row * (kCells + 1) + i);
  };
  for (int face = 0; face < 2; ++face)
    for (int j = face; j <= kCells; ++j)
      for (int i = 0; i <= kCells; ++i) {
        const double x = double(i) / kCells, s = double(j) / kCells;
        vertices.push_back(face == 0 ? Vec3{x, s, 0} : Vec3{x, s * std::cos(a), s * std::sin(a)});
      }
  for (int face = 0; face < 2; ++face)
    for (int j = 0; j < kCells; ++j)
      for (int i = 0; i < kCells; ++i) {
        const auto v = [&](int di, int dj) { return at(face, i + di, j + dj); };
        if (face == 0) {  // wound the other way on face 1: the normals point out of the wedge
          triangles.push_back({v(0, 0), v(1, 0), v(1, 1)});
          triangles.push_back({v(0, 0), v(1, 1), v(0, 1)});
        } else {
          triangles.push_back({v(0, 0), v(1, 1), v(1, 0)});
          triangles.push_back({v(0, 0), v(0, 1), v(1, 1)});
        }
      }
  return std::make_shared<const SurfaceDomain>(std::move(vertices), std::move(triangles));
}

TEST(SurfaceCell, AMovedDiskInsideWhichItsCellLiesStillCoversWhatOnlyItCovered) {
  struct Case {
    const char* file;
    double share;  // the radius, of the bounding box's diagonal
    bool features;
  };
  // Closed with genus, open with a boundary, CAD creases (disks on patches), and a flat
  // box, and a 20 degree wedge.
  const Case cases[] = {{"elephant.off", 0.009, false},
                        {"mesh_with_border.off", 0.02, false},
                        {"fandisk.off", 0.025, true},
                        {"box", 0.04, true},
                        {"wedge", 0.04, true}};
  for (const auto& [file, share, features] : cases) {
    const std::string name = file;
    SurfaceDomain d = name == "box"     ? *test::box_surface({1, 1, 0.3}, {4, 4, 1})
                      : name == "wedge" ? *wedge(20)
                                        : *test::surface_file(file);
    const double r = share * norm(d.bbox_max() - d.bbox_min());
    if (features) d.set_features(detect_features(d, {60, 60, 0}));
    const auto surface = std::make_shared<const SurfaceDomain>(std::move(d));
    const std::vector<std::size_t> label = test::patch_labels(*surface);
    double longest = 0;
    for (const auto& t : surface->triangles())
      for (int k = 0; k < 3; ++k)
        longest = std::max(longest,
                           norm(surface->vertices()[t[k]] - surface->vertices()[t[(k + 1) % 3]]));
    for (std::uint64_t seed = 1; seed <= 2; ++seed) {
      Rng rng(seed);
      const SurfacePacking p = sample_mps(surface, SurfaceSizing::constant(r), rng);
      std::vector<DiskId> ids = p.ids();
      std::vector<Vec3> centers;
      std::vector<std::uint32_t> triangles;
      std::vector<bool> fixed;
      for (const DiskId id : ids) {
        centers.push_back(p.center(id));
        triangles.push_back(p.point(id).triangle);
        fixed.push_back(p.flags(id) & kFixed);
      }
      const auto on = test::disk_patches(*surface, label, centers, triangles, fixed, r);
      std::mt19937_64 gen(seed);
      std::uniform_real_distribution<double> u(0, 1);
      std::size_t inside = 0, outside = 0, checked = 0;
      for (int trial = 0; trial < 500; ++trial) {
        const std::size_t i = static_cast<std::size_t>(u(gen) * static_cast<double>(ids.size()));
        const Vec3 c = centers[i];
        // A move along a random direction, by up to 0.6 r, and its half and quarter (a
        // relaxation move's halvings), to the nearest surface point, asked of one
        // DiskCell in a random order: each answer must be a fresh cell_inside's.
        const Vec3 dir{u(gen) - 0.5, u(gen) - 0.5, u(gen) - 0.5};
        const Vec3 step = dir * (0.6 * r * u(gen) / norm(dir));
        std::array<double, 3> parts{1, 0.5, 0.25};
        std::shuffle(parts.begin(), parts.end(), gen);
        detail::DiskCell cell;
        cell.of(p, ids[i]);
        for (const double part : parts) {
          const Vec3 x = test::nearest_surface_point(p, c + step * part).p;
          const double radius = r * (1 - 1e-7);
          const bool said_inside = cell.inside(x, radius);
          ASSERT_EQ(said_inside, detail::cell_inside(p, ids[i], x, radius))
              << file << " seed " << seed << " disk " << ids[i] << ", part " << part;
          if (!said_inside) {
            ++outside;
            continue;
          }
          ++inside;
          std::vector<std::size_t> others;  // the disks that can cover a point within r of c
          for (std::size_t j = 0; j < centers.size(); ++j)
            if (j != i && squared_norm(centers[j] - c) <= 4.1 * r * r) others.push_back(j);
          for (const Probe& y : probes_near(*surface, label, c, 1.01 * r + longest, gen)) {
            if (!on[i].count(y.patch) || squared_norm(y.at - c) > r * r * (1 + 4e-9)) continue;
            bool covered_by_other = false, nearer_other = false;
            for (const std::size_t j : others) {
              if (!on[j].count(y.patch)) continue;
              const double dj = squared_norm(y.at - centers[j]);
              covered_by_other = covered_by_other || dj <= r * r * (1 + 4e-9);
              nearer_other = nearer_other || dj < squared_norm(y.at - c);
            }
            if (covered_by_other && nearer_other) continue;
            ++checked;
            ASSERT_LE(norm(y.at - x), radius * (1 + 1e-9))
                << file << " seed " << seed << " disk " << ids[i] << ": the point (" << y.at.x
                << ", " << y.at.y << ", " << y.at.z << ") "
                << (covered_by_other ? "nearest to it" : "covered only by it")
                << " is outside its ball at the new place";
          }
        }
      }
      std::printf("[ cell ] %s seed %llu: %zu moves said inside (%zu probes checked), %zu not\n",
                  file, static_cast<unsigned long long>(seed), inside, checked, outside);
      // Both answers occur: the test is not vacuous, nor is the quick test useless.
      EXPECT_GT(inside, 100u) << file;
      EXPECT_GT(outside, 0u) << file;
    }
  }
}

// TrianglesNearDisks keeps a disk's list until the disk has moved more than the slack:
// after every move (small ones, which keep it, and large ones, which renew it), each
// triangle with a point within reach of the disk's center must be in its list. Points
// of a triangle: a barycentric grid (a triangle whose grid misses the ball by less than
// the grid's spacing is not asked for).
TEST(SurfaceCell, TheTrianglesNearADiskFollowItsMoves) {
  const auto surface = test::surface_file("elephant.off");
  const double r = 0.012, reach = r, slack = 0.5 * r;
  Rng rng(5);
  SurfacePacking p = sample_mps(surface, SurfaceSizing::constant(r), rng);
  detail::TrianglesNearDisks near(p.id_bound(), reach, slack);
  const std::vector<DiskId> ids = p.ids();
  double longest = 0;
  for (const auto& t : surface->triangles())
    for (int k = 0; k < 3; ++k)
      longest =
          std::max(longest, norm(surface->vertices()[t[k]] - surface->vertices()[t[(k + 1) % 3]]));
  std::mt19937_64 gen(5);
  std::uniform_real_distribution<double> u(0, 1);
  std::size_t asked = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const DiskId id = ids[static_cast<std::size_t>(u(gen) * static_cast<double>(ids.size()))];
    for (int step = 0; step < 4; ++step) {
      // Steps of up to 0.3 r (kept lists) and now and then 2 r (renewed ones).
      const double length = (step == 3 ? 2.0 : 0.3) * r * u(gen);
      const Vec3 dir{u(gen) - 0.5, u(gen) - 0.5, u(gen) - 0.5};
      p.move(id, test::nearest_surface_point(p, p.center(id) + dir * (length / norm(dir))));
      const std::vector<std::uint32_t>& listed = near.of(p, id);
      const std::set<std::uint32_t> in(listed.begin(), listed.end());
      const Vec3 c = p.center(id);
      for (std::size_t t = 0; t < surface->triangles().size(); ++t) {
        const auto& tri = surface->triangles()[t];
        const Vec3 a = surface->vertices()[tri[0]], b = surface->vertices()[tri[1]],
                   e = surface->vertices()[tri[2]];
        if (norm(a - c) > reach + longest) continue;  // no point of it within reach
        bool within = false;
        constexpr int kGrid = 24;
        for (int i = 0; i <= kGrid && !within; ++i)
          for (int j = 0; i + j <= kGrid && !within; ++j) {
            const Vec3 y = a + (b - a) * (double(i) / kGrid) + (e - a) * (double(j) / kGrid);
            within = norm(y - c) <= reach;
          }
        if (!within) continue;
        ++asked;
        ASSERT_TRUE(in.count(static_cast<std::uint32_t>(t)))
            << "trial " << trial << " step " << step << ": triangle " << t
            << " comes within reach of disk " << id << " but is not in its list";
      }
    }
  }
  EXPECT_GT(asked, 1000u);
}

}  // namespace
}  // namespace disktune
