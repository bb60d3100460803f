// SPDX-License-Identifier: GPL-3.0-or-later
// Whether a Voronoi edge meets a surface triangle, written once for any number type:
// with intervals it answers fast or says "unsure"; with an exact ring type (CGAL::Mpzf)
// it answers except in a true degeneracy. restricted_delaunay.cpp runs the two in turn
// and leaves what both call unsure to its rational construction.
//
// Voronoi vertices are kept homogeneous (x = n / d): the circumcenter of four input
// points is a polynomial over a polynomial, so every test below is a polynomial sign,
// exact in a ring type with no division.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "disktune/surface_domain.h"
#include "disktune/surface_mesh.h"
#include "disktune/vec3.h"

namespace disktune::detail {

/// A point x = n / d.
template <class NT>
struct HomogeneousPoint {
  std::array<NT, 3> n;
  NT d;
};

template <class NT>
using Vector3 = std::array<NT, 3>;

template <class NT>
Vector3<NT> vector_of(Vec3 v) {
  return {NT(v.x), NT(v.y), NT(v.z)};
}

template <class NT>
Vector3<NT> minus(const Vector3<NT>& a, const Vector3<NT>& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

template <class NT>
Vector3<NT> scaled(const Vector3<NT>& a, const NT& s) {
  return {a[0] * s, a[1] * s, a[2] * s};
}

template <class NT>
Vector3<NT> cross(const Vector3<NT>& a, const Vector3<NT>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

template <class NT>
NT dot(const Vector3<NT>& a, const Vector3<NT>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// det(a, b, c) = a . (b x c).
template <class NT>
NT determinant(const Vector3<NT>& a, const Vector3<NT>& b, const Vector3<NT>& c) {
  return dot(a, cross(b, c));
}

/// The center of the sphere through p0..p3: with u_i = p_i - p0 it is
/// p0 + (|u1|^2 u2 x u3 + |u2|^2 u3 x u1 + |u3|^2 u1 x u2) / (2 det(u1, u2, u3)).
/// d is zero for four coplanar points.
template <class NT>
HomogeneousPoint<NT> circumcenter(Vec3 p0, Vec3 p1, Vec3 p2, Vec3 p3) {
  const Vector3<NT> o = vector_of<NT>(p0);
  const Vector3<NT> u1 = minus(vector_of<NT>(p1), o), u2 = minus(vector_of<NT>(p2), o),
                    u3 = minus(vector_of<NT>(p3), o);
  const NT d = NT(2) * determinant(u1, u2, u3);
  const Vector3<NT> a = scaled(cross(u2, u3), dot(u1, u1)), b = scaled(cross(u3, u1), dot(u2, u2)),
                    c = scaled(cross(u1, u2), dot(u3, u3));
  HomogeneousPoint<NT> x{{}, d};
  for (int k = 0; k < 3; ++k) x.n[k] = o[k] * d + a[k] + b[k] + c[k];
  return x;
}

/// p + t * direction.
template <class NT>
HomogeneousPoint<NT> moved(const HomogeneousPoint<NT>& p, const Vector3<NT>& direction, double t) {
  HomogeneousPoint<NT> x{{}, p.d};
  for (int k = 0; k < 3; ++k) x.n[k] = p.n[k] + direction[k] * p.d * NT(t);
  return x;
}

/// p + u (q - p) = ((1 - u) np dq + u nq dp) / (dp dq), for a double u.
template <class NT>
HomogeneousPoint<NT> between(const HomogeneousPoint<NT>& p, const HomogeneousPoint<NT>& q, double u) {
  const NT from = (NT(1) - NT(u)) * q.d, to = NT(u) * p.d;
  HomogeneousPoint<NT> x{{}, p.d * q.d};
  for (int k = 0; k < 3; ++k) x.n[k] = p.n[k] * from + q.n[k] * to;
  return x;
}

/// What a test can say; `unsure` when a sign is not known (an interval holding zero) or
/// is zero (a degenerate case, left to the exact construction).
enum class Crossing { miss, hit, unsure };

/// -1 or +1 when x is certainly negative or positive, 0 otherwise. Overloaded per number
/// type next to the code that runs it.
template <class NT>
int strict_sign(const NT& x);

/// Whether the closed segment pq meets the closed triangle abc: p and q strictly on
/// opposite sides of its plane, and the line pq strictly inside its three edges.
template <class NT>
Crossing segment_meets_triangle(const HomogeneousPoint<NT>& p, const HomogeneousPoint<NT>& q, Vec3 a, Vec3 b,
                                Vec3 c) {
  const Vector3<NT> va = vector_of<NT>(a), vb = vector_of<NT>(b), vc = vector_of<NT>(c);
  const int sp = strict_sign(p.d), sq = strict_sign(q.d);
  if (sp == 0 || sq == 0) return Crossing::unsure;
  // The side of the plane: sign det(b - a, c - a, x - a), times d's sign for x = n / d.
  const Vector3<NT> ab = minus(vb, va), ac = minus(vc, va);
  const int side_p = sp * strict_sign(determinant(ab, ac, minus(p.n, scaled(va, p.d))));
  const int side_q = sq * strict_sign(determinant(ab, ac, minus(q.n, scaled(va, q.d))));
  if (side_p != 0 && side_p == side_q) return Crossing::miss;
  // The line's side of each edge: sign det(q - p, u - p, v - p); with x = n / d, the
  // same as det(nq dp - np dq, u dp - np, v dp - np) times sign(dp dq), a factor common
  // to the three edges and so left out.
  const Vector3<NT> pq = minus(scaled(q.n, p.d), scaled(p.n, q.d));
  const Vector3<NT> pa = minus(scaled(va, p.d), p.n), pb = minus(scaled(vb, p.d), p.n),
                    pc = minus(scaled(vc, p.d), p.n);
  const int e1 = strict_sign(determinant(pq, pa, pb)), e2 = strict_sign(determinant(pq, pb, pc)),
            e3 = strict_sign(determinant(pq, pc, pa));
  if (e1 * e2 < 0 || e2 * e3 < 0 || e3 * e1 < 0) return Crossing::miss;  // the line passes outside
  if (side_p == 0 || side_q == 0 || e1 == 0 || e2 == 0 || e3 == 0) return Crossing::unsure;
  return Crossing::hit;  // strictly opposite sides (equal ones returned above), strictly inside
}

/// How restricted_delaunay decides which dual edges meet the surface: `filtered` (the
/// default) tries intervals, then the exact ring, then rational constructions;
/// `rational` goes straight to the last, as a reference for tests.
enum class DualArithmetic { filtered, rational };

/// How many facets' duals each arithmetic settled.
struct DualEdgeCounts {
  std::size_t interval = 0, ring = 0, rational = 0;
};

/// The triangulation a mesh was made from, kept for the next (restricted_delaunay.cpp).
struct RestrictedDelaunayState;

/// restricted_delaunay with the arithmetic chosen and the counts returned. With
/// `covered_within` > 0 the caller vouches that every point of the surface lies within
/// that distance of a sample: a dual edge is then searched only within it of its facet's
/// corners (restricted_delaunay.h, Coverage::maximal). The dual edges are searched on
/// up to `threads` threads (0: one per core); the mesh is the same for any number.
SurfaceMesh restricted_delaunay(const std::vector<Vec3>& samples, const SurfaceDomain& surface,
                                const std::vector<std::uint32_t>& sample_patch,
                                const std::vector<std::array<std::uint32_t, 2>>& feature_edges,
                                DualArithmetic arithmetic, DualEdgeCounts* counts,
                                double covered_within = 0, unsigned threads = 0,
                                RestrictedDelaunayState* state = nullptr);

}  // namespace disktune::detail
