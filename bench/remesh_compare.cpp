// SPDX-License-Identifier: GPL-3.0-or-later
// disktune-remesh-compare: disktune's remesh against CGAL 5.5's isotropic_remeshing on
// the same surface, at the same vertex count, measured by the same (disktune's) quality
// code in the same run. CGAL's remesher takes an edge length, not a vertex count, so its
// length is calibrated until the count comes within 1 % of disktune's. disktune runs
// twice, on every core (its relaxation's threads) and on one, and says whether the two
// meshes are the same (they should be, vertex for vertex).
//
//   disktune-remesh-compare SURFACE.off --vertices N [--features ANGLE|none] [--seed S]
//                           [--iterations K]
//     --vertices    the vertex count (at least 4)
//     --features    sharp-edge angle in degrees for both tools (default 60); none: no
//                   features, and no protected CGAL row
//     --seed        disktune's seed (default 1)
//     --iterations  CGAL's number_of_iterations (default 10)
//
// Given a planar domain (.poly) instead, the peer is CGAL's Mesh_2 refinement and Lloyd
// optimizer (cvt_reference_mesh, at most --iterations Lloyd iterations, default 100),
// and disktune samples at the radius whose packing of N disks has remesh's area fraction
// (RemeshOptions), tunes to exactly N, relaxes as remesh does on a surface and takes the
// constrained Delaunay mesh.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh.h>
#include <malloc.h>
#include <sys/resource.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "disktune/boundary.h"
#include "disktune/cvt_reference.h"
#include "disktune/density.h"
#include "disktune/errors.h"
#include "disktune/mesh.h"
#include "disktune/planar_domain.h"
#include "disktune/quality.h"
#include "disktune/remesh.h"
#include "disktune/restricted_delaunay.h"
#include "disktune/sampling.h"
#include "disktune/surface_domain.h"
#include "disktune/surface_mesh.h"
#include "disktune/tuning.h"

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalMesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

struct Args {
  std::string path;
  std::size_t vertices = 0;
  std::optional<double> feature_angle = 60;  // nullopt: --features none
  std::uint64_t seed = 1;
  std::optional<unsigned> iterations;  // CGAL's: 10 remeshing, 100 Lloyd iterations unless given
};

const char* const kUsage =
    "usage: disktune-remesh-compare SURFACE.off|DOMAIN.poly --vertices N [--features ANGLE|none] [--seed S] "
    "[--iterations K]\n";

[[noreturn]] void bad_args(const std::string& why) {
  std::fprintf(stderr, "disktune-remesh-compare: %s\n%s", why.c_str(), kUsage);
  std::exit(2);
}

// Whole-string unsigned parse: "12x", "-3" and "" are errors, not 12, huge or 0.
std::uint64_t parse_unsigned(const std::string& flag, const std::string& text) {
  char* end = nullptr;
  errno = 0;
  const unsigned long long v = std::strtoull(text.c_str(), &end, 10);
  if (text.empty() || text[0] == '-' || *end != '\0' || errno == ERANGE) {
    bad_args(flag + " needs a non-negative integer, got '" + text + "'");
  }
  return v;
}

Args parse_args(int argc, char** argv) {
  Args args;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-h" || arg == "--help") {
      std::fputs(kUsage, stdout);
      std::exit(0);
    }
    if (arg.rfind("--", 0) != 0) {
      if (!args.path.empty()) bad_args("more than one surface given ('" + args.path + "', '" + arg + "')");
      args.path = arg;
      continue;
    }
    if (i + 1 >= argc) bad_args(arg + " needs a value");
    const std::string value = argv[++i];
    if (arg == "--vertices") {
      args.vertices = parse_unsigned(arg, value);
      if (args.vertices < 4) bad_args("--vertices must be at least 4");
    } else if (arg == "--features") {
      if (value == "none") {
        args.feature_angle.reset();
        continue;
      }
      char* end = nullptr;
      const double angle = std::strtod(value.c_str(), &end);
      if (value.empty() || *end != '\0' || !(angle > 0 && angle < 180)) {
        bad_args("--features needs an angle in (0, 180) degrees or 'none', got '" + value + "'");
      }
      args.feature_angle = angle;
    } else if (arg == "--seed") {
      args.seed = parse_unsigned(arg, value);
    } else if (arg == "--iterations") {
      const std::uint64_t k = parse_unsigned(arg, value);
      if (k < 1 || k > 1000) bad_args("--iterations must be in [1, 1000]");
      args.iterations = static_cast<unsigned>(k);
    } else {
      bad_args("unknown option " + arg);
    }
  }
  if (args.path.empty()) bad_args("no surface file given");
  if (args.vertices == 0) bad_args("--vertices is required");
  return args;
}

