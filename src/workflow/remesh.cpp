// SPDX-License-Identifier: GPL-3.0-or-later
#include "disktune/remesh.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <future>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include "../domain/thickness_limits.h"
#include "../geometry/threads.h"
#include "../io/number_text.h"
#include "../mesh/delaunay_flips.h"
#include "../sampling/surface_mps.h"
#include "../tuning/surface_tune.h"
#include "../voids/final_check.h"
#include "disktune/density.h"
#include "disktune/errors.h"
#include "disktune/resources.h"
#include "disktune/restricted_delaunay.h"
#include "disktune/sizing.h"
#include "disktune/surface_features.h"
#include "disktune/surface_sizing.h"
#include "disktune/surface_tuning.h"

namespace disktune {
namespace {

constexpr double kSharpAngle = 40;  // degrees: what open_sharp_angles opens

// The radii of remesh's graded try: smaller where another part of the surface faces a
// point closer than r / 0.45 (thickness_sizing: thin walls, ledges) or curves come
// close, constant where nothing is that close (so the crystal phases stay available).
// The surface is measured once, for the largest radius asked so far: the bisection
// over r asks for a dozen sizings (fandisk: 0.3 s each measured anew).
class GradedSizing {
 public:
  explicit GradedSizing(const SurfaceDomain& surface) : surface_(surface) {}
  SurfaceSizing at(double r) {
    if (r / kFeatureShare > reach_) {
      reach_ = 2 * r / kFeatureShare;  // room for the retries' larger radii
      limits_ = detail::thickness_limits(surface_, reach_);
    }
    SurfaceSizing thick = detail::thickness_sizing_from(surface_, r, limits_);
    return thick.min_radius() < r ? thick : SurfaceSizing::constant(r);
  }

