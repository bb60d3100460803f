// SPDX-License-Identifier: GPL-3.0-or-later
// 1D tuning of a surface's open boundary (paper, section 7): the surface adapter of the
// curve tuning core (curve_tuning.h). Each boundary loop is a closed curve with no
// pinned disk: surface sampling puts no disk on the loop's vertices, so a sharp vertex is
// an ordinary point of the curve, and what happens across it (two stretches of the loop
// close in space) is seen by the core's chord-distance checks.
#include <limits>
#include <vector>

#include "curve_tuning.h"
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
    for (std::size_t l = 0; l < d.boundary_loops().size(); ++l) {
      std::vector<Vec3> v;
      for (const std::size_t k : d.boundary_loops()[l]) v.push_back(d.vertices()[k]);
      out.emplace_back(std::move(v), true, l);
    }
    return out;
  }
  SurfacePoint point_at(const detail::Curve<Vec3>& c, std::size_t piece, double t) const {
    return packing_.index().on_boundary(c.tag, piece, t);
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
  if (packing.domain().is_closed()) return;  // no boundary: nothing to tune
  SurfaceCurves curves(packing);
  detail::CurveTuner<SurfaceCurves> tuner(curves);
  tuner.tune(spacing_factor, rng);
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
