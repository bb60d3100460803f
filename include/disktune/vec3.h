// SPDX-License-Identifier: GPL-3.0-or-later
// A point or vector in space, for surface domains.
#pragma once

#include <cmath>

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

}  // namespace disktune
