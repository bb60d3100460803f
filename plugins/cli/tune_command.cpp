// SPDX-License-Identifier: GPL-3.0-or-later
// `disktune tune`: from an MPS (made here, or read with --input) to exactly the
// number of disks asked for, by disk injection or ejection.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "command_domain.h"
#include "commands.h"
#include "disktune/density.h"
#include "disktune/errors.h"
#include "disktune/io.h"
#include "disktune/sampling.h"
#include "disktune/time_left.h"
#include "disktune/tuning.h"
#include "disktune/voids.h"
#include "progress_bar.h"

namespace disktune::cli {
namespace {

struct TuneArgs {
  DomainArgs domain;
  std::size_t target_count = 0;
  double target_fraction = 0, target_rho = 0;
  std::string method = "auto";
  std::string input, output, svg;
  std::uint64_t seed = 1;
  int relax_sweeps = 0;
  unsigned threads = 0;  // 0: one per core
};


}  // namespace

int run_tune(const TuneJob& given) {
  TuneJob job = given;
  job.domain = with_radius_of(given.domain, given.input);
  std::vector<NamedFile> inputs = domain_files(job.domain);
  inputs.push_back({"--input", job.input});
  check_files_apart(inputs, {{"--output", job.output}, {"--svg", job.svg}}, "--output");
  if (names_surface(job.domain)) return run_surface_tune(job);
  check_output_folder(job.output);
  check_output_folder(job.svg);
  const CommandDomain domain = open_domain(job.domain);
  const double boundary = domain.planar ? boundary_unit(*domain.planar, domain.sizing.get(), domain.radius) : 0;
  const std::size_t target = target_count_for_unit(job.target, domain.unit, boundary);  // fail early
  check_memory(domain, job.domain, static_cast<double>(target));
  if (job.input.empty()) require_output(job.output, job.svg, "tune");
  Rng rng(job.seed);
  const auto t0 = std::chrono::steady_clock::now();
  Packing packing = job.input.empty() ? domain.sample(rng) : domain.read(job.input, true);
  require_output(job.output, job.svg, "tune");  // after the input's own checks
  const std::size_t start = packing.size();

  const auto write_output = [&] { write_points_csv(job.output, packing); };
  const TuneResult res = tune_with_progress(
      target, job.method,
      [&](const TuneOptions& options) { return domain.tune(packing, job.target, rng, options); },
      job.output, write_output);
  const double spacing = relax_spacing(packing.size(), domain.unit);
  relax(packing, spacing, job.relax_sweeps, rng);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  if (!job.output.empty()) write_output();
  if (!job.svg.empty()) write_packing_svg(job.svg, packing);
  return report_tune(start, res, domain.density_text(res.count), seconds, relaxed_text(job.relax_sweeps), job.output);
}

double relax_spacing(std::size_t count, double unit) {
  return 1 / relative_radius_for(static_cast<double>(count) / unit);
}

std::string relaxed_text(int sweeps) {
  return sweeps > 0 ? ", relaxed " + std::to_string(sweeps) + (sweeps == 1 ? " sweep" : " sweeps") : "";
}

TuneResult tune_with_progress(std::size_t target, Method method,
                              const std::function<TuneResult(const TuneOptions&)>& run,
                              const std::string& output,
                              const std::function<void()>& write_output) {
  ProgressBar bar("tune");
  TuneOptions options;
  options.method = method;
  // The bar follows the running phase's time, as PhaseTimeLeft estimates it, not the
  // count: the last disks of a phase take the longest.
  PhaseTimeLeft time_left;
  options.on_progress = [&](const Progress& p) {
    time_left.add(bar.seconds(), p);
    const double left = time_left.seconds_left(), f = time_left.phase_fraction();
    char when[64];
    if (std::isnan(left)) {
      std::snprintf(when, sizeof when, "time left not known yet");
    } else if (std::isinf(left)) {
      std::snprintf(when, sizeof when, "slowing to a stop");
    } else {
      std::snprintf(when, sizeof when, "%.0f %%, about %.*f s left", 100 * f,
                    left < 1    ? 2
                    : left < 10 ? 1
                                : 0,
                    left);
    }
    char status[160];
    std::snprintf(status, sizeof status, "%s: %s; %zu/%zu disks, eta %.4f",
                  to_string(p.phase).c_str(), when, p.count, target, p.area_fraction);
    bar.update(f, status);
    return true;
  };
  try {
    const TuneResult res = run(options);
    bar.clear();
    return res;
  } catch (const InternalError& e) {
    bar.clear();
    if (output.empty()) throw;
    write_output();
    throw InternalError(std::string(e.what()) + ". That packing was written to " + output);
  }
}

int report_tune(std::size_t start, const TuneResult& res, const std::string& density,
                double seconds, const std::string& where, const std::string& output) {
  say("tune: %zu -> %zu disks (target %zu%s), %s, phase %s, %.3f s%s%s%s\n", start, res.count,
      res.target, res.reached ? ", reached" : ", NOT reached", density.c_str(),
      to_string(res.last_phase).c_str(), seconds, where.c_str(), output.empty() ? "" : " -> ",
      output.c_str());
  if (!res.reached) {
    std::fprintf(stderr,
                 "disktune: the target was not reached: no phase makes progress beyond %zu disks "
                 "(%s)%s\n",
                 res.count, density.c_str(),
                 output.empty() ? "" : "; the closest packing was written");
    return kExitNotReached;
  }
  return kExitOk;
}

void add_tune_command(CLI::App& app, Action& action) {
  auto args = std::make_shared<TuneArgs>();
  CLI::App* cmd = app.add_subcommand(
      "tune",
      "Tune a maximal packing to exactly the number of disks asked for: disk injection to go "
      "denser, disk ejection to go sparser.");
  add_domain_options(cmd, args->domain);
  args->domain.guarded = true;
  add_memory_option(cmd, args->domain.max_memory);
  auto* count = cmd->add_option("--target-count", args->target_count, "Exact number of disks wanted")
                    ->check(whole_number(1, UINT64_MAX, "--target-count"));
  auto* fraction = cmd->add_option("--target-fraction", args->target_fraction,
                                   "Area fraction eta = N pi (r/2)^2 / A wanted (MPS ~0.547, hex 0.9069)");
  auto* rho = cmd->add_option("--target-rho", args->target_rho,
                              "Relative radius rho = r / sqrt(2A / (sqrt(3) N)) wanted (below 1)");
  count->excludes(fraction)->excludes(rho);
  fraction->excludes(rho);
  cmd->add_option(
         "--method", args->method,
         "auto: denser in the periodic box by squeeze, then grain injection (switching at "
         "eta 0.82), in a planar domain by void, then repeller, then grain injection "
         "(switching at 0.70 and 0.78, or when a phase stalls); one crystal where the grains "
         "stall, near 0.86; to eta 0.84 and beyond grains from the start; on a curved surface "
         "void, then crystal injection from eta 0.75; sparser by sifting, then "
         "attractor, then "
         "crystal ejection, then attractor ejection over three rings of neighbours (on a "
         "surface before the crystal); or one phase alone: void, repeller, crystal (one "
         "ordered crystal), grains (crystals from many nuclei at random orientations), squeeze "
         "(the periodic box: new disks at the largest holes, conflicts pushed apart, voids "
         "refilled; random to eta 0.82), angle "
         "(repel from the circumcenters of obtuse Delaunay triangles), sift, attractor (one "
         "ring, then three), crystal-eject")
      ->check(CLI::IsMember({"auto", "void", "repeller", "crystal", "grains", "squeeze", "angle",
                             "sift", "attractor", "crystal-eject"}))
      ->capture_default_str();
  reads_file(cmd->add_option("--input,-i", args->input,
                             "Start from this CSV (x,y,r, or x,y,z,r on a surface; a conflict-free maximal "
                             "packing; - for standard input) instead of a new MPS"));
  add_seed_option(cmd, args->seed);
  cmd->add_option(
         "--relax", args->relax_sweeps,
         "After tuning, this many relaxation sweeps: each free disk moves toward a hexagonal "
         "spacing of its neighbours, conflict-free and maximal after every step (on a surface "
         "conflict-free after every step and maximal at the end, as remesh does: about twice "
         "as fast), the count unchanged; the triangles of the mesh come closer to equilateral, "
         "the packing more regular (remesh uses 30)")
      ->check(whole_number(0, 10000, "--relax"));
  add_threads_option(cmd, args->threads, "Threads for --relax on a surface and the final check");
  writes_file(cmd->add_option("--output,-o", args->output, "CSV file to write (header x,y,r; x,y,z,r on a surface)"));
  writes_file(cmd->add_option("--svg", args->svg, "Also draw the packing (frozen crystal disks in blue)"));
  cmd->callback([args, cmd, &action] {
    if (cmd->count("--target-count") + cmd->count("--target-fraction") + cmd->count("--target-rho") != 1) {
      throw CLI::ValidationError("tune", "give one target: --target-count, --target-fraction or --target-rho");
    }
    TuneJob job;
    job.domain = args->domain;
    job.target = cmd->count("--target-count") ? Target::count(args->target_count)
                 : cmd->count("--target-fraction") ? Target::area_fraction(args->target_fraction)
                                                   : Target::relative_radius(args->target_rho);
    job.method = method_named(args->method);
    job.input = args->input, job.output = args->output, job.svg = args->svg;
    job.seed = args->seed;
    job.relax_sweeps = args->relax_sweeps;
    job.threads = args->threads;
    action = [job] { return run_tune(job); };
  });
}

}  // namespace disktune::cli
