// SPDX-License-Identifier: GPL-3.0-or-later
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "command_domain.h"
#include "commands.h"
#include "disktune/density.h"
#include "disktune/errors.h"
#include "disktune/io.h"
#include "disktune/sampling.h"

namespace disktune::cli {

int run_sample(const SampleJob& job) {
  check_files_apart(domain_files(job.domain), {{"--output", job.output}, {"--svg", job.svg}});
  if (names_surface(job.domain)) return run_surface_sample(job);
  check_output_folder(job.output);
  check_output_folder(job.svg);
  const CommandDomain domain = open_domain(job.domain);
  require_output(job.output, job.svg, "sample");
  Rng rng(job.seed);
  const auto t0 = std::chrono::steady_clock::now();
  const Packing packing = domain.sample(rng);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!job.output.empty()) write_points_csv(job.output, packing);
  if (!job.svg.empty()) write_packing_svg(job.svg, packing);
  say("sample: %zu disks, %s, %.3f s (%s, %s)%s%s\n", packing.size(),
      domain.density_text(packing.size()).c_str(), seconds, domain.radius_text().c_str(),
      domain.describe().c_str(), job.output.empty() ? "" : " -> ", job.output.c_str());
  return kExitOk;
}

void add_domain_options(CLI::App* cmd, DomainArgs& domain) {
  cmd->add_option("--domain", domain.kind,
                  "'periodic' (a W x H periodic box); a planar domain file: .poly (Triangle's "
                  "format: outer boundary and holes), .off or .obj (a flat triangle mesh, all z "
                  "equal, whose boundary loops bound the domain), every polygon vertex getting a "
                  "fixed disk; or a curved surface: a .off, .obj (not flat), .ply or .stl triangle "
                  "mesh (a 2-manifold, possibly with boundary curves, which get fixed disks); "
                  "surface samples are CSV x,y,z,r")
      ->capture_default_str();
  const auto box_size_given = [&domain](const std::string&) { domain.has_box_size = true; };
  cmd->add_option("--width", domain.width, "Width W of the periodic box")->capture_default_str()->each(box_size_given);
  cmd->add_option("--height", domain.height, "Height H of the periodic box")->capture_default_str()->each(box_size_given);
  cmd->add_option("--radius,-r", domain.radius,
                  "Conflict radius r: no center closer than r to another; every point within r "
                  "of a center. In the box 0 < r < min(W,H)/2")
      ->each([&domain](const std::string&) { domain.has_radius = true; });
  cmd->add_option("--sizing", domain.sizing,
                  "Radii that vary over the domain, instead of --radius: a number, an expression "
                  "in x and y (e.g. '0.005 + 0.01*x'), a grid file, or boundary:RMIN,RMAX,G "
                  "(r grows with the distance to a planar domain's boundary); docs/sizing.md. On "
                  "a surface: a number, an expression in x, y and z, curvature[:RMIN,RMAX] "
                  "(smaller where the surface bends more), or auto:RMAX (smaller where the surface "
                  "faces itself closely, as thin walls and ledges do, or its feature curves and "
                  "boundaries come close)");
  cmd->add_option(
         "--features", domain.features,
         "On a surface: edges where the surface folds by more than ANGLE degrees (the "
         "angle between their triangles' normals) are sharp features, chained into curves "
         "that hold fixed disks as open boundaries do, so the mesh keeps them as edges; "
         "ANGLE:STRAY also drops stray folds, groups of them with a loose end shorter than "
         "STRAY times the bounding-box diagonal (default 0.2; 0 keeps all); 'none' for no "
         "features (docs/surfaces.md)")
      ->capture_default_str()
      ->each([&domain](const std::string&) { domain.has_features = true; });
}

void add_sample_command(CLI::App& app, Action& action) {
  auto job = std::make_shared<SampleJob>();
  CLI::App* cmd = app.add_subcommand(
      "sample", "Make a maximal Poisson-disk sample (MPS) and write it as CSV (x,y,r).");
  add_domain_options(cmd, job->domain);
  job->domain.guarded = true;
  add_memory_option(cmd, job->domain.max_memory);
  add_seed_option(cmd, job->seed);
  add_threads_option(cmd, job->threads,
                     "Threads for the sample's tests of darts and cells and its final check");
  writes_file(cmd->add_option("--output,-o", job->output, "CSV file to write (header x,y,r; x,y,z,r on a surface)"));
  writes_file(cmd->add_option("--svg", job->svg, "Also draw the packing as an SVG picture (not on a surface)"));
  cmd->callback([job, &action] { action = [job] { return run_sample(*job); }; });
}

}  // namespace disktune::cli
