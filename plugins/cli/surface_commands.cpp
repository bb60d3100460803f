// SPDX-License-Identifier: GPL-3.0-or-later
// `sample`, `tune`, `mesh` and `report` on a curved surface (--domain FILE.off|.obj|.ply|
// .stl that is not flat): samples as CSV x,y,z,r, the restricted Delaunay mesh as OFF,
// OBJ or PLY, and a JSON report. Each command's file dispatches here when
// names_surface(--domain) holds (command_domain.h decides).
#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>

#include "command_domain.h"
#include "commands.h"
#include "disktune/density.h"
#include "disktune/errors.h"
#include "disktune/io.h"
#include "disktune/quality.h"
#include "disktune/quality_json.h"
#include "disktune/remesh.h"
#include "disktune/report_pictures.h"
#include "disktune/restricted_delaunay.h"
#include "disktune/surface_io.h"
#include "disktune/surface_mesh.h"
#include "disktune/surface_tuning.h"
#include "disktune/surface_voids.h"

namespace disktune::cli {
namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void refuse_svg(const std::string& svg, const std::string& command) {
  if (svg.empty()) return;
  throw InvalidInput(command +
                     " --svg: the SVG picture draws the plane (the periodic box or a planar "
                     "domain) and cannot show disks on a curved surface; leave out --svg and view "
                     "the surface mesh from 'disktune mesh' (.off, .obj, .ply, .vtk, .vtu, .msh, .stl) in a mesh viewer");
}

std::size_t fixed_count(const SurfacePacking& packing) {
  std::size_t n = 0;
  for (const DiskId id : packing.ids()) n += (packing.flags(id) & kFixed) != 0;
  return n;
}

std::string boundary_text(const SurfacePacking& packing) {
  const SurfaceDomain& d = packing.domain();
  if (d.fixed_curves().empty()) return "";
  const char* where = d.features().curves.empty() ? "on the boundary"
                      : d.is_closed()             ? "on feature curves"
                                                  : "on the boundary and feature curves";
  return " (" + std::to_string(fixed_count(packing)) + " " + where + ")";
}

// A restricted Delaunay mesh needs 4 samples (a tetrahedron); fewer still make a valid
// packing, which sample and tune write with a warning and report measures without a mesh.
constexpr std::size_t kFewestToMesh = 4;

void warn_too_few_to_mesh(std::size_t count) {
  if (count >= kFewestToMesh) return;
  std::fprintf(stderr,
               "disktune: warning: %zu disks are too few to mesh (a restricted Delaunay mesh needs at least %zu); "
               "they were still written: use a smaller radius for a mesh\n",
               count, kFewestToMesh);
}

// The restricted Delaunay mesh of the samples, in id order, with their radii.
struct SampleMesh {
  SurfaceMesh mesh;
  std::vector<double> radius;
  SurfaceMeshCheck check;
};

SampleMesh sample_mesh(const SurfacePacking& packing) {
  SampleMesh out;
  for (const DiskId id : packing.ids()) out.radius.push_back(packing.radius(id));
  out.mesh = restricted_delaunay(packing);
  out.check = check_surface_mesh(out.mesh);
  return out;
}

// "manifold yes, genus 2 (input genus 2)"
std::string topology_text(const SurfaceMeshCheck& check, const SurfaceDomain& surface) {
  std::ostringstream s;
  s << "manifold " << (check.manifold ? "yes" : "no");
  if (check.manifold) s << ", genus " << check.genus;
  s << " (input genus " << surface.genus() << ")";
  if (check.manifold && check.boundary_loops != surface.boundary_loops().size())
    s << ", " << check.boundary_loops << " boundary loops (input " << surface.boundary_loops().size() << ")";
  return s.str();
}

// On stderr when the mesh is no manifold of the input's genus; `done` says what was
// still done with it ("written", "measured"); `denser` how to ask for denser samples
// (null: a smaller radius, or where the mesh is no manifold, the thickness sizing too).
void warn_topology(const SurfaceMeshCheck& check, const SurfaceDomain& surface, const char* done,
                   const char* denser = nullptr) {
  const char* smaller = denser ? denser : "use a smaller radius";
  if (!check.manifold) {
    std::fprintf(stderr,
                 "disktune: warning: the restricted Delaunay mesh is not a manifold (%zu edges in "
                 "more than two triangles, %zu bow-tie vertices); it was still %s. The samples are "
                 "too sparse for the surface: %s\n",
                 check.non_manifold_edges, check.non_manifold_vertices, done,
                 denser ? denser
                        : "use a smaller radius, or --sizing auto:R (smaller where the surface faces itself "
                          "closely, as thin walls and ledges do)");
  } else if (check.boundary_loops != surface.boundary_loops().size()) {
    std::fprintf(stderr,
                 "disktune: warning: the restricted Delaunay mesh has %zu boundary loops, the input "
                 "surface %zu: it has holes; it was still %s. The samples are too sparse for the "
                 "surface there: %s\n",
                 check.boundary_loops, surface.boundary_loops().size(), done, smaller);
  } else if (check.genus != surface.genus()) {
    std::fprintf(stderr,
                 "disktune: warning: the restricted Delaunay mesh has genus %d, the input surface "
                 "genus %d; it was still %s. The samples are too sparse to capture the surface's "
                 "topology: %s\n",
                 check.genus, surface.genus(), done, smaller);
  }
}

std::string json_number(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[32];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);  // shortest round trip
  return std::string(buf, res.ptr);
}

}  // namespace

