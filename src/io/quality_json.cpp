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
  j["angles"] = {{"min", q.angles.min},
                 {"max", q.angles.max},
                 {"mean_abs_dev_60", q.angles.mean_abs_dev_60},
                 {"fraction_50_70", q.angles.fraction_50_70},
                 {"fraction_obtuse_triangles", q.angles.fraction_obtuse_triangles},
                 {"histogram", to_json(q.angles.histogram)}};
  j["edges"] = {{"min_over_r", q.edges.min_over_r},
                {"max_over_r", q.edges.max_over_r},
                {"histogram", to_json(q.edges.histogram)}};
  j["local_beta"] = {{"min", q.local_beta.min},
                     {"mean", q.local_beta.mean},
                     {"max", q.local_beta.max},
                     {"histogram", to_json(q.local_beta.histogram)}};
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
  const std::string text = quality_json(report, spectrum);
  write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

}  // namespace disktune