// After collect_garbage a Surface_mesh's vertex indices are 0..n-1, so they carry over.
disktune::SurfaceMesh to_disktune(CgalMesh mesh) {
  mesh.collect_garbage();
  disktune::SurfaceMesh out;
  out.vertices.reserve(mesh.number_of_vertices());
  for (const auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    out.vertices.push_back({p.x(), p.y(), p.z()});
  }
  out.triangles.reserve(mesh.number_of_faces());
  for (const auto f : mesh.faces()) {
    std::array<std::uint32_t, 3> tri{};
    int k = 0;
    for (const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      if (k < 3) tri[k] = static_cast<std::uint32_t>(v.idx());
      ++k;
    }
    if (k != 3) throw disktune::InvalidInput("CGAL's output has a face of " + std::to_string(k) + " vertices");
    out.triangles.push_back(tri);
  }
  return out;
}

struct Remeshed {
  disktune::SurfaceMesh mesh;
  double seconds = 0;
  std::string note;
  long faults = 0;  // page faults while timed
};

// The process's page faults so far (first touches of memory).
long page_faults() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_minflt + usage.ru_majflt;
}

// One isotropic_remeshing of a fresh copy of `input` at edge length `length`; with
// `feature_angle`, sharp edges are detected, split to the length (CGAL requires
// protected edges no longer than 4/3 of it, and its own example splits them first) and
// protected. Timed from feature detection to the end of remeshing.
CgalMesh cgal_remesh_once(const CgalMesh& input, double length, std::optional<double> feature_angle,
                          unsigned iterations, double& seconds, long& faults) {
  CgalMesh mesh = input;
  faults = page_faults();
  const auto t0 = Clock::now();
  if (feature_angle) {
    auto is_sharp = mesh.add_property_map<CgalMesh::Edge_index, bool>("e:is_sharp", false).first;
    PMP::detect_sharp_edges(mesh, *feature_angle, is_sharp);
    std::vector<CgalMesh::Edge_index> sharp;
    for (const auto e : mesh.edges()) {
      if (is_sharp[e]) sharp.push_back(e);
    }
    PMP::split_long_edges(sharp, length, mesh, CGAL::parameters::edge_is_constrained_map(is_sharp));
    PMP::isotropic_remeshing(faces(mesh), length, mesh,
                             CGAL::parameters::number_of_iterations(iterations)
                                 .edge_is_constrained_map(is_sharp)
                                 .protect_constraints(true));
  } else {
    PMP::isotropic_remeshing(faces(mesh), length, mesh, CGAL::parameters::number_of_iterations(iterations));
  }
  seconds = since(t0);
  faults = page_faults() - faults;
  return mesh;
}

// Calibrates the edge length so the vertex count comes within 1 % of `target`: a closed
// triangle mesh of n vertices has about 2n triangles, each sqrt(3)/4 L^2 when
// equilateral; then L is rescaled by sqrt(count / target) (the count goes as 1 / L^2),
// at most 6 tries, keeping the closest.
Remeshed cgal_remesh(const CgalMesh& input, std::size_t target, std::optional<double> feature_angle,
                     unsigned iterations) {
  const double n = static_cast<double>(target);
  double length = std::sqrt(4 * PMP::area(input) / (std::sqrt(3.0) * 2 * n));
  std::optional<CgalMesh> best;
  double best_error = 1e300, best_seconds = 0, best_length = 0;
  long best_faults = 0;
  int tries = 0;
  for (; tries < 6 && best_error > 0.01; ++tries) {
    double seconds = 0;
    long faults = 0;
    CgalMesh mesh = cgal_remesh_once(input, length, feature_angle, iterations, seconds, faults);
    const double count = static_cast<double>(mesh.number_of_vertices());
    const double error = std::abs(count - n) / n;
    if (error < best_error) {
      best_error = error, best_seconds = seconds, best_length = length, best_faults = faults;
      best = std::move(mesh);
    }
    length *= std::sqrt(count / n);
  }
  char note[160];
  std::snprintf(note, sizeof note, "edge length %.6g after %d tr%s (count off by %.2f %%)", best_length, tries,
                tries == 1 ? "y" : "ies", 100 * best_error);
  return {to_disktune(*best), best_seconds, note, best_faults};
}

struct Row {
  std::string tool;
  Remeshed result;
};

