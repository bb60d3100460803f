// SPDX-License-Identifier: GPL-3.0-or-later
// The angle bound of the constrained Delaunay mesh near the boundary (docs/planar.md,
// "Boundary spacing"): boundary disks laid out at most kCurveSpacing r apart leave no
// room for a disk inside the diametral circle of two consecutive ones, so every
// triangle's circumcenter lies in the domain and every angle is between 30 and 120
// degrees. Judged apart from the library: the corner angles, the boundary disks,
// encroachment and the angles are computed here from coordinates alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "disktune/boundary.h"
#include "disktune/mesh.h"
#include "disktune/planar_domain.h"
#include "disktune/sampling.h"
#include "disktune/tuning.h"
#include "oracle/planar_oracle.h"
#include "planar_checks.h"

namespace disktune {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegree = 180 / kPi;

struct Corner {
  Vec2 at;
  double angle;  // the domain's interior angle there, degrees
};

// Each polygon vertex with the domain's angle at it: the angle swept from the next
// vertex's direction to the previous one's on the side where the domain lies (found by
// the oracle's even-odd test a little way along the bisector).
std::vector<Corner> input_corners(const PlanarDomain& d, const oracle::Domain& od) {
  std::vector<Corner> out;
  for (const auto& loop : d.loops()) {
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Vec2 v = loop[i], prev = loop[(i + loop.size() - 1) % loop.size()],
                 next = loop[(i + 1) % loop.size()];
      const double a_next = std::atan2(next.y - v.y, next.x - v.x),
                   a_prev = std::atan2(prev.y - v.y, prev.x - v.x);
      double ccw = a_prev - a_next;  // counterclockwise from next to prev
      while (ccw <= 0) ccw += 2 * kPi;
      const double mid = a_next + ccw / 2;
      const double step = 1e-6 * std::min(distance(v, prev), distance(v, next));
      const bool left =
          oracle::even_odd_inside(od, v.x + step * std::cos(mid), v.y + step * std::sin(mid));
      out.push_back({v, (left ? ccw : 2 * kPi - ccw) * kDegree});
    }
  }
  return out;
}

// The smallest distance from a polygon vertex to a segment not ending at it: the width
// of the narrowest gap between boundary parts (a thin part, a close hole).
double narrowest_gap(const PlanarDomain& d) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& loop : d.loops())
    for (const Vec2 v : loop)
      for (const BoundarySegment& s : d.segments()) {
        if (distance(s.a, v) == 0 || distance(s.b, v) == 0) continue;
        const Vec2 ab = s.b - s.a;
        const double t = std::clamp(dot(v - s.a, ab) / squared_norm(ab), 0.0, 1.0);
        best = std::min(best, distance(v, s.a + ab * t));
      }
  return best;
}

struct Verdict {
  std::size_t triangles = 0, encroached = 0;
  double min_angle = 180, max_angle = 0;
  double longest_step = 0;  // between consecutive boundary centers along a segment, over r
};

