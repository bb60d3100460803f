// SPDX-License-Identifier: GPL-3.0-or-later
// A point or vector in space, for surface domains.
#pragma once

#include <array>
#include <cmath>
#include <optional>

namespace disktune {

struct Vec3 {
  double x = 0, y = 0, z = 0;
  Vec3 operator+(Vec3 o) const { return {x + o.x, y + o.y, z + o.z}; }
  Vec3 operator-(Vec3 o) const { return {x - o.x, y - o.y, z - o.z}; }
  Vec3 operator*(double s) const { return {x * s, y * s, z * s}; }
  bool operator==(Vec3 o) const { return x == o.x && y == o.y && z == o.z; }
  bool operator!=(Vec3 o) const { return !(*this == o); }
};

inline double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double squared_norm(Vec3 a) { return dot(a, a); }
inline double norm(Vec3 a) { return std::sqrt(dot(a, a)); }

/// Distance from p to the segment [a, b] (to a when a == b).
inline double distance_to_segment(Vec3 p, Vec3 a, Vec3 b) {
  const Vec3 ab = b - a;
  const double len2 = squared_norm(ab);
  const double t = len2 > 0 ? std::fmin(std::fmax(dot(p - a, ab) / len2, 0.0), 1.0) : 0;
  return norm(p - (a + ab * t));
}

/// The parameters s in [0, 1] at which a + s (b - a) lies in the closed ball of radius r
/// around c, as [s0, s1]; nothing when the segment misses the ball or has no length. For
/// points in space (Vec3) and in the plane (Vec2).
template <class V>
std::optional<std::array<double, 2>> segment_in_ball(V a, V b, V c, double r) {
  // |a + s d - c|^2 <= r^2: a quadratic in s.
  const V d = b - a, f = a - c;
  const double A = dot(d, d), B = dot(f, d), C = dot(f, f) - r * r;
  const double disc = B * B - A * C;
  if (!(A > 0) || disc < 0) return std::nullopt;
  const double root = std::sqrt(disc);
  const double s0 = std::fmax(0.0, (-B - root) / A), s1 = std::fmin(1.0, (-B + root) / A);
  if (s0 > s1) return std::nullopt;
  return std::array<double, 2>{s0, s1};
}

}  // namespace disktune
