// SPDX-License-Identifier: GPL-3.0-or-later
// cell_inside and DiskCell: each triangle within the disk's ball is clipped by the
// bisector planes of the disks within twice that ball (no farther disk is nearer to a
// point of the ball), Sutherland-Hodgman style; a cell part is convex, so it lies in a
// ball when its corners do.
#include "surface_cell.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "disktune/tolerance.h"

namespace disktune::detail {
namespace {

double farthest2(const Vec3* corner, std::size_t size, Vec3 from) {
  double far2 = 0;
  for (std::size_t i = 0; i < size; ++i) far2 = std::max(far2, squared_norm(corner[i] - from));
  return far2;
}

// What clipping leaves of a polygon: its corners' number and farthest squared distances
// from two points.
struct Clipped {
  std::size_t size;
  double far2, far_x2;
};

// The part of polygon corner[0, n) where dot(y - c, u) <= k (the side of the bisector
// plane of c and c + u, with k = |u|^2 / 2, nearer to c), in place (made in `out`
// first), with its farthest squared distances from c and x; nothing where the plane
// leaves the polygon whole, or where the part would need more than `most` corners (then
// size is above `most`, and the polygon is left as it was).
std::optional<Clipped> clip(Vec3* corner, std::size_t n, Vec3 c, Vec3 u, double k, Vec3 x,
                            std::size_t most, Vec3* out) {
  std::array<double, DiskCell::kCorners> f;  // the corners' heights over the plane
  bool cut = false;
  for (std::size_t i = 0; i < n; ++i) cut = (f[i] = dot(corner[i] - c, u) - k) > 0 || cut;
  // With no corner beyond the plane the polygon stays as it is; one of `most` corners
  // fails all the same, as every clip of it did when each clip copied the polygon.
  if (!cut) return n + 1 > most ? std::optional<Clipped>({most + 1, 0, 0}) : std::nullopt;
  Clipped kept{0, 0, 0};
  const auto keep = [&](Vec3 y) {
    out[kept.size++] = y;
    kept.far2 = std::max(kept.far2, squared_norm(y - c));
    kept.far_x2 = std::max(kept.far_x2, squared_norm(y - x));
  };
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = i + 1 == n ? 0 : i + 1;
    const double fa = f[i], fb = f[j];
    if (kept.size + 2 > most) return Clipped{most + 1, 0, 0};
    if (fa <= 0) keep(corner[i]);
    if ((fa < 0 && fb > 0) || (fa > 0 && fb < 0))
      keep(corner[i] + (corner[j] - corner[i]) * (fa / (fa - fb)));
  }
  std::copy_n(out, kept.size, corner);
  return kept;
}

}  // namespace

bool cell_inside(const SurfacePacking& packing, DiskId p, Vec3 x, double radius,
                 const std::vector<std::uint32_t>* near_p) {
  thread_local DiskCell cell;
  cell.of(packing, p, near_p);
  return cell.inside(x, radius);
}

void DiskCell::of(const SurfacePacking& packing, DiskId p, const std::vector<std::uint32_t>* near) {
  packing_ = &packing;
  p_ = p;
  c_ = packing.center(p);
  R_ = packing.radius(p) * (1 + 1e-6);
  if (!near) packing.index().triangles_near(c_, R_, found_), near = &found_;
  listed_ = near;
  scanned_ = 0;
  parts_.clear();
  near_.clear();
  packing.for_each_near(c_, 2 * R_ + packing.max_radius() * kRelTol, [&](DiskId q) {
    if (q != p) near_.emplace_back(squared_norm(packing.center(q) - c_), q);
  });
  // Nearest first: they cut the most, and once a part lies within half a disk's
  // distance of c, neither that disk's bisector nor a farther one's reaches it.
  std::sort(near_.begin(), near_.end());
}

bool DiskCell::inside(Vec3 x, double radius) {
  const SurfacePacking& packing = *packing_;
  const SurfaceIndex& index = packing.index();
  const double inside2 = radius * radius;
  for (std::size_t k = 0;; ++k) {
    // The next listed triangle within the ball made a part, when first reached.
    while (k == parts_.size() && scanned_ < listed_->size()) {
      const std::uint32_t t = (*listed_)[scanned_++];
      const PatchSet patch = index.patch_of_triangle(t);
      if (!packing.share_patch(packing.patches(p_), patch)) continue;  // p covers nothing there
      const double h = index.plane(t).height(c_);  // the plane's distance: a cheap first test
      if (h * h > R_ * R_ || squared_norm(index.closest_point(t, c_) - c_) > R_ * R_) continue;
      if (corners_.size() < kCorners * (k + 1)) corners_.resize(kCorners * (k + 1));
      Vec3* corner = &corners_[kCorners * k];
      for (int i = 0; i < 3; ++i)
        corner[i] = packing.domain().vertices()[packing.domain().triangles()[t][i]];
      parts_.push_back({3, 0, farthest2(corner, 3, c_), patch, false});
    }
    if (k == parts_.size()) return true;
    Part& part = parts_[k];
    Vec3* corner = &corners_[kCorners * k];
    double far_x2 = farthest2(corner, part.size, x);
    // Clipped by the nearest bisectors first, a part soon lies in the ball at x, and
    // further cuts only shrink it.
    for (; far_x2 > inside2 && !part.final; ++part.next) {
      if (part.next == near_.size()) {
        part.final = true;
        break;
      }
      const auto [d2, q] = near_[part.next];
      if (part.far2 < 0.25 * d2 * (1 - 1e-9)) {
        part.final = true;
        break;
      }
      if (!packing.share_patch(packing.patches(q), part.patch))
        continue;               // it covers nothing there
      if (!(d2 > 0)) continue;  // no bisector: the cell stays larger, never smaller
      const std::optional<Clipped> clipped = clip(corner, part.size, c_, packing.center(q) - c_,
                                                  0.5 * d2, x, kCorners, scratch_.data());
      if (!clipped) continue;  // the plane misses the part
      if (clipped->size > kCorners) {
        part.final = true;
        break;
      }
      part.size = clipped->size;
      part.far2 = clipped->far2;
      far_x2 = clipped->far_x2;
    }
    if (far_x2 > inside2) return false;
  }
}

TrianglesNearDisks::TrianglesNearDisks(DiskId id_bound, double reach, double slack)
    : reach_(reach),
      slack_(slack),
      near_(id_bound),
      found_at_(id_bound, Vec3{std::numeric_limits<double>::infinity(), 0, 0}) {}

const std::vector<std::uint32_t>& TrianglesNearDisks::of(const SurfacePacking& packing, DiskId p) {
  const Vec3 c = packing.center(p);
  if (!(squared_norm(c - found_at_[p]) <= slack_ * slack_)) {
    packing.index().triangles_near(c, reach_ + slack_, near_[p]);
    found_at_[p] = c;
  }
  return near_[p];
}

}  // namespace disktune::detail
