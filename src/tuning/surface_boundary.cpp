// SPDX-License-Identifier: GPL-3.0-or-later
// 1D tuning of a surface's fixed curves (paper, section 7): the surface adapter of the
// curve tuning core (curve_tuning.h). A boundary loop with no corner on it (no feature
// corner, no turn sharper than kBoundaryCornerAngle) is a closed curve with no pinned
// disk: a bend is an ordinary point of the curve, and what happens across it (two
// stretches of the loop close in space) is seen by the core's chord-distance checks.
// Every other curve runs between two corner disks, which stay.
//
// Feature curves are never spaced wider than kCurveSpacing r, below the sqrt(2) r
// that keeps the edge between consecutive feature disks in the restricted Delaunay mesh
// (surface_mps.cpp lays them out so).
#include <algorithm>
#include <limits>
#include <vector>

#include "curve_tuning.h"
#include "disktune/sampling.h"
#include "disktune/surface_tuning.h"
#include "surface_repair.h"

namespace disktune {

namespace {

class SurfaceCurves {
 public:
  using Pack = SurfacePacking;
  using Pos = Vec3;
  using Point = SurfacePoint;

  explicit SurfaceCurves(SurfacePacking& packing) : packing_(packing) {}

  SurfacePacking& packing() { return packing_; }
  std::vector<detail::Curve<Vec3>> curves() const {
    const SurfaceDomain& d = packing_.domain();
    std::vector<detail::Curve<Vec3>> out;
    for (std::size_t c = 0; c < d.fixed_curves().size(); ++c) {
      std::vector<Vec3> v;
      for (const std::size_t k : d.fixed_curves()[c].vertices) v.push_back(d.vertices()[k]);
      out.emplace_back(std::move(v), d.fixed_curves()[c].closed, c);
    }
    return out;
  }
  bool is_feature(std::size_t c) const {
    return c >= packing_.domain().first_feature_curve();
  }
  SurfacePoint point_at(const detail::Curve<Vec3>& c, std::size_t piece, double t) const {
    return packing_.index().on_curve(c.tag, piece, t);
  }
  static Vec3 pos(const SurfacePoint& x) { return x.p; }
  double radius_at(const SurfacePoint& x) const { return packing_.radius_at(x); }
  template <class F>
  void for_each_near(Vec3 q, double R, F&& f) const {
    packing_.for_each_near(q, R, f);
  }
  void repair(detail::SurfaceUndoLog& log, Vec3 c, double r, Rng& rng) const {
    detail::repair_void(log, packing_, c, detail::void_reach(r), rng, std::numeric_limits<std::size_t>::max() - 1);
  }

 private:
  SurfacePacking& packing_;
};

}  // namespace

void respace_surface_boundary(SurfacePacking& packing, double spacing_factor, Rng& rng) {
  SurfaceCurves curves(packing);
  detail::CurveTuner<SurfaceCurves> tuner(curves);
  const auto factor_of = [&](std::size_t c) {
    return curves.is_feature(c) ? std::min(spacing_factor, kCurveSpacing) : spacing_factor;
  };
  tuner.tune(factor_of, rng);
}

long boundary_inject(SurfacePacking& packing, Rng& rng) {
  SurfaceCurves curves(packing);
  detail::CurveTuner<SurfaceCurves> tuner(curves);
  return tuner.random_step(true, rng).added;
}

long boundary_eject(SurfacePacking& packing, Rng& rng) {
  SurfaceCurves curves(packing);
  detail::CurveTuner<SurfaceCurves> tuner(curves);
  return tuner.random_step(false, rng).added;
}

}  // namespace disktune