int run_surface_sample(const SampleJob& job) {
  refuse_svg(job.svg, "sample");
  check_output_folder(job.output);
  const CommandDomain domain = open_domain(job.domain);
  require_output(job.output, job.svg, "sample");
  Rng rng(job.seed);
  const auto t0 = std::chrono::steady_clock::now();
  const SurfacePacking packing = domain.sample_surface(rng);
  const double seconds = seconds_since(t0);
  if (!job.output.empty()) write_surface_csv(job.output, packing);
  say("sample: %zu disks%s, %s, %.3f s (%s, %s)%s%s\n", packing.size(),
      boundary_text(packing).c_str(), domain.density_text(packing.size()).c_str(), seconds,
      domain.radius_text().c_str(), domain.describe().c_str(), job.output.empty() ? "" : " -> ",
      job.output.c_str());
  warn_too_few_to_mesh(packing.size());
  return kExitOk;
}

int run_surface_tune(const TuneJob& job) {
  refuse_svg(job.svg, "tune");
  check_output_folder(job.output);
  const CommandDomain domain = open_domain(job.domain);
  const std::size_t target = target_count_for_unit(job.target, domain.unit);  // fail early
  check_memory(domain, job.domain, static_cast<double>(target));
  if (job.input.empty()) require_output(job.output, job.svg, "tune");
  Rng rng(job.seed);
  const auto t0 = std::chrono::steady_clock::now();
  SurfacePacking packing =
      job.input.empty() ? domain.sample_surface(rng) : domain.read_surface(job.input, true);
  require_output(job.output, job.svg, "tune");  // after the input's own checks
  const std::size_t start = packing.size();

  const auto write_output = [&] { write_surface_csv(job.output, packing); };
  const TuneResult res = tune_with_progress(
      target, job.method,
      [&](const TuneOptions& options) { return tune(packing, job.target, rng, options); },
      job.output, write_output);
  const double spacing = relax_spacing(packing.size(), domain.unit);
  relax(packing, spacing, job.relax_sweeps, rng, {}, job.threads, Maximality::at_end);
  const double seconds = seconds_since(t0);

  if (!job.output.empty()) write_output();
  warn_too_few_to_mesh(res.count);
  return report_tune(start, res, domain.density_text(res.count), seconds,
                     relaxed_text(job.relax_sweeps) + " (" + domain.radius_text() + ", " + domain.describe() + ")",
                     job.output);
}

