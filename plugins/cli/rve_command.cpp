// SPDX-License-Identifier: GPL-3.0-or-later
// `disktune rve`: a fiber-composite cross section (rve.h): a random periodic arrangement
// of fibers at an exact count or volume fraction, written as CSV x,y,d, and its periodic
// finite-element mesh (rve_mesh.h) as Gmsh MSH and Abaqus input.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "disktune/errors.h"
#include "disktune/fiber_statistics.h"
#include "disktune/io.h"
#include "disktune/quality_json.h"
#include "disktune/report_pictures.h"
#include "disktune/rve.h"
#include "disktune/rve_mesh.h"

namespace disktune::cli {
namespace {

struct RveJob {
  RveSpec spec;
  RveMeshSpec mesh;
  std::string output, stats, msh, inp, diameters;
  PictureArgs pictures;
  std::size_t realizations = 1;
  unsigned threads = 0;  // for the realizations; 0: one per core
  bool mesh_options = false;  // --fiber-segments or --element-size given
  bool diameter_given = false;  // --diameter or --diameters
};

// Realization k's file: `file` itself for one, else NAME-k.EXT (k from 1).
std::string output_of(const RveJob& job, const std::string& file, std::size_t k) {
  if (job.realizations == 1 || file.empty()) return file;
  const std::filesystem::path path(file);
  std::filesystem::path named = path;
  named.replace_filename(path.stem().string() + "-" + std::to_string(k + 1) + path.extension().string());
  return named.string();
}

std::vector<Rve> make_all(const RveJob& job, std::size_t count) {
  try {
    if (job.realizations > 1) return make_rves(job.spec, job.realizations, job.threads);
    std::vector<Rve> one(1);
    tune_with_progress(
        count, Method::automatic,
        [&](const TuneOptions& options) {
          RveSpec spec = job.spec;
          spec.tune = options;
          one[0] = make_rve(spec);
          return one[0].tuning;
        },
        "", [] {});
    return one;
  } catch (const InvalidInput& e) {
    if (e.remedy() != InvalidInput::Remedy::memory) throw;
    throw InvalidInput(std::string(e.what()) + " (--max-memory SIZE)");
  }
}

void write_statistics(const RveJob& job, const std::vector<Rve>& rves) {
  std::vector<FiberStatistics> fibers, samples;
  const std::size_t measured = job.stats.empty() ? 1 : rves.size();  // the pictures show the first only
  for (std::size_t k = 0; k < measured; ++k) {
    const Rve& rve = rves[k];
    fibers.push_back(fiber_statistics(rve.cell, rve.centers, rve.diameters));
    if (rve.sample_centers.size() >= 7) {
      samples.push_back(fiber_statistics(rve.cell, rve.sample_centers, rve.sample_diameter));
    }
  }
  if (samples.size() != fibers.size()) samples.clear();  // a sample of under 7 fibers has no statistics
  if (!job.pictures.dir.empty()) {                       // the first realization's
    write_fiber_pictures(job.pictures.dir, rves[0].cell, rves[0].centers, rves[0].diameters,
                         fibers[0], samples.empty() ? nullptr : &samples[0], job.pictures.format);
  }
  if (job.stats.empty()) return;
  if (rves.size() == 1) {
    write_json(job.stats, fiber_statistics_json(fibers[0], samples.empty() ? nullptr : &samples[0], rves[0].gap, job.spec.seed));
  } else {
    write_json(job.stats, fiber_ensemble_json(fibers, samples, rves[0].gap, job.spec.seed));
  }
}

RveMeshSpec mesh_spec(const RveJob& job) {
  RveMeshSpec spec = job.mesh;
  spec.max_memory = job.spec.max_memory;
  return spec;
}

// Runs `work`, naming the options that help when it is refused for memory.
template <class Work>
void memory_remedy(const Work& work) {
  try {
    work();
  } catch (const InvalidInput& e) {
    if (e.remedy() != InvalidInput::Remedy::memory) throw;
    throw InvalidInput(std::string(e.what()) + " (--element-size, --max-memory SIZE)");
  }
}

void write_mesh(const RveJob& job, const Rve& rve, std::size_t k) {
  const auto t0 = std::chrono::steady_clock::now();
  RveMesh mesh;
  memory_remedy([&] { mesh = mesh_rve(rve, mesh_spec(job)); });
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::size_t in_fibers = 0;
  for (const std::uint32_t m : mesh.material) in_fibers += m > 0;
  say("rve mesh: %zu nodes, %zu triangles (%zu in fibers), angles %.1f-%.1f deg, radius ratio max %.2f "
              "mean %.3f, %zu + %zu periodic node pairs, sides %.3g D clear of fiber tangents, %.3f s",
              mesh.nodes.size(), mesh.triangles.size(), in_fibers, mesh.angles.min, mesh.angles.max,
              mesh.radius_ratio.max, mesh.radius_ratio.mean, mesh.left.size() + 2, mesh.bottom.size() + 2,
              mesh.side_clearance / rve.diameter, seconds);
  for (const std::string* file : {&job.msh, &job.inp}) {
    if (!file->empty()) say(" -> %s", output_of(job, *file, k).c_str());
  }
  say("\n");
  if (!job.msh.empty()) write_rve_msh(output_of(job, job.msh, k), mesh);
  if (!job.inp.empty()) write_rve_inp(output_of(job, job.inp, k), mesh);
}

int run_rve(const RveJob& given) {
  if (!given.diameter_given) {
    throw InvalidInput("rve: give the fibers' diameter (--diameter D) or a file of diameters (--diameters FILE)");
  }
  RveJob job = given;
  std::vector<NamedFile> outputs;
  for (std::size_t k = 0; k < job.realizations; ++k) {
    outputs.push_back({"--output", output_of(job, job.output, k)});
    outputs.push_back({"--msh", output_of(job, job.msh, k)});
    outputs.push_back({"--inp", output_of(job, job.inp, k)});
  }
  outputs.push_back({"--stats", job.stats});
  check_files_apart({}, outputs);
  for (const std::string* file : {&job.output, &job.stats, &job.msh, &job.inp}) check_output_folder(*file);
  if (!job.pictures.dir.empty()) check_picture_folder(job.pictures.dir);
  if (!job.diameters.empty()) job.spec.diameter_list = read_diameters_csv(job.diameters);
  const bool unequal = job.spec.diameter_cv != 0 || !job.spec.diameter_list.empty();
  const std::size_t count = rve_fiber_count(job.spec);  // fail before any work
  const bool meshing = !job.msh.empty() || !job.inp.empty();
  if (job.mesh_options && !meshing) {
    throw InvalidInput("rve: --fiber-segments and --element-size shape the mesh; add --msh FILE or --inp FILE");
  }
  if (meshing) memory_remedy([&] { check_rve_mesh(job.spec, mesh_spec(job)); });
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<Rve> rves = make_all(job, count);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  bool reached = true;
  for (std::size_t k = 0; k < rves.size(); ++k) {
    const Rve& rve = rves[k];
    write_fibers_csv(output_of(job, job.output, k), rve.centers, rve.diameters);
    reached = reached && rve.tuning.reached;
    if (unequal) {  // each arrangement draws its own diameters, and so its own count for a fraction
      const auto [least, most] = std::minmax_element(rve.diameters.begin(), rve.diameters.end());
      double spread = 0;
      for (const double d : rve.diameters) spread += (d - rve.diameter) * (d - rve.diameter);
      spread = std::sqrt(spread / static_cast<double>(rve.diameters.size())) / rve.diameter;
      say("rve: %zu fibers, vf %.4f, diameters %g-%g (mean %g, cv %.3f), gap %g, cell %g x %g, "
                  "from a sample of %zu equal ones, seed %llu",
                  rve.centers.size(), rve.fiber_fraction, *least, *most, rve.diameter, spread, rve.gap,
                  rve.cell.width(), rve.cell.height(), rve.sample_centers.size(),
                  static_cast<unsigned long long>(job.spec.seed + k));
    } else {
      say("rve: %zu fibers (%s%zu), vf %.4f, diameter %g, gap %g, cell %g x %g, from a sample of %zu, "
                  "phase %s, seed %llu",
                  rve.centers.size(), rve.tuning.reached ? "as asked: " : "NOT reached, asked ", count,
                  rve.fiber_fraction, rve.diameter, rve.gap, rve.cell.width(), rve.cell.height(),
                  rve.sample_centers.size(), to_string(rve.tuning.last_phase).c_str(),
                  static_cast<unsigned long long>(job.spec.seed + k));
    }
    if (rves.size() == 1) say(", %.3f s", seconds);
    say(" -> %s\n", output_of(job, job.output, k).c_str());
    if (meshing) write_mesh(job, rve, k);
  }
  if (rves.size() > 1) say("rve: %zu realizations, %.3f s\n", rves.size(), seconds);
  if (!job.stats.empty() || !job.pictures.dir.empty()) write_statistics(job, rves);
  if (!reached) {
    say(
                 "disktune: the fiber count was not reached: no phase makes progress beyond the counts above; "
                 "those arrangements were written; ask for fewer fibers or a smaller gap\n");
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
  auto* diameter = cmd->add_option("--diameter,-d", job->spec.diameter, "Fiber diameter D (the mean, with --diameter-cv)");
  auto* cv = cmd->add_option("--diameter-cv", job->spec.diameter_cv,
                             "Unequal fibers: diameters from a normal law of mean D and standard deviation CV x D, "
                             "redrawn beyond two standard deviations (CV up to 0.2); no two fibers closer than "
                             "(d1 + d2) / 2 + G, no room for one more of the smallest");
  auto* listed = cmd->add_option("--diameters", job->diameters,
                                 "Unequal fibers: diameters drawn at random from this CSV file, header 'd' (one "
                                 "measured diameter a line) or 'x,y,d' (an arrangement's)");
  listed->excludes(diameter)->excludes(cv);
  cmd->add_option("--gap,-g", job->spec.gap, "Least matrix gap G between two fibers (centers at least D + G apart)")
      ->capture_default_str();
  auto* vf = cmd->add_option("--vf", job->spec.fiber_fraction,
                             "Fiber volume fraction vf = N pi (D/2)^2 / (W H) wanted (the count nearest it; unequal fibers: "
                             "the count of diameters drawn whose areas come nearest)");
  auto* fibers = cmd->add_option("--fibers,-n", job->spec.fibers, "Exact number of fibers wanted")
                     ->check(whole_number(1, UINT64_MAX, "--fibers"));
  vf->excludes(fibers);
  cmd->add_option("--width", job->spec.width, "Width W of the periodic cell")->capture_default_str();
  cmd->add_option("--height", job->spec.height, "Height H of the periodic cell")->capture_default_str();
  writes_file(cmd->add_option("--output,-o", job->output, "CSV file to write (header x,y,d)"))->required();
  writes_file(cmd->add_option("--stats", job->stats,
                  "Also write the arrangement's statistics as JSON: nearest-neighbour distances (1st to "
                  "6th) and orientation, Ripley's K and L, g(r), psi6, Voronoi cell areas, the local fiber "
                  "fraction in windows 2 to 16 D wide; beside them the "
                  "same for the maximal sample it was tuned from (random sequential adsorption), complete "
                  "spatial randomness and the hexagonal lattice"));
  add_picture_options(
      cmd, job->pictures,
      "cell.png (the fibers), pair_correlation.png and ripley_l.png (L(r) - r; blue "
      "the arrangement, orange the maximal sample it was tuned from), nearest.png and "
      "psi6_local.png (histograms) of the first realization");
  writes_file(cmd->add_option("--msh", job->msh,
                  "Also write a periodic finite-element mesh of fibers and matrix as Gmsh MSH 4.1: "
                  "physical groups matrix, fibers, 'fiber K', left, right, bottom, top, corners; the "
                  "right and top sides periodic copies of the left and bottom, node for node"));
  writes_file(cmd->add_option("--inp", job->inp,
                  "Also write the mesh as Abaqus input: CPE3 triangles, element sets MATRIX, FIBERS, "
                  "FIBER-K, node sets LEFT/RIGHT and BOTTOM/TOP in periodic pairs, CORNER-1..4"));
  auto* segments = cmd->add_option("--fiber-segments", job->mesh.fiber_segments, "Segments of a fiber's boundary in the mesh")
      ->check(whole_number(6, 10000, "--fiber-segments"))
      ->capture_default_str();
  auto* element_size = cmd->add_option("--element-size", job->mesh.element_size,
                  "Largest triangle edge of the mesh (default: a fiber segment's length, pi D / segments)");
  cmd->add_option("--realizations", job->realizations,
                  "Make K independent arrangements (seeds S, S+1, ...) on all cores, written as "
                  "NAME-1.csv ... NAME-K.csv (and meshes alike); --stats then holds each one's statistics and their "
                  "spread over the ensemble")
      ->check(whole_number(1, 10000, "--realizations"))
      ->capture_default_str();
  add_threads_option(cmd, job->threads, "Threads for the realizations");
  add_seed_option(cmd, job->spec.seed);
  add_memory_option(cmd, job->spec.max_memory);
  cmd->callback([job, &action, segments, element_size, diameter, listed] {
    job->diameter_given = diameter->count() > 0 || listed->count() > 0;
    job->mesh_options = segments->count() > 0 || element_size->count() > 0;
    action = [job] { return run_rve(*job); };
  });
}

}  // namespace disktune::cli