 private:
  const SurfaceDomain& surface_;
  double reach_ = 0;
  std::vector<double> limits_;
};

// The disks' centers, by vertex of their mesh (the i-th live disk is vertex i).
std::vector<Vec3> centers(const SurfacePacking& packing) {
  std::vector<Vec3> out;
  for (const DiskId id : packing.ids()) out.push_back(packing.center(id));
  return out;
}

bool keeps_topology(const SurfaceMeshCheck& check, const SurfaceDomain& surface) {
  return check.manifold && check.genus == surface.genus() && check.isolated_vertices == 0 &&
         check.boundary_loops == surface.boundary_loops().size();
}

// One try of remesh at conflict radius r (the radius for the count), or with
// `thin_parts` at the largest radius whose thickness sizing gives about the count at
// the area fraction asked for; none where the thin parts alone need more vertices.
std::optional<RemeshResult> remesh_at(const std::shared_ptr<const SurfaceDomain>& surface, std::size_t vertex_count,
                                      double r, bool thin_parts, const RemeshOptions& options) {
  RemeshResult out;
  out.radius = r;
  GradedSizing graded(*surface);
  const auto sizing_at = [&](double radius) { return thin_parts ? graded.at(radius) : SurfaceSizing::constant(radius); };
  if (thin_parts) {
    const auto count_at = [&](double radius) {
      return options.area_fraction * density_integral(graded.at(radius), *surface);
    };
    const double n = static_cast<double>(vertex_count);
    double lo = r, hi = 64 * r;  // bisection in log r: the count falls as r grows
    if (count_at(hi) > n) return std::nullopt;
    for (int step = 0; step < 8; ++step) {
      const double mid = std::sqrt(lo * hi);
      (count_at(mid) > n ? lo : hi) = mid;
    }
    out.radius = hi;
  }
  out.sizing = sizing_at(out.radius);
  Rng rng(options.seed);
  // The sample and the tuned packing are checked once, at the end (below).
  SurfacePacking packing = detail::sample_mps_unchecked(surface, out.sizing, rng);
  // Disks fixed on features and boundaries, and the smaller disks of thin parts, can make
  // the sample denser than asked, and then more than the count. A few more (at most one
  // in 32) are ejected: mesh_with_border at 10^4 and 3·10^4 vertices, seeds 1-3, samples
  // 0.5-1.8 % over the count, ejected in 0.04 and 0.08 s, a new sample taking 0.11 and
  // 0.31 s. Where there are more, or the ejection stalls (near the sample's own density
  // it can), sample again at a larger radius that gives a little less, so that the count
  // is reached by injection. Thin parts keep their radii, so with them this can take
  // more than one try.
  bool reached = false;
  if (packing.size() > vertex_count && packing.size() <= vertex_count + vertex_count / 32) {
    out.tuning =
        detail::tune_surface(packing, Target::count(vertex_count), rng, options.tune, false);
    reached = out.tuning.reached;
  }
  for (int retry = 0; !reached && retry < 12 && packing.size() > vertex_count; ++retry) {
    out.radius *= std::sqrt(1.03 * static_cast<double>(packing.size()) / static_cast<double>(vertex_count));
    out.sizing = sizing_at(out.radius);
    packing = detail::sample_mps_unchecked(surface, out.sizing, rng);
  }
  if (!reached)
    out.tuning =
        detail::tune_surface(packing, Target::count(vertex_count), rng, options.tune, false);
  // Ids in a spatial order again (the tuning's new disks came anywhere), as relaxation
  // and the meshes read neighbours' data by them.
  packing.order_by_place();
  // The rest length of the springs: the hexagonal spacing of the count reached.
  const double eta = static_cast<double>(packing.size()) / density_unit(packing);
  const double spacing = 1 / relative_radius_for(eta);
  const Progress progress{packing.size(), eta, Phase::relaxation};
  bool cancelled = false;
  relax(
      packing, spacing, options.relax_sweeps, rng,
      [&](int) {
        cancelled = options.tune.on_progress && !options.tune.on_progress(progress);
        return !cancelled;
      },
      options.threads, Maximality::at_end);
  if (cancelled) throw Cancelled("remesh: cancelled by the progress callback during relaxation");

  // tune, relax and open_obtuse_angles keep the packing maximal
  RestrictedDelaunayReuse reuse;  // the mesh after open_obtuse_angles redoes only what moved
  out.mesh = restricted_delaunay(packing, Coverage::maximal, options.threads, &reuse);
  // Relaxation leaves about one triangle in a hundred obtuse: open those angles, in three
  // passes over one mesh (a move can leave an angle nearby still obtuse, which the next
  // pass sees at the disks' new places), then one pass opens the angles below
  // kSharpAngle, which set the mesh's smallest angle: a handful of the 6·10^4 (elephant
  // and eight at 10^4 vertices, seeds 1-4 and 1-3: smallest angles 33.1-37.9 degrees
  // without it, 38.2-40.1 with, the other figures within noise). Twice: against one pass
  // per mesh three times (2026-12-04, 10^4 and 3·10^4 vertices), obtuse triangles on the
  // elephant 0.15 / 0.10 % -> 0.12 / 0.08 %, fandisk 0.93 / 0.58 % -> 0.85 / 0.52 %.
  // Between the two rounds the mesh's edges around the moved disks are flipped toward
  // Delaunay, not meshed anew: the same figures within a triangle or two (four surfaces
  // at 10^4, seeds 1-2), a restricted Delaunay mesh fewer (fandisk: 0.05 s of 0.65).
  // The last line of defence, for the sample, tune and every move since: the packing's
  // check runs beside the last mesh, where more than one thread is allowed (both only
  // read the packing; the mesh's serial parts leave a core idle).
  constexpr int kRounds = 2;
  bool moved_since_mesh = false;
  for (int round = 0; round < kRounds && options.relax_sweeps > 0; ++round) {
    std::size_t moved = 0;
    for (int pass = 0; pass < 3; ++pass) moved += open_obtuse_angles(packing, out.mesh);
    moved += open_sharp_angles(packing, out.mesh, kSharpAngle);
    if (moved == 0) break;
    moved_since_mesh = true;
    if (round + 1 < kRounds) detail::flip_toward_delaunay(out.mesh, centers(packing));
  }
  std::future<std::string> final_check;
  if (moved_since_mesh) {
    if (detail::thread_count(options.threads) > 1) {
      try {
        final_check =
            std::async(std::launch::async, [&packing] { return packing_defect(packing); });
      } catch (const std::system_error&) {  // no thread to be had: the check runs after
      }
    }
    out.mesh = restricted_delaunay(packing, Coverage::maximal, options.threads, &reuse);
  }
  const std::string defect = final_check.valid() ? final_check.get() : packing_defect(packing);
  if (!defect.empty()) {
    throw InternalError("remesh: the packing of the new mesh's vertices failed the final check: " +
                        defect + ". " + detail::kReportBug);
  }
  out.check = check_surface_mesh(out.mesh);
  // The check advises a sampler's user; remesh's denser samples are more vertices.
  const std::string radius_advice = "(a smaller radius)";
  const std::size_t advice = out.check.problems.rfind(radius_advice);
  if (advice != std::string::npos) out.check.problems.replace(advice, radius_advice.size(), "(ask for more vertices)");
  for (const DiskId id : packing.ids()) {
    out.radii.push_back(packing.radius(id));
    out.input_triangles.push_back(packing.point(id).triangle);
    out.on_curves.push_back(packing.flags(id) & kFixed);
  }
  return out;
}

// "<why>, so the vertices were placed with r = R where the surface leaves room and
// smaller radii near ..., down to r_min near (x, y, z)".
std::string grading_note(const RemeshResult& result, const SurfaceDomain& surface, const std::string& why) {
  const std::vector<double>& radii = result.sizing.vertex_radii();
  const auto thinnest = static_cast<std::size_t>(std::min_element(radii.begin(), radii.end()) - radii.begin());
  const Vec3 at = surface.vertices()[thinnest];
  return why + ", so the vertices were placed with r = " + detail::short_text(result.radius) +
         " where the surface leaves room and smaller radii where parts of it face each other closer than r / " +
         detail::short_text(kFeatureShare) + " or feature curves and boundaries come closer than r / " +
         detail::short_text(kCurveGapShare) + ", down to " + detail::short_text(radii[thinnest]) + " near (" +
         detail::short_text(at.x) + ", " + detail::short_text(at.y) + ", " + detail::short_text(at.z) + ")";
}

}  // namespace

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
  if (options.relax_sweeps < 0) {
    throw InvalidInput("remesh: the number of relaxation sweeps must be 0 or more, got " +
                       std::to_string(options.relax_sweeps));
  }
  const SurfaceFeatures& given = surface->features();
  if (options.feature_angle > 0 && given.curves.empty() && given.corners.empty()) {
    auto with_features = std::make_shared<SurfaceDomain>(*surface);
    FeatureOptions detect;
    detect.angle = options.feature_angle;
    with_features->set_features(detect_features(*with_features, detect));
    surface = std::move(with_features);
  }
  const double r = radius_for_count(vertex_count, surface->area(), options.area_fraction);
  const ResourceEstimate need =
      estimate_resources(*surface, SurfaceSizing::constant(r)).tuned_to(static_cast<double>(vertex_count));
  const double limit = options.max_memory > 0 ? options.max_memory : available_memory();
  try {
    check_resources(need, limit);
  } catch (const InvalidInput& e) {
    if (!(need.bytes > limit)) {
      throw InvalidInput("remesh: " + std::to_string(vertex_count) + " vertices are too many: " + e.what(), e.remedy());
    }
    // The memory grows with the count: say how many would fit, not which radius.
    char text[320];
    std::snprintf(text, sizeof text,
                  "remesh: %zu vertices are too many for this surface: their packing needs about %.3g GiB but "
                  "%.3g GiB are allowed; ask for at most about %.0f vertices, or allow more memory",
                  vertex_count, need.bytes / 1073741824.0, limit / 1073741824.0,
                  std::floor(0.9 * static_cast<double>(vertex_count) * limit / need.bytes));
    throw InvalidInput(text, InvalidInput::Remedy::memory);
  }
  // Where r would leave a feature or boundary without disks of its own (curves_fit),
  // smaller radii near it at once. Else one radius first; where its mesh is no manifold
  // of the input's topology (the surface is thinner than r allows somewhere), again with
  // smaller radii there, kept when that mesh is one and still has the count.
  if (!curves_fit(*surface, r)) {
    if (std::optional<RemeshResult> graded = remesh_at(surface, vertex_count, r, true, options)) {
      if (!graded->sizing.is_constant()) {
        graded->grading_note = grading_note(*graded, *surface,
                                            "one radius (" + detail::short_text(r) + ") would leave a stretch of a feature "
                                            "curve or boundary without vertices, next to another one closer than r");
      }
      return *graded;
    }
  }
  RemeshResult out = *remesh_at(surface, vertex_count, r, false, options);
  if (!keeps_topology(out.check, *surface)) {
    std::optional<RemeshResult> graded = remesh_at(surface, vertex_count, r, true, options);
    if (graded && !graded->sizing.is_constant() && keeps_topology(graded->check, *surface) &&
        (graded->tuning.reached || !out.tuning.reached)) {
      out = std::move(*graded);
      out.grading_note = grading_note(out, *surface, "with one radius the mesh was no manifold of the input's topology");
    }
  }
  return out;
}

RemeshResult remesh(const SurfaceDomain& surface, std::size_t vertex_count, const RemeshOptions& options) {
  return remesh(std::make_shared<const SurfaceDomain>(surface), vertex_count, options);
}

}  // namespace disktune
