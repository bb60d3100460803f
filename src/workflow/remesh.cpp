// SPDX-License-Identifier: GPL-3.0-or-later
#include "disktune/remesh.h"

#include <string>
#include <vector>

#include "disktune/density.h"
#include "disktune/errors.h"
#include "disktune/resources.h"
#include "disktune/restricted_delaunay.h"
#include "disktune/surface_features.h"
#include "disktune/surface_tuning.h"

namespace disktune {

RemeshResult remesh(std::shared_ptr<const SurfaceDomain> surface, std::size_t vertex_count,
                    const RemeshOptions& options) {
  if (!surface) throw InvalidInput("remesh: no surface given");
  if (vertex_count < 4) {
    throw InvalidInput("remesh: a surface mesh needs at least 4 vertices, " + std::to_string(vertex_count) +
                       " asked for");
  }
  if (!(options.feature_angle >= 0 && options.feature_angle < 180)) {
    throw InvalidInput("remesh: the feature angle must be in [0, 180) degrees (0: no features), got " +
                       std::to_string(options.feature_angle));
  }
  const SurfaceFeatures& given = surface->features();
  if (options.feature_angle > 0 && given.curves.empty() && given.corners.empty()) {
    auto with_features = std::make_shared<SurfaceDomain>(*surface);
    FeatureOptions detect;
    detect.angle = options.feature_angle;
    with_features->set_features(detect_features(*with_features, detect));
    surface = std::move(with_features);
  }
  RemeshResult out;
  out.radius = radius_for_count(vertex_count, surface->area(), options.area_fraction);
  const SurfaceSizing sizing = SurfaceSizing::constant(out.radius);
  try {
    const ResourceEstimate need =
        estimate_resources(*surface, sizing).tuned_to(static_cast<double>(vertex_count));
    check_resources(need, options.max_memory > 0 ? options.max_memory : available_memory());
  } catch (const InvalidInput& e) {
    throw InvalidInput("remesh: " + std::to_string(vertex_count) + " vertices are too many: " + e.what(),
                       e.remedy());
  }
  Rng rng(options.seed);
  SurfacePacking packing = sample_mps(surface, sizing, rng);
  out.tuning = tune(packing, Target::count(vertex_count), rng, options.tune);

  out.mesh = restricted_delaunay(packing);
  out.check = check_surface_mesh(out.mesh);
  return out;
}

RemeshResult remesh(const SurfaceDomain& surface, std::size_t vertex_count, const RemeshOptions& options) {
  return remesh(std::make_shared<const SurfaceDomain>(surface), vertex_count, options);
}

}  // namespace disktune
