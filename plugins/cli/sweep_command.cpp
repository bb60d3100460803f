// SPDX-License-Identifier: GPL-3.0-or-later
// `disktune sweep`: the paper's Figs. 7 and 9 as a table. One MPS of the unit periodic
// square is tuned to each area fraction in turn (each row starts from the same MPS);
// each row is measured (angles, beta, edges, spectrum peak, time) and set against a
// CVT mesh (CGAL's Mesh_2 refinement plus Lloyd) with about the same vertex count.
#include <chrono>
#include <cstdio>
#include <memory>
#include <sstream>
#include <vector>

#include "command_domain.h"
#include "commands.h"
#include "disktune/cvt_reference.h"
#include "disktune/density.h"
#include "disktune/io.h"
#include "disktune/mesh.h"
#include "disktune/resources.h"
#include "disktune/quality.h"
#include "disktune/sampling.h"
#include "disktune/spectrum.h"
#include "disktune/tuning.h"

namespace disktune::cli {
namespace {

struct SweepArgs {
  double radius = 0.01;
  std::uint64_t seed = 1;
  int cvt_iterations = 100;
  std::vector<double> etas{0.31, 0.35, 0.45, 0, 0.65, 0.75, 0.80, 0.85, 0.89};  // 0: the MPS
  std::string output;
  double max_memory = 0;  // --max-memory; 0: what the machine has
};

struct Row {
  std::string label;
  std::size_t count;
  bool reached;
  double seconds;
  QualityReport q;
  double peak_power;
  PlanarMeshQuality cvt;
  double cvt_seconds;
};

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::string fixed(double v, int digits) {
  char s[32];
  std::snprintf(s, sizeof s, "%.*f", digits, v);
  return s;
}

std::string percent(double fraction) { return fixed(100 * fraction, 1) + " %"; }

std::string table(const SweepArgs& args, std::size_t mps_count, const std::vector<Row>& rows) {
  std::ostringstream md;
  md << "One MPS of the unit periodic square at r = " << args.radius << " (" << mps_count
     << " disks, seed " << args.seed << "), tuned by the automatic schedule to each eta; CVT: "
     << "CGAL refine_Delaunay_mesh_2 + lloyd_optimize_mesh_2 (at most " << args.cvt_iterations
     << " iterations) in the unit square (not periodic) with about the same vertex count. "
     << "Angles in degrees; beta of CVT vertices off the boundary; edges over r.\n\n";
  md << "| eta | disks | time s | min angle | max angle | mean abs(a-60) | in [50,70] | obtuse "
        "triangles | beta mean | beta max | edge min/r | edge max/r | coverage/r | spectrum peak |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Row& w : rows) {
    md << "| " << w.label << (w.reached ? "" : " (not reached)") << " | " << w.count << " | "
       << fixed(w.seconds, 2) << " | " << fixed(w.q.angles.min, 2) << " | "
       << fixed(w.q.angles.max, 2) << " | " << fixed(w.q.angles.mean_abs_dev_60, 2) << " | "
       << percent(w.q.angles.fraction_50_70) << " | "
       << percent(w.q.angles.fraction_obtuse_triangles) << " | " << fixed(w.q.local_beta.mean, 3)
       << " | " << fixed(w.q.local_beta.max, 3) << " | " << fixed(w.q.edges.min_over_r, 3)
       << " | " << fixed(w.q.edges.max_over_r, 3) << " | " << fixed(w.q.max_coverage_over_r, 3)
       << (w.q.maximal && w.q.conflict_free ? "" : " (NOT maximal and conflict-free)") << " | "
       << fixed(w.peak_power, 2) << " |\n";
  }
  md << "\n| CVT at the count of eta | vertices | time s | min angle | max angle | mean "
        "abs(a-60) | in [50,70] | obtuse triangles | beta mean | beta max | edge min/r | edge "
        "max/r |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Row& w : rows) {
    const PlanarMeshQuality& c = w.cvt;
    md << "| " << w.label << " | " << c.vertex_count << " | " << fixed(w.cvt_seconds, 2) << " | "
       << fixed(c.angles.min, 2) << " | " << fixed(c.angles.max, 2) << " | "
       << fixed(c.angles.mean_abs_dev_60, 2) << " | " << percent(c.angles.fraction_50_70) << " | "
       << percent(c.angles.fraction_obtuse_triangles) << " | " << fixed(c.local_beta.mean, 3)
       << " | " << fixed(c.local_beta.max, 3) << " | " << fixed(c.edges.min_over_r, 3) << " | "
       << fixed(c.edges.max_over_r, 3) << " |\n";
  }
  return md.str();
}

