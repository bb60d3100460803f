// SPDX-License-Identifier: GPL-3.0-or-later
#include "disktune/quality_json.h"

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "disktune/errors.h"
#include "disktune/io.h"

namespace disktune {
namespace {

using json = nlohmann::ordered_json;  // keys in the order written here

json to_json(const Histogram& h) {
  return {{"lo", h.lo}, {"bin_width", h.bin_width}, {"counts", h.counts}, {"overflow", h.overflow}};
}

json to_json(const Statistics& s) {
  return {{"min", s.min}, {"mean", s.mean}, {"max", s.max}, {"stddev", s.stddev}};
}

json to_json(const QualityReport::Angles& a) {
  return {{"min", a.min},
          {"max", a.max},
          {"mean_abs_dev_60", a.mean_abs_dev_60},
          {"fraction_50_70", a.fraction_50_70},
          {"fraction_obtuse_triangles", a.fraction_obtuse_triangles},
          {"histogram", to_json(a.histogram)}};
}

json to_json(const QualityReport::Edges& e) {
  return {{"min_over_r", e.min_over_r}, {"max_over_r", e.max_over_r}, {"histogram", to_json(e.histogram)}};
}

json to_json(const QualityReport::LocalBeta& b) {
  return {{"min", b.min}, {"mean", b.mean}, {"max", b.max}, {"histogram", to_json(b.histogram)}};
}

// A mesh's measures (PlanarMeshQuality, SurfaceMeshQuality); `hausdorff`, when given,
// stands after the counts. Measures of nothing (no triangle, as in a thin domain's
// interior; no interior vertex) are null, not zeros that read as figures.
template <class MeshQuality>
json mesh_json(const MeshQuality& m, const double* hausdorff = nullptr) {
  json j;
  j["vertex_count"] = m.vertex_count;
  j["triangle_count"] = m.triangle_count;
  j["interior_vertex_count"] = m.interior_vertex_count;
  if (hausdorff) j["hausdorff"] = *hausdorff;
  j["angles"] = m.triangle_count ? to_json(m.angles) : json(nullptr);
  j["edges"] = m.triangle_count ? to_json(m.edges) : json(nullptr);
  j["local_beta"] = m.interior_vertex_count ? to_json(m.local_beta) : json(nullptr);
  return j;
}

void write_text(const std::string& path, const std::string& text) {
  write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

// The bond order's figures (not its per-disk arrays); null when it was not measured.
json order_json(const BondOrder& o) {
  if (o.count == 0) return nullptr;
  return {{"psi6_global", o.psi6_global},
          {"psi6_local_mean", o.psi6_local_mean},
          {"hexagonal_share", o.hexagonal_share},
          {"hexagonal_above", kHexagonalPsi6},
          {"grains",
           {{"count", o.grain_count},
            {"largest", o.largest_grain},
            {"mean_size", o.grain_mean_size},
            {"share", o.grain_share},
            {"angle_within_degrees", kGrainAngle},
            {"min_size", kMinGrain}}}};
}

}  // namespace

std::string quality_json(const QualityReport& q, const Spectrum* spectrum) {
  json j;
  j["radius"] = q.radius;
  j["box"] = {{"width", q.width}, {"height", q.height}};
  j["count"] = q.count;
  j["triangle_count"] = q.triangle_count;
  j["edge_count"] = q.edge_count;
  j["area_fraction"] = q.area_fraction;
  j["relative_radius"] = q.relative_radius;
  j["min_distance_over_r"] = q.min_distance_over_r;
  j["max_coverage_over_r"] = q.max_coverage_over_r;
  j["maximal"] = q.maximal;
  j["conflict_free"] = q.conflict_free;
  j["angles"] = to_json(q.angles);
  j["edges"] = to_json(q.edges);
  j["local_beta"] = to_json(q.local_beta);
  j["voronoi"] = {{"aspect_ratio", to_json(q.voronoi.aspect_ratio)},
                  {"cell_area", to_json(q.voronoi.cell_area)},
                  {"cell_area_cv", q.voronoi.cell_area_cv}};
  j["order"] = order_json(q.order);
  if (spectrum) {
    const Spectrum& s = *spectrum;
    j["spectrum"] = {{"window", s.window},
                     {"frequency_unit", s.frequency_unit},
                     {"radial_mean", s.radial_mean},
                     {"anisotropy_db", s.anisotropy_db},
                     {"peak_power", s.peak_power},
                     {"peak_frequency", s.peak_frequency},
                     {"effective_nyquist", s.effective_nyquist}};
  }
  return j.dump(2) + "\n";
}

void write_quality_json(const std::string& path, const QualityReport& report,
                        const Spectrum* spectrum) {
  write_text(path, quality_json(report, spectrum));
}

std::string quality_json(const PlanarQualityReport& q) {
  json j;
  j["radius"] = q.radius;
  j["area"] = q.area;
  j["count"] = q.count;
  j["boundary_count"] = q.boundary_count;
  j["area_fraction"] = q.area_fraction;
  j["relative_radius"] = q.relative_radius;
  j["min_distance_over_r"] = q.min_distance_over_r;
  j["maximal"] = q.maximal;
  j["conflict_free"] = q.conflict_free;
  j["mesh"] = mesh_json(q.all);
  j["interior_triangles"] = mesh_json(q.interior);
  j["boundary_triangles"] = mesh_json(q.boundary);
  j["order"] = order_json(q.order);
  return j.dump(2) + "\n";
}

void write_quality_json(const std::string& path, const PlanarQualityReport& report) {
  write_text(path, quality_json(report));
}

std::string quality_json(const SurfaceMeshQuality& q) {
  return mesh_json(q, &q.hausdorff).dump(2) + "\n";
}

void write_quality_json(const std::string& path, const SurfaceMeshQuality& quality) {
  write_text(path, quality_json(quality));
}

namespace {

json to_json(const FiberStatistics& s) {
  json nearest = json::array(), histograms = json::array(), local = json::array();
  for (const auto& w : s.local_fraction)
    local.push_back({{"side_over_d", w.side}, {"windows", w.windows}, {"fraction", to_json(w.fraction)}});
  for (int k = 0; k < 6; ++k) nearest.push_back(to_json(s.nearest[k])), histograms.push_back(to_json(s.nearest_histogram[k]));
  return {{"fibers", s.count},
          {"fiber_fraction", s.fiber_fraction},
          {"nearest_over_d", nearest},
          {"nearest_histograms", histograms},
          {"nearest_orientation_degrees", to_json(s.nearest_orientation)},
          {"r_over_d", s.r},
          {"ripley_k_over_d2", s.ripley_k},
          {"ripley_l_over_d", s.ripley_l},
          {"pair_correlation", s.pair_correlation},
          {"psi6_global", s.psi6_global},
          {"psi6_local_mean", s.psi6_local_mean},
          {"psi6_hexagonal_share", s.psi6_hexagonal_share},
          {"psi6_local_histogram", to_json(s.psi6_local)},
          {"voronoi_area_cv", s.voronoi_area_cv},
          {"local_fraction", local}};
}

json rve_json(const FiberStatistics& fibers, double gap, std::uint64_t seed) {
  return {{"fibers", fibers.count},         {"width", fibers.width},
          {"height", fibers.height},        {"diameter", fibers.diameter},
          {"diameters", to_json(fibers.diameters)}, {"gap", gap},
          {"fiber_fraction", fibers.fiber_fraction}, {"seed", seed}};
}

// Complete spatial randomness and the hexagonal lattice at the arrangement's intensity,
// their fibers equal, of the fraction's diameter (the root mean square).
void add_references(json& out, const FiberStatistics& fibers) {
  constexpr double kPi = 3.14159265358979323846;
  const double area = fibers.width * fibers.height, n = static_cast<double>(fibers.count), d = fibers.diameter;
  const double fiber = fibers.diameter_rms;
  json csr_nearest = json::array();
  for (int k = 1; k <= 6; ++k) csr_nearest.push_back(poisson_nearest_mean(k, n / area) / d);
  json csr_k = json::array();
  for (const double r : fibers.r) csr_k.push_back(kPi * r * r);
  const double lattice_spacing = std::sqrt(2 * area / (std::sqrt(3.0) * n));
  // The local fraction at the arrangement's window sizes (the lattice: as many windows
  // as the arrangement's, at least 16 by 16).
  json csr_local = json::array(), lattice_local = json::array();
  for (const auto& w : fibers.local_fraction) {
    csr_local.push_back({{"side_over_d", w.side}, {"stddev", poisson_local_fraction_stddev(w.side * d, fiber, n / area)}});
    const auto per_row = std::max<std::size_t>(16, static_cast<std::size_t>(std::ceil(std::sqrt(double(w.windows)))));
    const auto lattice = hexagonal_local_fraction(w.side * d, fiber, n / area, per_row);
    lattice_local.push_back({{"side_over_d", w.side}, {"windows", lattice.windows}, {"min", lattice.fraction.min},
                             {"mean", lattice.fraction.mean}, {"max", lattice.fraction.max},
                             {"stddev", lattice.fraction.stddev}});
  }
  out["csr"] = {{"nearest_mean_over_d", csr_nearest}, {"ripley_k_over_d2", csr_k}, {"ripley_l_over_d", fibers.r},
                {"pair_correlation", 1}, {"voronoi_area_cv", kPoissonVoronoiAreaCv}, {"local_fraction", csr_local}};
  out["hexagonal"] = {{"nearest_over_d", lattice_spacing / d}, {"psi6_global", 1}, {"psi6_local_mean", 1},
                      {"voronoi_area_cv", 0}, {"local_fraction", lattice_local}};
}

// Min, mean, max and stddev of one figure over the realizations.
template <class Figure>
json spread(const std::vector<FiberStatistics>& all, Figure&& figure) {
  Statistics s;
  s.min = s.max = figure(all.front());
  double sum = 0, sum2 = 0;
  for (const FiberStatistics& f : all) {
    const double v = figure(f);
    s.min = std::min(s.min, v), s.max = std::max(s.max, v), sum += v;
  }
  s.mean = sum / static_cast<double>(all.size());
  for (const FiberStatistics& f : all) sum2 += (figure(f) - s.mean) * (figure(f) - s.mean);
  s.stddev = std::sqrt(sum2 / static_cast<double>(all.size()));
  return to_json(s);
}

}  // namespace

std::string fiber_statistics_json(const FiberStatistics& fibers, const FiberStatistics* sample, double gap,
                                  std::uint64_t seed) {
  json out;
  out["rve"] = rve_json(fibers, gap, seed);
  out["statistics"] = to_json(fibers);
  if (sample) out["rsa"] = to_json(*sample);
  add_references(out, fibers);
  return out.dump(2) + "\n";
}

std::string fiber_ensemble_json(const std::vector<FiberStatistics>& fibers, const std::vector<FiberStatistics>& samples,
                                double gap, std::uint64_t first_seed) {
  if (fibers.empty() || (!samples.empty() && samples.size() != fibers.size())) {
    throw InvalidInput("fiber_ensemble_json: no realization, or not one sample for each");
  }
  json out;
  out["rve"] = rve_json(fibers.front(), gap, first_seed);
  out["rve"]["realizations"] = fibers.size();
  json ensemble;
  ensemble["psi6_global"] = spread(fibers, [](const FiberStatistics& f) { return f.psi6_global; });
  ensemble["psi6_local_mean"] = spread(fibers, [](const FiberStatistics& f) { return f.psi6_local_mean; });
  ensemble["psi6_hexagonal_share"] = spread(fibers, [](const FiberStatistics& f) { return f.psi6_hexagonal_share; });
  ensemble["voronoi_area_cv"] = spread(fibers, [](const FiberStatistics& f) { return f.voronoi_area_cv; });
  json nearest = json::array(), local = json::array(), g = json::array(), k_mean = json::array();
  for (int k = 0; k < 6; ++k)
    nearest.push_back(spread(fibers, [k](const FiberStatistics& f) { return f.nearest[k].mean; }));
  for (std::size_t w = 0; w < fibers.front().local_fraction.size(); ++w) {
    local.push_back({{"side_over_d", fibers.front().local_fraction[w].side},
                     {"stddev", spread(fibers, [w](const FiberStatistics& f) { return f.local_fraction[w].fraction.stddev; })}});
  }
  for (std::size_t i = 0; i < fibers.front().r.size(); ++i) {
    double gi = 0, ki = 0;
    for (const FiberStatistics& f : fibers) gi += f.pair_correlation[i], ki += f.ripley_k[i];
    g.push_back(gi / static_cast<double>(fibers.size())), k_mean.push_back(ki / static_cast<double>(fibers.size()));
  }
  ensemble["nearest_mean_over_d"] = nearest;
  ensemble["local_fraction_stddev"] = local;
  ensemble["r_over_d"] = fibers.front().r;
  ensemble["pair_correlation_mean"] = g;
  ensemble["ripley_k_over_d2_mean"] = k_mean;
  out["ensemble"] = ensemble;
  json each = json::array();
  for (std::size_t k = 0; k < fibers.size(); ++k) {
    json one = {{"seed", first_seed + k}, {"statistics", to_json(fibers[k])}};
    if (!samples.empty()) one["rsa"] = to_json(samples[k]);
    each.push_back(one);
  }
  out["realizations"] = each;
  add_references(out, fibers.front());
  return out.dump(2) + "\n";
}

void write_fiber_statistics_json(const std::string& path, const FiberStatistics& fibers, const FiberStatistics* sample,
                                 double gap, std::uint64_t seed) {
  write_text(path, fiber_statistics_json(fibers, sample, gap, seed));
}

void write_fiber_ensemble_json(const std::string& path, const std::vector<FiberStatistics>& fibers,
                               const std::vector<FiberStatistics>& samples, double gap, std::uint64_t first_seed) {
  write_text(path, fiber_ensemble_json(fibers, samples, gap, first_seed));
}

}  // namespace disktune