void print_row(const Row& row, const disktune::SurfaceDomain& surface, double radius, double diagonal) {
  const disktune::SurfaceMesh& mesh = row.result.mesh;
  // One radius for every vertex, disktune's, so edge-length ratios compare across rows.
  const std::vector<double> vertex_radius(mesh.vertices.size(), radius);
  const disktune::SurfaceMeshQuality q = disktune::measure_surface_mesh(mesh, vertex_radius);
  const double hausdorff = disktune::hausdorff_distance(mesh, surface, 100000, 1) / diagonal;
  const disktune::SurfaceMeshCheck check = disktune::check_surface_mesh(mesh);
  std::string topology = check.manifold ? "yes / " + std::to_string(check.genus) : "no";
  if (check.isolated_vertices) topology += ", " + std::to_string(check.isolated_vertices) + " isolated";
  if (check.boundary_edges) topology += ", " + std::to_string(check.boundary_edges) + " boundary edges";
  if (check.components != 1) topology += ", " + std::to_string(check.components) + " components";
  std::printf("| %s | %zu | %.2f | %.2f | %.4f | %.4f | %.2e | %s | %.3f |\n", row.tool.c_str(),
              mesh.vertices.size(), q.angles.min, q.angles.max, q.angles.fraction_50_70,
              q.angles.fraction_obtuse_triangles, hausdorff, topology.c_str(), row.result.seconds);
  if (!check.problems.empty()) std::fprintf(stderr, "%s: %s\n", row.tool.c_str(), check.problems.c_str());
}

void print_planar_row(const std::string& tool, const disktune::PlanarMesh& mesh, double radius, double seconds) {
  const disktune::PlanarMeshQuality q = disktune::measure_planar_mesh(mesh, radius);
  std::printf("| %s | %zu | %.2f | %.2f | %.4f | %.4f | %.3f | %.3f |\n", tool.c_str(), mesh.vertices.size(),
              q.angles.min, q.angles.max, q.angles.fraction_50_70, q.angles.fraction_obtuse_triangles,
              q.local_beta.max, seconds);
}

