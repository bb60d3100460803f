// SPDX-License-Identifier: GPL-3.0-or-later
#include "feature_chain.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace disktune::detail {

std::vector<std::array<std::uint32_t, 2>> feature_neighbours(const SurfacePacking& packing) {
  const SurfaceDomain& d = packing.domain();
  std::vector<std::array<std::uint32_t, 2>> out;
  if (d.features().curves.empty()) return out;
  std::map<DiskId, std::uint32_t> vertex;  // each fixed disk's vertex number
  std::uint32_t n = 0;
  for (const DiskId id : packing.ids()) {
    if (packing.flags(id) & kFixed) vertex.emplace(id, n);
    ++n;
  }
  const double r = packing.max_radius(), tol = 1e-9 * r;
  for (const SurfaceCurve& curve : d.features().curves) {
    const auto& v = curve.vertices;
    std::map<DiskId, double> at;  // each fixed disk on the curve, by arc length
    double start = 0;
    for (std::size_t k = 0; k < curve.edge_count(); ++k) {
      const Vec3 a = d.vertices()[v[k]], ab = d.vertices()[v[(k + 1) % v.size()]] - a;
      const double len = norm(ab);
      const int pieces = std::max(1, static_cast<int>(std::ceil(len / r)));
      for (int p = 0; p < pieces; ++p) {
        packing.for_each_near(a + ab * ((p + 0.5) / pieces), 0.5 * len / pieces + tol, [&](DiskId id) {
          if (!(packing.flags(id) & kFixed) || at.count(id)) return;
          const double t = std::clamp(dot(packing.center(id) - a, ab) / (len * len), 0.0, 1.0);
          if (norm(packing.center(id) - (a + ab * t)) <= tol) at.emplace(id, start + t * len);
        });
      }
      start += len;
    }
    std::vector<std::pair<double, DiskId>> order;
    for (const auto& [id, s] : at) order.push_back({s, id});
    std::sort(order.begin(), order.end());
    for (std::size_t i = 0; i + 1 < order.size() + (curve.closed && order.size() > 2 ? 1 : 0); ++i)
      out.push_back({vertex.at(order[i].second), vertex.at(order[(i + 1) % order.size()].second)});
  }
  return out;
}

}  // namespace disktune::detail
