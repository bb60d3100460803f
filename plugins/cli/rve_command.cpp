// SPDX-License-Identifier: GPL-3.0-or-later
// `disktune rve`: a fiber-composite cross section (rve.h): a random periodic arrangement
// of fibers at an exact count or volume fraction, written as CSV x,y,d.
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "disktune/errors.h"
#include "disktune/fiber_statistics.h"
#include "disktune/io.h"
#include "disktune/quality_json.h"
#include "disktune/rve.h"

namespace disktune::cli {
namespace {

struct RveJob {
  RveSpec spec;
  std::string output, stats;
};

int run_rve(const RveJob& job) {
  check_files_apart({}, {{"--output", job.output}, {"--stats", job.stats}});
  check_output_folder(job.output);
  check_output_folder(job.stats);
  const std::size_t count = rve_fiber_count(job.spec);  // fail before any work
  const auto t0 = std::chrono::steady_clock::now();
  Rve rve;
  try {
    tune_with_progress(0, count, Method::automatic,
                       [&](const TuneOptions& options) {
                         RveSpec spec = job.spec;
                         spec.tune = options;
                         rve = make_rve(spec);
                         return rve.tuning;
                       },
                       "", [] {});
  } catch (const InvalidInput& e) {
    if (e.remedy() != InvalidInput::Remedy::memory) throw;
    throw InvalidInput(std::string(e.what()) + " (--max-memory SIZE)");
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  write_fibers_csv(job.output, rve.centers, std::vector<double>(rve.centers.size(), rve.diameter));
  if (!job.stats.empty()) {
    const FiberStatistics fibers = fiber_statistics(rve.cell, rve.centers, rve.diameter);
    if (rve.sample_centers.size() >= 7) {
      const FiberStatistics sample = fiber_statistics(rve.cell, rve.sample_centers, rve.diameter);
      write_fiber_statistics_json(job.stats, fibers, &sample, rve.gap, job.spec.seed);
    } else {
      write_fiber_statistics_json(job.stats, fibers, nullptr, rve.gap, job.spec.seed);
    }
  }
  std::printf("rve: %zu fibers (%s%zu), vf %.4f, diameter %g, gap %g, cell %g x %g, from a sample of %zu, "
              "phase %s, %.3f s -> %s\n",
              rve.centers.size(), rve.tuning.reached ? "as asked: " : "NOT reached, asked ", count,
              rve.fiber_fraction, rve.diameter, rve.gap, rve.cell.width(), rve.cell.height(), rve.sample_centers.size(),
              to_string(rve.tuning.last_phase).c_str(), seconds, job.output.c_str());
  if (!rve.tuning.reached) {
    std::fprintf(stderr,
                 "disktune: the fiber count was not reached: no phase makes progress beyond %zu fibers (vf %.4f); "
                 "that arrangement was written; ask for fewer fibers or a smaller gap\n",
                 rve.centers.size(), rve.fiber_fraction);
    return kExitNotReached;
  }
  return kExitOk;
}

}  // namespace

void add_rve_command(CLI::App& app, Action& action) {
  auto job = std::make_shared<RveJob>();
  CLI::App* cmd = app.add_subcommand(
      "rve",
      "Make a fiber-composite cross section: a random periodic arrangement of fibers of one "
      "diameter, at an exact fiber count or volume fraction, no two fibers closer than the gap, "
      "and no room left for one more (a maximal sample at center distance D + G, tuned to the "
      "count). Writes CSV x,y,d (fiber centers in the cell; a fiber cut by an edge continues on "
      "the opposite side). docs/rve.md");
  cmd->add_option("--diameter,-d", job->spec.diameter, "Fiber diameter D")->required();
  cmd->add_option("--gap,-g", job->spec.gap, "Least matrix gap G between two fibers (centers at least D + G apart)")
      ->capture_default_str();
  auto* vf = cmd->add_option("--vf", job->spec.fiber_fraction,
                             "Fiber volume fraction vf = N pi (D/2)^2 / (W H) wanted (the count nearest it)");
  auto* fibers = cmd->add_option("--fibers,-n", job->spec.fibers, "Exact number of fibers wanted")
                     ->check(whole_number(1, UINT64_MAX, "--fibers"));
  vf->excludes(fibers);
  cmd->add_option("--width", job->spec.width, "Width W of the periodic cell")->capture_default_str();
  cmd->add_option("--height", job->spec.height, "Height H of the periodic cell")->capture_default_str();
  cmd->add_option("--output,-o", job->output, "CSV file to write (header x,y,d)")->required();
  cmd->add_option("--stats", job->stats,
                  "Also write the arrangement's statistics as JSON: nearest-neighbour distances (1st to "
                  "6th) and orientation, Ripley's K and L, g(r), psi6, Voronoi cell areas; beside them the "
                  "same for the maximal sample it was tuned from (random sequential adsorption), complete "
                  "spatial randomness and the hexagonal lattice");
  add_seed_option(cmd, job->spec.seed);
  add_memory_option(cmd, job->spec.max_memory);
  cmd->callback([job, &action] { action = [job] { return run_rve(*job); }; });
}

}  // namespace disktune::cli