// The mesh's angles, and the boundary's steps: their longest, and how many are
// encroached (a center strictly inside the diametral circle of two consecutive boundary
// centers along a segment).
Verdict judge(const PlanarMesh& mesh, const PlanarDomain& d, double r) {
  Verdict out;
  for (const auto& t : mesh.triangles) {
    ++out.triangles;
    for (int k = 0; k < 3; ++k) {
      const Vec2 a = mesh.vertices[t[k]], b = mesh.vertices[t[(k + 1) % 3]], c = mesh.vertices[t[(k + 2) % 3]];
      const double cosine = dot(b - a, c - a) / (distance(a, b) * distance(a, c));
      const double angle = std::acos(std::clamp(cosine, -1.0, 1.0)) * kDegree;
      out.min_angle = std::min(out.min_angle, angle), out.max_angle = std::max(out.max_angle, angle);
    }
  }
  for (const BoundarySegment& s : d.segments()) {
    const Vec2 ab = s.b - s.a;
    std::vector<std::pair<double, Vec2>> on_segment;
    for (const Vec2 p : mesh.vertices) {
      const double t = dot(p - s.a, ab) / squared_norm(ab);
      if (t >= -1e-12 && t <= 1 + 1e-12 && distance(p, s.a + ab * t) <= 1e-9 * r) on_segment.push_back({t, p});
    }
    std::sort(on_segment.begin(), on_segment.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    for (std::size_t k = 0; k + 1 < on_segment.size(); ++k) {
      const Vec2 a = on_segment[k].second, b = on_segment[k + 1].second, mid = (a + b) * 0.5;
      out.longest_step = std::max(out.longest_step, distance(a, b) / r);
      const double radius = distance(a, b) / 2 * (1 - 1e-9);
      for (const Vec2 p : mesh.vertices)
        if (distance(p, mid) < radius) {
          ++out.encroached;
          break;
        }
    }
  }
  return out;
}

struct DomainCase {
  std::string name;
  std::shared_ptr<const PlanarDomain> domain;
  double r;
  bool sharp;  // a corner under 60 degrees, or a reflex one over 300
};

// Every .poly of data/domains at a radius for about 1000 disks, and at most 0.45 of its
// shortest segment and 0.9 of its narrowest gap between boundary parts (shorter
// segments and narrower gaps are small features: docs/planar.md).
std::vector<DomainCase> cases() {
  std::vector<DomainCase> out;
  for (const auto& e : std::filesystem::directory_iterator(std::string(DISKTUNE_DATA_DIR) + "/domains")) {
    if (e.path().extension() != ".poly") continue;
    auto d = std::make_shared<const PlanarDomain>(read_poly(e.path().string()));
    double shortest = std::numeric_limits<double>::infinity();
    for (const BoundarySegment& s : d->segments()) shortest = std::min(shortest, distance(s.a, s.b));
    const double r = std::min({std::sqrt(0.55 * d->area() / (kPi / 4 * 1000)), 0.9 * narrowest_gap(*d), 0.45 * shortest});
    bool sharp = false;
    for (const Corner& c : input_corners(*d, test::oracle_domain(*d))) sharp |= c.angle < 60 || c.angle > 300;
    out.push_back({e.path().stem().string(), d, r, sharp});
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  return out;
}

// Two claims on the constrained Delaunay mesh of a packing:
//  - proven: with every boundary step at most sqrt(2) r, no center encroaches on the
//    boundary, every triangle is Delaunay with its circumcenter in the domain, its
//    circumradius below r (maximality) and its edges at least r, so every angle lies in
//    [30, 120] degrees;
//  - the layout (`laid_out`): without corners under 60 degrees (or reflex over 300),
//    sampling keeps every step at most sqrt(2) r, so the first claim applies.
// Prints the figures either way (docs/planar.md).
void expect_bound(const DomainCase& c, const Packing& packing, const std::string& stage, bool laid_out) {
  SCOPED_TRACE(c.name + " " + stage);
  Packing p = packing;
  const PlanarMesh mesh = constrained_delaunay(p, boundary_loops(p, *c.domain));
  test::expect_mesh_tiles(mesh, test::oracle_domain(*c.domain), 1e-6 * c.r);
  const Verdict v = judge(mesh, *c.domain, c.r);
  std::printf("[bound] %-16s %-13s r=%.4g triangles=%zu angles %.2f..%.2f, longest step %.3f r, %zu encroached\n",
              c.name.c_str(), stage.c_str(), c.r, v.triangles, v.min_angle, v.max_angle, v.longest_step,
              v.encroached);
  if (v.longest_step <= std::sqrt(2.0)) {
    EXPECT_EQ(v.encroached, 0u);
    EXPECT_GE(v.min_angle, 30 - 1e-9);
    EXPECT_LE(v.max_angle, 120 + 1e-9);
  }
  if (laid_out && !c.sharp) {
    EXPECT_LE(v.longest_step, std::sqrt(2.0));
  }
}

TEST(BoundarySpacing, MpsKeepsTheAngleBound) {
  for (const DomainCase& c : cases()) {
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
      Rng rng(seed);
      expect_bound(c, sample_mps(c.domain, c.r, rng), "mps seed " + std::to_string(seed), true);
    }
  }
}

TEST(BoundarySpacing, TuningKeepsTheAngleBound) {
  for (const DomainCase& c : cases()) {
    for (const double eta : {0.4, 0.8}) {
      for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        Rng rng(seed);
        Packing p = sample_mps(c.domain, c.r, rng);
        tune(p, *c.domain, Target::area_fraction(eta), rng);
        // Tuning spaces the boundary toward the target's spacing (1.5 r at 0.4) but never
        // wider than 1.35 r, so the layout's claim holds after it too.
        expect_bound(c, p, "eta " + std::to_string(eta).substr(0, 3) + " seed " + std::to_string(seed), true);
      }
    }
  }
}

}  // namespace
}  // namespace disktune
