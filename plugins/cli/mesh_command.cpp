// SPDX-License-Identifier: GPL-3.0-or-later
// `disktune mesh`: the Delaunay mesh of a packing (periodic, or constrained by a planar
// domain's boundary), as OFF, OBJ, PLY, VTK, VTU, MSH, STL or Triangle's .node/.ele.
#include <chrono>
#include <cstdio>
#include <memory>

#include "command_domain.h"
#include "commands.h"
#include "disktune/boundary.h"
#include "disktune/errors.h"
#include "disktune/io.h"
#include "disktune/mesh.h"
#include "disktune/mesh_io.h"

namespace disktune::cli {
namespace {

struct MeshArgs {
  std::string input;
  DomainArgs domain;
  std::string output, format;
  unsigned threads = 0;  // set_default_threads does the work (options.cpp)
};

int run_mesh(const MeshArgs& given) {
  MeshArgs args = given;
  args.domain = with_radius_of(given.domain, given.input);
  std::vector<NamedFile> inputs = domain_files(args.domain);
  inputs.push_back({"the points file", args.input});
  check_files_apart(inputs, {{"--output", args.output}});
  if (names_surface(args.domain)) return run_surface_mesh(args.input, args.domain, args.output, args.format);
  const MeshFormat format = output_mesh_format(args.output, args.format);  // before any work
  check_output_folder(args.output);
  const CommandDomain domain = open_domain(args.domain);
  Packing packing = domain.read(args.input, false);
  const auto t0 = std::chrono::steady_clock::now();
  if (domain.planar) {
    const PlanarMesh mesh = constrained_delaunay(packing, boundary_loops(packing, *domain.planar));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    write_mesh(args.output, mesh, format);
    say("mesh: %zu disks, %zu triangles (constrained Delaunay, holes removed), %.3f s -> %s\n",
                mesh.vertices.size(), mesh.triangles.size(), seconds, args.output.c_str());
    return kExitOk;
  }
  const TriangleMesh mesh = periodic_delaunay(packing);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  write_mesh(args.output, mesh, format);
  say(
      "mesh: %zu disks, %zu triangles, %zu vertices (%zu copies across the seam), "
      "%.3f s -> %s\n",
      mesh.disk_count, mesh.triangles.size(), mesh.vertices.size(),
      mesh.vertices.size() - mesh.disk_count, seconds, args.output.c_str());
  return kExitOk;
}

}  // namespace

void add_mesh_command(CLI::App& app, Action& action) {
  auto args = std::make_shared<MeshArgs>();
  CLI::App* cmd = app.add_subcommand(
      "mesh",
      "Write the Delaunay mesh of a packing (CSV x,y,r) as OFF, OBJ, PLY, VTK, VTU, MSH or STL. In the periodic "
      "box: each torus triangle once, laid out with its centroid in the box; vertices past "
      "the first N are periodic copies of disks, across the seam. In a planar domain: the "
      "constrained Delaunay triangulation, boundary segments as edges, holes removed. On a "
      "surface: the restricted Delaunay triangulation, checked for manifoldness and genus.");
  reads_file(cmd->add_option("points", args->input,
                              "CSV file of the packing (header x,y,r; x,y,z,r on a surface); - for standard input"))
      ->required();
  add_domain_options(cmd, args->domain);
  writes_file(
      cmd->add_option(
          "--output,-o", args->output,
          "Mesh file to write: .off, .obj, .ply, .vtk (legacy VTK), .msh (Gmsh 4.1), all ASCII, "
          ".vtu (VTK XML) or .stl, binary, on every domain; or NAME.node for Triangle's .node and "
          ".ele pair (planar and periodic meshes)"))
      ->required();
  add_format_option(cmd, args->format);
  add_threads_option(cmd, args->threads, "Threads for the restricted Delaunay mesh of a surface");
  cmd->callback([args, &action] { action = [args] { return run_mesh(*args); }; });
}

}  // namespace disktune::cli