// The planar comparison (see the top of the file).
int compare_planar(const Args& args) {
  const disktune::PlanarDomain domain = disktune::read_poly(args.path);
  const auto shared = std::make_shared<const disktune::PlanarDomain>(domain);
  const disktune::RemeshOptions defaults;  // the surface's remesh: its density and relaxation
  const double eta = defaults.area_fraction, n = static_cast<double>(args.vertices);
  const double radius = std::sqrt(4 * eta * domain.area() / (n * 3.14159265358979323846));
  if (!domain.corners_fit(radius)) {
    std::fprintf(stderr, "disktune-remesh-compare: r = %g (eta %.2f at %zu disks) is too large for the corners of %s; "
                 "ask for more vertices\n", radius, eta, args.vertices, args.path.c_str());
    return 1;
  }
  const auto t0 = Clock::now();
  disktune::Rng rng(args.seed);
  disktune::Packing packing = disktune::sample_mps(shared, radius, rng);
  const std::size_t sampled = packing.size();
  const disktune::TuneResult tuned = disktune::tune(packing, *shared, disktune::Target::count(args.vertices), rng);
  const double spacing = 1 / disktune::relative_radius_for(n / disktune::density_unit(packing, domain.area()));
  disktune::relax(packing, spacing, defaults.relax_sweeps, rng);
  const disktune::PlanarMesh ours =
      disktune::constrained_delaunay(packing, disktune::boundary_loops(packing, *shared));
  const double our_seconds = since(t0);
  const unsigned lloyd = args.iterations.value_or(100);
  const auto t1 = Clock::now();
  const disktune::CvtReference cgal = disktune::cvt_reference_mesh(domain, args.vertices, static_cast<int>(lloyd));
  const double cgal_seconds = since(t1);

  std::printf("%s: %zu loops, area %.6g; target %zu vertices; r = %.6g (MPS %zu disks, %s); seed %llu; "
              "Lloyd iterations at most %u\n\n",
              args.path.c_str(), domain.loops().size(), domain.area(), args.vertices, radius, sampled,
              tuned.reached ? "count reached" : "count NOT reached", static_cast<unsigned long long>(args.seed),
              lloyd);
  std::printf("| tool | vertices | min angle | max angle | angles in [50,70] | obtuse triangles | local beta max "
              "| time (s) |\n");
  std::printf("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
  print_planar_row("disktune sample + tune + relax + constrained Delaunay", ours, radius, our_seconds);
  print_planar_row("CGAL Mesh_2 + Lloyd", cgal.mesh, radius, cgal_seconds);
  std::printf("\nNotes:\n- Times are wall clock, reading excluded; CGAL's includes its size calibration "
              "(refinement %.3f s for the kept one, Lloyd %.3f s).\n- Angle fractions are of all triangle "
              "angles; obtuse is the fraction of triangles; local beta over vertices off the boundary, lengths "
              "in units of disktune's r.\n",
              cgal.refine_seconds, cgal.lloyd_seconds);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const Args args = parse_args(argc, argv);
  try {
    if (args.path.size() > 5 && args.path.compare(args.path.size() - 5, 5, ".poly") == 0) return compare_planar(args);
    const disktune::SurfaceDomain surface = disktune::read_surface(args.path);
    CgalMesh cgal_input;
    if (!PMP::IO::read_polygon_mesh(args.path, cgal_input) || !CGAL::is_triangle_mesh(cgal_input)) {
      std::fprintf(stderr, "disktune-remesh-compare: CGAL cannot read %s as a triangle mesh\n", args.path.c_str());
      return 1;
    }
    const double diagonal = disktune::norm(surface.bbox_max() - surface.bbox_min());

    std::vector<Row> rows;
    // disktune: timed from feature detection (inside remesh) to the mesh, as the CGAL
    // rows are.
    // On every core (relaxation's threads), then on one: the same mesh, and the time
    // beside CGAL's, which runs on one.
    disktune::RemeshOptions options;
    options.seed = args.seed;
    options.feature_angle = args.feature_angle.value_or(0);
    const auto shared = std::make_shared<const disktune::SurfaceDomain>(surface);
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    // Each tool is timed on memory the process has touched before: freed memory stays
    // in the process, and disktune runs once untimed first, as CGAL's calibration
    // passes run before its timed pass. A fresh page costs some machines 11 us to
    // fault in (this project's, 2026-12-06): the first remesh of the elephant at 10^4
    // vertices touched 5,900 of them, CGAL's passes after it none.
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
    mallopt(M_MMAP_THRESHOLD, 32 << 20);  // glibc's largest
    disktune::remesh(shared, args.vertices, options);
    long faults = page_faults();
    auto t0 = Clock::now();
    disktune::RemeshResult result = disktune::remesh(shared, args.vertices, options);
    const double disktune_seconds = since(t0);
    const long disktune_faults = page_faults() - faults;
    const std::string tuned = result.tuning.reached ? "count reached"
                                                    : "count NOT reached: " + std::to_string(result.tuning.count);
    options.threads = 1;
    faults = page_faults();
    t0 = Clock::now();
    disktune::RemeshResult alone = disktune::remesh(shared, args.vertices, options);
    const double alone_seconds = since(t0);
    const long alone_faults = page_faults() - faults;
    const bool same = alone.mesh.vertices == result.mesh.vertices &&
                      alone.mesh.triangles == result.mesh.triangles;
    rows.push_back(
        {"disktune remesh, " + std::to_string(cores) + (cores == 1 ? " thread" : " threads"),
         {std::move(result.mesh), disktune_seconds, tuned, disktune_faults}});
    rows.push_back(
        {"disktune remesh, 1 thread",
         {std::move(alone.mesh), alone_seconds,
          same ? "the same mesh, vertex for vertex" : "NOT the same mesh as on every core",
          alone_faults}});

    rows.push_back({"CGAL isotropic_remeshing", cgal_remesh(cgal_input, args.vertices, std::nullopt, args.iterations.value_or(10))});
    if (args.feature_angle) {
      rows.push_back({"CGAL isotropic_remeshing, sharp edges protected",
                      cgal_remesh(cgal_input, args.vertices, args.feature_angle, args.iterations.value_or(10))});
    }

    char features[64] = "none";
    if (args.feature_angle) {
      std::snprintf(features, sizeof features, "%g deg (%zu feature edges)", *args.feature_angle,
                    surface.features().edges.size());
    }
    std::printf("%s: %zu vertices, %zu triangles, genus %d, %s; target %zu vertices; features %s; seed %llu; "
                "CGAL iterations %u\n\n",
                args.path.c_str(), surface.vertices().size(), surface.triangles().size(), surface.genus(),
                surface.is_closed() ? "closed" : "open", args.vertices, features,
                static_cast<unsigned long long>(args.seed), args.iterations.value_or(10));
    std::printf("| tool | vertices | min angle | max angle | angles in [50,70] | obtuse triangles "
                "| Hausdorff / bbox diagonal | manifold / genus | time (s) |\n");
    std::printf("| --- | ---: | ---: | ---: | ---: | ---: | ---: | --- | ---: |\n");
    for (const Row& row : rows) print_row(row, surface, result.radius, diagonal);
    std::printf("\nNotes:\n");
    for (const Row& row : rows)
      std::printf("- %s: %s; %ld page faults while timed\n", row.tool.c_str(),
                  row.result.note.c_str(), row.result.faults);
    std::printf(
        "- Times are wall clock, from feature detection to the finished mesh, reading excluded. "
        "A CGAL time is one remeshing pass at the calibrated edge length, excluding the "
        "calibration passes before it; disktune runs once untimed before its timed runs, and "
        "the process keeps the memory it frees.\n");
    std::printf("- Angle fractions are of all triangle angles; obtuse is the fraction of triangles. "
                "Hausdorff: symmetric, 100000 samples per side, seed 1.\n");
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "disktune-remesh-compare: %s\n", e.what());
    return 1;
  }
}
