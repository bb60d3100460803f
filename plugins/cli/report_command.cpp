// SPDX-License-Identifier: GPL-3.0-or-later
// `disktune report`: quality measures of a packing and its periodic Delaunay mesh
// (docs/quality.md), as a summary line, a JSON file and an SVG picture.
#include <cstdio>
#include <memory>

#include "commands.h"
#include "disktune/errors.h"
#include "disktune/io.h"
#include "disktune/mesh.h"
#include "disktune/mesh_io.h"
#include "disktune/quality.h"
#include "disktune/quality_json.h"

namespace disktune::cli {
namespace {

struct ReportArgs {
  std::string input;
  DomainArgs domain;
  std::string json, svg;
};

int run_report(const ReportArgs& args) {
  check_output_folder(args.json);
  check_output_folder(args.svg);
  const PeriodicBox box(args.domain.width, args.domain.height);
  const Packing packing = read_packing_csv(args.input, box, args.domain.radius);
  const TriangleMesh mesh = periodic_delaunay(packing);
  const QualityReport q = measure_quality(packing, mesh, args.domain.radius);
  if (!args.json.empty()) write_quality_json(args.json, q);
  if (!args.svg.empty()) write_mesh_svg(args.svg, mesh, packing);
  std::printf(
      "report: %zu disks, eta = %.4f, rho = %.4f, %s, %s, distance >= %.4f r, "
      "coverage <= %.4f r, angles %.2f..%.2f deg (mean |a-60| %.2f), beta <= %.4f%s%s\n",
      q.count, q.area_fraction, q.relative_radius, q.maximal ? "maximal" : "NOT maximal",
      q.conflict_free ? "conflict-free" : "CONFLICTS", q.min_distance_over_r, q.max_coverage_over_r,
      q.angles.min, q.angles.max, q.angles.mean_abs_dev_60, q.local_beta.max,
      args.json.empty() ? "" : " -> ", args.json.c_str());
  return kExitOk;
}

}  // namespace

void add_report_command(CLI::App& app, Action& action) {
  auto args = std::make_shared<ReportArgs>();
  CLI::App* cmd = app.add_subcommand(
      "report",
      "Measure a packing (CSV x,y,r) and its periodic Delaunay mesh: density, spacing, "
      "coverage, maximality, angles, edge lengths, local beta, Voronoi cells (docs/quality.md).");
  cmd->add_option("points", args->input, "CSV file of the packing (header x,y,r)")->required();
  add_domain_options(cmd, args->domain);
  cmd->add_option("--json", args->json, "Write the full report (with histograms) as JSON");
  cmd->add_option("--svg", args->svg, "Draw the mesh over the disks (at r/2) as an SVG picture");
  cmd->callback([args, &action] { action = [args] { return run_report(*args); }; });
}

}  // namespace disktune::cli
