// SPDX-License-Identifier: GPL-3.0-or-later
// `disktune report`: quality measures of a packing and its periodic Delaunay mesh
// and its spectrum (docs/quality.md), as summary lines, a JSON file, an SVG picture and
// PNG pictures.
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "command_domain.h"
#include "commands.h"
#include "disktune/boundary.h"
#include "disktune/errors.h"
#include "disktune/io.h"
#include "disktune/mesh.h"
#include "disktune/mesh_io.h"
#include "disktune/quality.h"
#include "disktune/quality_json.h"
#include "disktune/report_pictures.h"
#include "disktune/spectrum.h"

namespace disktune::cli {
namespace {

struct ReportArgs {
  std::string input;
  DomainArgs domain;
  std::string json, svg;
  PictureArgs pictures;
  bool no_spectrum = false;
  int spectrum_window = 0;  // 0: automatic
  unsigned threads = 0;     // 0: one per core
};

// "26.50..125.32", or "none" for a part of the mesh without triangles (a thin domain
// has no interior triangle).
std::string angle_range(const PlanarMeshQuality& part) {
  if (part.triangle_count == 0) return "none";
  char text[48];
  std::snprintf(text, sizeof text, "%.2f..%.2f", part.angles.min, part.angles.max);
  return text;
}

// The bond order's line: psi6 and the crystalline grains (nothing under 7 disks).
void say_order(const BondOrder& o) {
  if (o.count == 0) return;
  say("order: psi6 %.3f (local mean %.3f), %.1f %% of the disks hexagonal, "
      "%zu grains (largest %zu disks, %.1f %% of all in grains)\n",
      o.psi6_global, o.psi6_local_mean, 100 * o.hexagonal_share, o.grain_count, o.largest_grain,
      100 * o.grain_share);
}

// A planar domain: the constrained Delaunay mesh, its triangles measured all together,
// inside and along the boundary (no spectrum: it needs the periodic box).
int run_planar_report(const ReportArgs& args, const CommandDomain& domain) {
  Packing packing = domain.read(args.input, false);
  const PlanarMesh mesh = constrained_delaunay(packing, boundary_loops(packing, *domain.planar));
  const PlanarQualityReport q = measure_planar_quality(packing, mesh, domain.area());
  if (!args.json.empty()) write_json(args.json, quality_json(q));
  if (!args.pictures.dir.empty())
    write_report_pictures(args.pictures.dir, q, packing, args.pictures.format);
  if (!args.svg.empty()) write_mesh_svg(args.svg, mesh, packing);
  say(
      "report: %zu disks (%zu on the boundary), eta = %.4f, rho = %.4f, %s, %s, distance >= "
      "%.4f r; angles %.2f..%.2f deg (mean |a-60| %.2f, %.1f %% in [50,70]; interior "
      "triangles %s, boundary triangles %s), beta <= %.4f%s%s\n",
      q.count, q.boundary_count, q.area_fraction, q.relative_radius,
      q.maximal ? "maximal" : "NOT maximal", q.conflict_free ? "conflict-free" : "CONFLICTS",
      q.min_distance_over_r, q.all.angles.min, q.all.angles.max, q.all.angles.mean_abs_dev_60,
      100 * q.all.angles.fraction_50_70, angle_range(q.interior).c_str(), angle_range(q.boundary).c_str(),
      q.all.local_beta.max,
      args.json.empty() ? "" : " -> ", args.json.c_str());
  say_order(q.order);
  return kExitOk;
}

int run_report(const ReportArgs& given) {
  ReportArgs args = given;
  args.domain = with_radius_of(given.domain, given.input);
  std::vector<NamedFile> inputs = domain_files(args.domain);
  inputs.push_back({"the points file", args.input});
  check_files_apart(inputs, {{"--json", args.json}, {"--svg", args.svg}});
  if (names_surface(args.domain))
    return run_surface_report(
        {args.input, args.domain, args.json, args.svg, args.pictures, args.spectrum_window});
  check_output_folder(args.json);
  check_output_folder(args.svg);
  if (!args.pictures.dir.empty()) check_picture_folder(args.pictures.dir);
  const CommandDomain domain = open_domain(args.domain);
  if (domain.planar) return run_planar_report(args, domain);
  if (domain.sizing) {
    throw InvalidInput("report: the periodic box's report is for one radius; give --radius (varying "
                       "radii are reported in planar domains)");
  }
  const Packing packing = domain.read(args.input, false);
  std::optional<Spectrum> spectrum;
  if (!args.no_spectrum) {
    const auto start = std::chrono::steady_clock::now();
    SpectrumOptions options;
    options.window = args.spectrum_window;
    options.threads = args.threads;
    spectrum = measure_spectrum(packing, options);
    const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
    say(
        "spectrum: window |k| < %d (rings to frequency %.2f), peak power %.2f at %.3f, "
        "effective Nyquist %.3f, %.2f s\n",
        spectrum->window, spectrum->reach(), spectrum->peak_power, spectrum->peak_frequency,
        spectrum->effective_nyquist, took.count());
  }
  const TriangleMesh mesh = periodic_delaunay(packing);
  const QualityReport q = measure_quality(packing, mesh, args.domain.radius);
  const Spectrum* s = spectrum ? &*spectrum : nullptr;
  if (!args.json.empty()) write_json(args.json, quality_json(q, s));
  if (!args.pictures.dir.empty())
    write_report_pictures(args.pictures.dir, q, s, &packing, args.pictures.format);
  if (!args.svg.empty()) write_mesh_svg(args.svg, mesh, packing);
  say(
      "report: %zu disks, eta = %.4f, rho = %.4f, %s, %s, distance >= %.4f r, "
      "coverage <= %.4f r, angles %.2f..%.2f deg (mean |a-60| %.2f), beta <= %.4f%s%s\n",
      q.count, q.area_fraction, q.relative_radius, q.maximal ? "maximal" : "NOT maximal",
      q.conflict_free ? "conflict-free" : "CONFLICTS", q.min_distance_over_r, q.max_coverage_over_r,
      q.angles.min, q.angles.max, q.angles.mean_abs_dev_60, q.local_beta.max,
      args.json.empty() ? "" : " -> ", args.json.c_str());
  say_order(q.order);
  return kExitOk;
}

}  // namespace

void add_report_command(CLI::App& app, Action& action) {
  auto args = std::make_shared<ReportArgs>();
  CLI::App* cmd = app.add_subcommand(
      "report",
      "Measure a packing (CSV x,y,r) and its periodic Delaunay mesh: density, spacing, "
      "coverage, maximality, angles, edge lengths, local beta, Voronoi cells, spectrum "
      "(docs/quality.md). On a surface: density, maximality, conflicts, and the restricted "
      "Delaunay mesh's topology, angles, edges, local beta and Hausdorff distance (--json only).");
  reads_file(cmd->add_option("points", args->input,
                              "CSV file of the packing (header x,y,r; x,y,z,r on a surface); - for standard input"))
      ->required();
  add_domain_options(cmd, args->domain);
  writes_file(cmd->add_option("--json", args->json, "Write the full report (with histograms) as JSON"));
  writes_file(cmd->add_option("--svg", args->svg, "Draw the mesh over the disks (at r/2) as an SVG picture"));
  add_picture_options(cmd, args->pictures,
                      "angles.png, edges.png and, in the plane, orientation.png (disks colored "
                      "by their lattice orientation where locally hexagonal), in the periodic box "
                      "spectrum.png, radial_mean.png and anisotropy.png, on a surface surface.png "
                      "(the mesh colored by each triangle's smallest angle)");
  cmd->add_flag("--no-spectrum", args->no_spectrum, "Skip the spectrum (seconds for 1e5 disks)");
  cmd->add_option("--spectrum-window", args->spectrum_window,
                  "Spectrum frequencies |kx|, |ky| < K (default: reach normalised frequency 3, "
                  "capped at N K (2K-1) <= 1e10); at most 4096")
      ->check(whole_number(0, kMaxSpectrumWindow, "--spectrum-window"));
  add_threads_option(cmd, args->threads, "Threads for the spectrum and the checks");
  cmd->callback([args, &action] { action = [args] { return run_report(*args); }; });
}

}  // namespace disktune::cli