int run_surface_mesh(const std::string& input, const DomainArgs& domain_args, const std::string& output,
                     const std::string& format_name) {
  const MeshFormat format = output_mesh_format(output, format_name, true);  // before any work
  check_output_folder(output);
  const CommandDomain domain = open_domain(domain_args);
  const SurfacePacking packing = domain.read_surface(input, false);
  const auto t0 = std::chrono::steady_clock::now();
  const SampleMesh m = sample_mesh(packing);
  const double seconds = seconds_since(t0);
  write_surface_mesh(output, m.mesh, format);
  const std::string along = domain.surface->features().curves.empty()
                                ? ""
                                : ", " + std::to_string(m.mesh.feature_edges.size()) + " edges along feature curves";
  say(
      "mesh: %zu disks, %zu vertices, %zu triangles (restricted Delaunay)%s, %s, %.3f s -> %s\n",
      packing.size(), m.mesh.vertices.size(), m.mesh.triangles.size(), along.c_str(),
      topology_text(m.check, *domain.surface).c_str(), seconds, output.c_str());
  if (!m.check.problems.empty()) say("mesh: %s\n", m.check.problems.c_str());
  warn_topology(m.check, *domain.surface, "written");
  return kExitOk;
}

// The mesh check as JSON (report and remesh).
std::string mesh_check_json(const SurfaceMeshCheck& c) {
  std::ostringstream j;
  j << "{\"manifold\": " << (c.manifold ? "true" : "false") << ", \"oriented\": " << (c.oriented ? "true" : "false")
    << ", \"genus\": " << c.genus << ", \"components\": " << c.components
    << ", \"boundary_edges\": " << c.boundary_edges << ", \"boundary_loops\": " << c.boundary_loops
    << ", \"non_manifold_edges\": " << c.non_manifold_edges
    << ", \"non_manifold_vertices\": " << c.non_manifold_vertices
    << ", \"isolated_vertices\": " << c.isolated_vertices << ", \"problems\": " << json_string(c.problems) << "}";
  return j.str();
}

// The report's JSON up to the mesh: the surface, the sizing and the packing's figures.
std::string packing_json(const CommandDomain& domain, const SurfacePacking& packing, double eta, double rho,
                         bool maximal, bool conflict_free) {
  const SurfaceDomain& surface = *domain.surface;
  std::ostringstream j;
  j << "{\n  \"surface\": {\"file\": " << json_string(domain.file)
      << ", \"vertices\": " << surface.vertices().size()
      << ", \"triangles\": " << surface.triangles().size() << ", \"genus\": " << surface.genus()
      << ", \"boundary_loops\": " << surface.boundary_loops().size()
      << ", \"feature_curves\": " << surface.features().curves.size()
      << ", \"feature_corners\": " << surface.features().corners.size()
      << ", \"corners\": " << surface.corners().size()
      << ", \"area\": " << json_number(surface.area()) << "},\n"
      << "  \"sizing\": " << json_string(domain.radius_text()) << ",\n"
      << "  \"min_radius\": " << json_number(packing.sizing().min_radius()) << ",\n"
      << "  \"max_radius\": " << json_number(packing.sizing().max_radius()) << ",\n"
      << "  \"count\": " << packing.size() << ",\n"
      << "  \"boundary_count\": " << fixed_count(packing) << ",\n"  // fixed: boundary and features
      << "  \"area_fraction\": " << json_number(eta) << ",\n"
      << "  \"relative_radius\": " << json_number(rho) << ",\n"
      << "  \"maximal\": " << (maximal ? "true" : "false") << ",\n"
      << "  \"conflict_free\": " << (conflict_free ? "true" : "false") << ",\n";
  return j.str();
}

