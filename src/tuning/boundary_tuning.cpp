// SPDX-License-Identifier: GPL-3.0-or-later
// 1D tuning of a planar domain's boundary disks (paper, section 7): the planar adapter of
// the curve tuning core (curve_tuning.h). Each boundary segment is a curve between two
// corners (every polygon vertex is one), whose disks never move.
#include <limits>
#include <vector>

#include "curve_tuning.h"
#include "disktune/boundary.h"
#include "void_repair.h"

namespace disktune {

namespace {

class PlanarCurves {
 public:
  using Pack = Packing;
  using Pos = Vec2;
  using Point = Vec2;

  PlanarCurves(Packing& packing, const PlanarDomain& domain) : packing_(packing), domain_(domain) {}

  Packing& packing() { return packing_; }
  std::vector<detail::Curve<Vec2>> curves() const {
    std::vector<detail::Curve<Vec2>> out;
    for (const BoundarySegment& s : domain_.segments()) out.emplace_back(std::vector<Vec2>{s.a, s.b}, false, out.size());
    return out;
  }
  Vec2 point_at(const detail::Curve<Vec2>& c, std::size_t, double t) const {
    return t >= 1 ? c.b(0) : c.a(0) + (c.b(0) - c.a(0)) * t;
  }
  static Vec2 pos(Vec2 x) { return x; }
  double radius_at(Vec2 x) const { return packing_.radius_at(x); }
  template <class F>
  void for_each_near(Vec2 q, double R, F&& f) const {
    packing_.for_each_near(q, R, [&](const Neighbor& n) { f(n.id); });
  }
  void repair(detail::UndoLog& log, Vec2 c, double r, Rng& rng) const {
    detail::repair_void(log, packing_, c, r, rng, std::numeric_limits<std::size_t>::max() - 1);
  }

 private:
  Packing& packing_;
  const PlanarDomain& domain_;
};

}  // namespace

void tune_boundary(Packing& packing, const PlanarDomain& domain, double spacing_factor, Rng& rng,
                   BoundaryChange change, std::size_t budget, double longest_step) {
  boundary_loops(packing, domain);  // flags the boundary disks (a packing read from a file)
  PlanarCurves curves(packing, domain);
  detail::CurveTuner<PlanarCurves> tuner(curves);
  tuner.tune([&](std::size_t) { return spacing_factor; }, rng, change, budget, longest_step);
}

long boundary_tune_by(Packing& packing, const PlanarDomain& domain, long change, Rng& rng) {
  boundary_loops(packing, domain);
  PlanarCurves curves(packing, domain);
  detail::CurveTuner<PlanarCurves> tuner(curves);
  return tuner.tune_by(change, rng);
}

long boundary_inject(Packing& packing, const PlanarDomain& domain, Rng& rng) {
  PlanarCurves curves(packing, domain);
  detail::CurveTuner<PlanarCurves> tuner(curves);
  return tuner.random_step(true, rng).added;
}

long boundary_eject(Packing& packing, const PlanarDomain& domain, Rng& rng) {
  PlanarCurves curves(packing, domain);
  detail::CurveTuner<PlanarCurves> tuner(curves);
  return tuner.random_step(false, rng).added;
}

}  // namespace disktune