int run_sweep(const SweepArgs& args) {
  check_output_folder(args.output);
  const PeriodicBox box(1, 1);
  const double r = args.radius;
  ResourceEstimate need = estimate_resources(box, r);
  for (double eta : args.etas) {
    if (eta != 0) need = need.tuned_to(target_count(Target::area_fraction(eta), r, box.area()));  // fail early
  }
  check_memory(need, args.max_memory);
  box.validate_radius(r);
  Rng rng(args.seed);
  const auto t0 = std::chrono::steady_clock::now();
  const Packing mps = sample_mps(box, r, rng);
  const double mps_seconds = seconds_since(t0);

  std::vector<Row> rows;
  for (const double eta : args.etas) {
    Row row;
    Packing packing = mps;
    row.reached = true;
    row.seconds = mps_seconds;
    row.label = "MPS " + fixed(area_fraction(mps.size(), r, box.area()), 3);
    if (eta != 0) {
      Rng tune_rng(args.seed + rows.size() + 1);
      const TuneResult res = tune(packing, box, Target::area_fraction(eta), tune_rng);
      row.reached = res.reached;
      row.seconds = res.seconds;
      row.label = fixed(eta, 2);
    }
    row.count = packing.size();
    row.q = measure_quality(packing, periodic_delaunay(packing), r);
    row.peak_power = measure_spectrum(packing).peak_power;
    const CvtReference cvt = cvt_reference_mesh({1, 1}, row.count, args.cvt_iterations);
    row.cvt = measure_planar_mesh(cvt.mesh, r);
    row.cvt_seconds = cvt.refine_seconds + cvt.lloyd_seconds;
    say("sweep: %s: %zu disks in %.2f s; CVT %zu vertices in %.2f s\n",
                 row.label.c_str(), row.count, row.seconds, row.cvt.vertex_count, row.cvt_seconds);
    rows.push_back(std::move(row));
  }
  const std::string md = table(args, mps.size(), rows);
  std::fputs(md.c_str(), stdout);
  if (!args.output.empty()) {
    write_file_atomically(args.output, [&](std::ostream& out) { out << md; });
  }
  return kExitOk;
}

}  // namespace

void add_sweep_command(CLI::App& app, Action& action) {
  auto args = std::make_shared<SweepArgs>();
  CLI::App* cmd = app.add_subcommand(
      "sweep",
      "Tune one MPS of the unit periodic square to a list of area fractions and tabulate "
      "mesh quality, spectrum peak and time against CGAL's CVT mesh (Markdown)");
  cmd->add_option("--radius,-r", args->radius, "Disk radius r")->capture_default_str();
  cmd->add_option("--eta", args->etas, "Area fractions to tune to; 0 stands for the MPS itself")
      ->capture_default_str();
  cmd->add_option("--cvt-iterations", args->cvt_iterations, "Most Lloyd iterations of the CVT")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  add_seed_option(cmd, args->seed);
  add_memory_option(cmd, args->max_memory);
  cmd->add_option("--output,-o", args->output, "Also write the table to this Markdown file");
  cmd->callback([args, &action] { action = [args] { return run_sweep(*args); }; });
}

}  // namespace disktune::cli
