// SPDX-License-Identifier: GPL-3.0-or-later
// `disktune remesh`: the mesh-improvement stage (remesh.h) on the command line: a surface
// file in, a mesh of the same surface with exactly N vertices out.
#include <memory>

#include "commands.h"

namespace disktune::cli {

void add_remesh_command(CLI::App& app, Action& action) {
  auto job = std::make_shared<RemeshJob>();
  CLI::App* cmd = app.add_subcommand(
      "remesh",
      "Remesh a triangulated surface (.off, .obj, .ply, .stl) with exactly N vertices: a maximal "
      "sample, tuned to N disks, relaxed toward a hexagonal spacing (still conflict-free and "
      "maximal), and its restricted Delaunay mesh, with the sharp edges kept. Prints the mesh's "
      "topology and angle figures; --json writes them in full.");
  cmd->add_option("surface", job->input, "The surface to remesh (a closed or open 2-manifold of triangles)")
      ->required();
  cmd->add_option("--vertices,-n", job->vertices, "The vertex count of the new mesh (at least 4)")
      ->check(whole_number(4, 1'000'000'000, "--vertices"))
      ->required();
  writes_file(cmd->add_option("--output,-o", job->output, "Mesh file to write: .off, .obj, .ply, .vtk, .vtu (VTK XML), .msh (Gmsh 4.1) or .stl (binary)"))->required();
  add_format_option(cmd, job->format);
  cmd->add_option(
         "--features", job->features,
         "Sharp edges to keep: edges whose triangles' normals differ by more than ANGLE "
         "degrees (default 60), less the stray folds (groups with a loose end shorter than "
         "STRAY times the bounding-box diagonal; ANGLE:STRAY, default 0.2, 0 keeps all), "
         "or 'none'")
      ->capture_default_str();
  cmd->add_option("--relax", job->relax_sweeps,
                  "Relaxation sweeps after the count is reached (0: none); more make the triangles "
                  "closer to equilateral, and cost time")
      ->check(whole_number(0, 10000, "--relax"))
      ->capture_default_str();
  add_threads_option(cmd, job->threads, "Threads for relaxation and the meshes");
  writes_file(cmd->add_option("--json", job->json, "Write the report (topology, angles, edges, Hausdorff distance) as JSON"));
  add_picture_options(cmd, job->pictures,
                      "surface.png (the new mesh colored by each triangle's smallest angle), "
                      "angles.png and edges.png");
  add_seed_option(cmd, job->seed);
  add_memory_option(cmd, job->max_memory);
  cmd->callback([job, &action] { action = [job] { return run_surface_remesh(*job); }; });
}

}  // namespace disktune::cli
