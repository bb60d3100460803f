// SPDX-License-Identifier: GPL-3.0-or-later
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "commands.h"
#include "disktune/density.h"
#include "disktune/errors.h"
#include "disktune/io.h"
#include "disktune/sampling.h"

namespace disktune::cli {

namespace {

struct SampleArgs {
  std::string domain = "periodic";
  SampleJob job;
};

}  // namespace

int run_sample(const SampleJob& job) {
  check_output_folder(job.output);
  check_output_folder(job.svg);
  const PeriodicBox box(job.width, job.height);
  box.validate_radius(job.radius);
  Rng rng(job.seed);
  const auto t0 = std::chrono::steady_clock::now();
  const Packing packing = sample_mps(box, job.radius, rng);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!job.output.empty()) write_points_csv(job.output, packing);
  if (!job.svg.empty()) write_packing_svg(job.svg, packing);
  std::printf("sample: %zu disks, eta = %.4f, rho = %.4f, %.3f s (r = %g, %g x %g periodic box)%s%s\n",
              packing.size(), area_fraction(packing.size(), job.radius, box.area()),
              relative_radius(packing.size(), job.radius, box.area()), seconds, job.radius,
              box.width(), box.height(), job.output.empty() ? "" : " -> ",
              job.output.c_str());
  return kExitOk;
}

void check_output_folder(const std::string& path) {
  if (path.empty()) return;
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (!parent.empty() && !std::filesystem::is_directory(parent)) {
    throw IoError("cannot write '" + path + "': folder '" + parent.string() + "' does not exist");
  }
}

void add_sample_command(CLI::App& app, Action& action) {
  auto args = std::make_shared<SampleArgs>();
  CLI::App* cmd = app.add_subcommand(
      "sample", "Make a maximal Poisson-disk sample (MPS) and write it as CSV (x,y,r).");
  cmd->add_option("--domain", args->domain, "Domain kind; only 'periodic' (a periodic box) for now")
      ->check(CLI::IsMember({"periodic"}))
      ->capture_default_str();
  cmd->add_option("--width", args->job.width, "Width W of the periodic box")->capture_default_str();
  cmd->add_option("--height", args->job.height, "Height H of the periodic box")->capture_default_str();
  cmd->add_option("--radius,-r", args->job.radius,
                  "Conflict radius r: no center closer than r to another; every point within r "
                  "of a center. Needs 0 < r < min(W,H)/2")
      ->required();
  cmd->add_option("--seed", args->job.seed, "Random seed; the same seed gives the same output")
      ->capture_default_str();
  cmd->add_option("--output,-o", args->job.output, "CSV file to write (header x,y,r)");
  cmd->add_option("--svg", args->job.svg, "Also draw the packing as an SVG picture");
  cmd->callback([args, &action] { action = [args] { return run_sample(args->job); }; });
}

}  // namespace disktune::cli