int report_without_mesh(const SurfaceReportJob& job, const CommandDomain& domain, const SurfacePacking& packing,
                        double eta, double rho, bool maximal, bool conflict_free) {
  if (!job.json.empty()) {
    const std::string text =
        packing_json(domain, packing, eta, rho, maximal, conflict_free) + "  \"mesh_check\": null,\n  \"mesh\": null\n}\n";
    write_json(job.json, text);
  }
  say("report: %zu disks%s, eta = %.4f, rho = %.4f, %s, %s; no mesh (a restricted Delaunay mesh needs at "
              "least %zu samples: use a smaller radius)%s%s\n",
              packing.size(), boundary_text(packing).c_str(), eta, rho, maximal ? "maximal" : "NOT maximal",
              conflict_free ? "conflict-free" : "CONFLICTS", kFewestToMesh, job.json.empty() ? "" : " -> ",
              job.json.c_str());
  return kExitOk;
}

int run_surface_report(const SurfaceReportJob& job) {
  if (!job.svg.empty()) {
    throw InvalidInput(
        "report --svg: the SVG picture draws the plane (the periodic box or a planar "
        "domain); on a surface write the mesh with 'disktune mesh' (.off, .obj, .ply, "
        ".vtk, .vtu, .msh, .stl) and use --json for the measures");
  }
  if (!job.pictures.dir.empty()) check_picture_folder(job.pictures.dir);
  if (job.spectrum_window != 0) {
    throw InvalidInput(
        "report --spectrum-window: the spectrum needs the periodic box; a surface "
        "report has none");
  }
  check_output_folder(job.json);
  const CommandDomain domain = open_domain(job.domain);
  const SurfacePacking packing = domain.read_surface(job.input, false);
  const SurfaceDomain& surface = *domain.surface;

  const bool conflict_free = is_conflict_free(packing);
  const bool maximal = is_maximal(packing);
  const double eta = static_cast<double>(packing.size()) / domain.unit;
  const double rho = relative_radius_for(eta);
  if (packing.size() < kFewestToMesh) return report_without_mesh(job, domain, packing, eta, rho, maximal, conflict_free);
  const SampleMesh m = sample_mesh(packing);
  SurfaceMeshQuality q = measure_surface_mesh(m.mesh, m.radius);
  q.hausdorff = hausdorff_distance(m.mesh, surface, 10000, 1, 0);

  if (!job.json.empty()) {
    std::ostringstream j;
    j << packing_json(domain, packing, eta, rho, maximal, conflict_free)
      << "  \"mesh_check\": " << mesh_check_json(m.check) << ",\n"
      << "  \"mesh\": " << quality_json(q) << "\n}\n";
    const std::string text = j.str();
    write_json(job.json, text);
  }
  if (!job.pictures.dir.empty())
    write_report_pictures(job.pictures.dir, q, m.mesh, job.pictures.format);
  say(
      "report: %zu disks%s, eta = %.4f, rho = %.4f, %s, %s; mesh: %zu vertices, %zu triangles, "
      "%s, angles %.2f..%.2f deg (mean |a-60| %.2f), beta <= %.4f, Hausdorff %.4g%s%s\n",
      packing.size(), boundary_text(packing).c_str(), eta, rho, maximal ? "maximal" : "NOT maximal",
      conflict_free ? "conflict-free" : "CONFLICTS", m.mesh.vertices.size(),
      m.mesh.triangles.size(), topology_text(m.check, surface).c_str(), q.angles.min, q.angles.max,
      q.angles.mean_abs_dev_60, q.local_beta.max, q.hausdorff, job.json.empty() ? "" : " -> ",
      job.json.c_str());
  if (!m.check.problems.empty()) say("report: %s\n", m.check.problems.c_str());
  warn_topology(m.check, surface, "measured");
  return kExitOk;
}

