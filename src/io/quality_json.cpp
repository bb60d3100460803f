// SPDX-License-Identifier: GPL-3.0-or-later
#include "disktune/quality_json.h"

#include <cmath>

#include <nlohmann/json.hpp>

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

}  // namespace

std::string fiber_statistics_json(const FiberStatistics& fibers, const FiberStatistics* sample, double gap,
                                  std::uint64_t seed) {
  constexpr double kPi = 3.14159265358979323846;
  const double area = fibers.width * fibers.height, n = static_cast<double>(fibers.count), d = fibers.diameter;
  json csr_nearest = json::array();
  for (int k = 1; k <= 6; ++k) csr_nearest.push_back(poisson_nearest_mean(k, n / area) / d);
  json csr_k = json::array();
  for (const double r : fibers.r) csr_k.push_back(kPi * r * r);
  const double lattice_spacing = std::sqrt(2 * area / (std::sqrt(3.0) * n));
  json out;
  out["rve"] = {{"fibers", fibers.count}, {"width", fibers.width},  {"height", fibers.height},
                {"diameter", d},          {"gap", gap},             {"fiber_fraction", fibers.fiber_fraction},
                {"seed", seed}};
  out["statistics"] = to_json(fibers);
  if (sample) out["rsa"] = to_json(*sample);
  out["csr"] = {{"nearest_mean_over_d", csr_nearest}, {"ripley_k_over_d2", csr_k}, {"ripley_l_over_d", fibers.r},
                {"pair_correlation", 1}, {"voronoi_area_cv", kPoissonVoronoiAreaCv}};
  out["hexagonal"] = {{"nearest_over_d", lattice_spacing / d}, {"psi6_global", 1}, {"psi6_local_mean", 1},
                      {"voronoi_area_cv", 0}};
  return out.dump(2) + "\n";
}

void write_fiber_statistics_json(const std::string& path, const FiberStatistics& fibers, const FiberStatistics* sample,
                                 double gap, std::uint64_t seed) {
  write_text(path, fiber_statistics_json(fibers, sample, gap, seed));
}

}  // namespace disktune
