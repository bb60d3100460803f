// SPDX-License-Identifier: GPL-3.0-or-later
#include "disktune/quality_json.h"

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

}  // namespace disktune