int run_surface_remesh(const RemeshJob& job) {
  check_files_apart({{"the surface", job.input}}, {{"--output", job.output}, {"--json", job.json}});
  const MeshFormat format = output_mesh_format(job.output, job.format, true);  // before any work
  check_output_folder(job.output);
  if (!job.json.empty()) check_output_folder(job.json);
  if (!job.pictures.dir.empty()) check_picture_folder(job.pictures.dir);
  DomainArgs args;
  args.kind = job.input;
  args.features = job.features;
  if (!names_surface(args)) {
    throw InvalidInput("remesh: " + job.input +
                       " is flat (every vertex has the same z) or not a mesh file: remesh takes a curved "
                       "surface (.off, .obj, .ply, .stl); for a planar domain run sample, tune and mesh with "
                       "--domain " + job.input);
  }
  const std::shared_ptr<const SurfaceDomain> surface = surface_with_features(args);
  RemeshOptions options;
  options.seed = job.seed;
  options.relax_sweeps = job.relax_sweeps;
  options.feature_angle = 0;  // the surface's own features, as --features set them
  options.max_memory = job.max_memory;
  options.threads = job.threads;
  const auto t0 = std::chrono::steady_clock::now();
  RemeshResult result;
  tune_with_progress(
      job.vertices, Method::automatic,
      [&](const TuneOptions& tune_options) {
        options.tune = tune_options;
        result = remesh(surface, job.vertices, options);
        return result.tuning;
      },
      "", [] {});
  const double seconds = seconds_since(t0);
  if (!result.grading_note.empty()) say("disktune: note: %s\n", result.grading_note.c_str());
  write_surface_mesh(job.output, result.mesh, format);
  SurfaceMeshQuality q;
  if (!result.mesh.triangles.empty()) {
    q = measure_surface_mesh(result.mesh, result.radii);
    q.hausdorff = hausdorff_distance(result.mesh, *surface, 10000, 1, job.threads);
  }
  if (!job.json.empty()) {
    std::ostringstream j;
    j << "{\n  \"surface\": {\"file\": " << json_string(job.input) << ", \"vertices\": " << surface->vertices().size()
      << ", \"triangles\": " << surface->triangles().size() << ", \"genus\": " << surface->genus()
      << ", \"boundary_loops\": " << surface->boundary_loops().size()
      << ", \"feature_curves\": " << surface->features().curves.size() << "},\n"
      << "  \"vertices_asked\": " << job.vertices << ",\n  \"vertices\": " << result.mesh.vertices.size()
      << ",\n  \"reached\": " << (result.tuning.reached ? "true" : "false")
      << ",\n  \"radius\": " << json_number(result.radius) << ",\n  \"seed\": " << job.seed
      << ",\n  \"features\": " << json_string(job.features) << ",\n  \"relax_sweeps\": " << job.relax_sweeps
      << ",\n  \"seconds\": " << json_number(seconds) << ",\n  \"mesh_check\": " << mesh_check_json(result.check)
      << ",\n  \"mesh\": " << (result.mesh.triangles.empty() ? std::string("null") : quality_json(q)) << "\n}\n";
    const std::string text = j.str();
    write_json(job.json, text);
  }
  if (!job.pictures.dir.empty() && !result.mesh.triangles.empty())
    write_report_pictures(job.pictures.dir, q, result.mesh, job.pictures.format);
  say(
      "remesh: %zu vertices (%s), %zu triangles, %zu edges along feature curves, %s, angles %.2f..%.2f deg, "
      "%.1f %% in [50,70], %.2f %% obtuse triangles, Hausdorff %.4g, r = %.6g, %.3f s -> %s%s%s\n",
      result.mesh.vertices.size(), result.tuning.reached ? "as asked" : "NOT as asked",
      result.mesh.triangles.size(), result.mesh.feature_edges.size(), topology_text(result.check, *surface).c_str(),
      q.angles.min, q.angles.max, 100 * q.angles.fraction_50_70, 100 * q.angles.fraction_obtuse_triangles,
      q.hausdorff, result.radius, seconds, job.output.c_str(), job.json.empty() ? "" : ", ", job.json.c_str());
  if (!result.check.problems.empty()) say("remesh: %s\n", result.check.problems.c_str());
  warn_topology(result.check, *surface, "written", "ask for more vertices");
  if (!result.tuning.reached) {
    say(
                 "disktune: remesh reached %zu vertices, not %zu: tuning found no way to the exact count; the "
                 "mesh of the closest packing was written\n",
                 result.tuning.count, job.vertices);
    return kExitNotReached;
  }
  return kExitOk;
}

}  // namespace disktune::cli
