// SPDX-License-Identifier: GPL-3.0-or-later
// The subcommands of the `disktune` command. Each registers its options on the app and,
// when it is the one given, sets `action` to the work to run after parsing.
#pragma once

#include <CLI/CLI.hpp>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "disktune/mesh_io.h"
#include "disktune/report_pictures.h"
#include "disktune/tuning.h"

namespace disktune::cli {

/// Exit codes: 4 is not an error but a result (the target could not be reached; the
/// closest packing was still written).
enum ExitCode : int { kExitOk = 0, kExitInternal = 1, kExitUsage = 2, kExitIo = 3, kExitNotReached = 4 };

using Action = std::function<int()>;

/// Runs a command with its output files as one transaction (OutputTransaction): they
/// are renamed into place when it returns, whatever its exit code, or when it throws
/// InternalError (what it wrote is the closest packing that passed the checks); on any
/// other exception they are removed and every existing file stays as it was.
int with_outputs_as_one(const Action& command);

/// The domain options every command shares: --domain, --width, --height, and the
/// radius: --radius R, or --sizing SPEC for radii that vary over the domain.
struct DomainArgs {
  std::string kind = "periodic";
  double width = 1, height = 1, radius = 0;
  bool has_radius = false;  // --radius was given
  bool has_box_size = false;  // --width or --height was given
  std::string sizing;
  // A surface's sharp features: a dihedral angle in degrees, or "none".
  std::string features = "60";
  bool has_features = false;  // --features was given
  // Commands that sample or tune check the job against memory before any work.
  bool guarded = false;    // this command does (add_memory_option)
  double max_memory = 0;   // --max-memory in bytes; 0: what the machine has (available_memory)
};
void add_domain_options(CLI::App* cmd, DomainArgs& domain);
/// --max-memory SIZE (bytes, or with K, M, G, T: powers of 1024) on a command that
/// samples or tunes, into `bytes`.
void add_memory_option(CLI::App* cmd, double& bytes);
/// The bytes SIZE means ("8G", "500M", "1.5GiB", "1048576"), or a negative number when
/// it is not a positive size.
double memory_size(const std::string& text);

/// A validator for a whole number written in decimal digits only, from low to high
/// (options.cpp); `what` names the option in the message.
CLI::Validator whole_number(std::uint64_t low, std::uint64_t high, const std::string& what);
/// The --seed option of sample, tune and sweep: 0 to 2^64 - 1, nothing else.
CLI::Option* add_seed_option(CLI::App* cmd, std::uint64_t& seed);
/// --threads N (1 to 4096) into `threads`, "WHAT (default: one per core); ..." as help;
/// it also sets the library's default thread count (threads.h).
CLI::Option* add_threads_option(CLI::App* cmd, unsigned& threads, const std::string& what);
/// Where the pictures go (--picture-dir, also --png-dir) and as what (--picture-format).
struct PictureArgs {
  std::string dir;  // empty: no pictures
  PictureFormat format = PictureFormat::png;
};
/// --picture-dir (`pictures`: what it writes, named .png) and --picture-format.
void add_picture_options(CLI::App* cmd, PictureArgs& args, const std::string& pictures);
/// Makes `option` an output file that may be given as "-": standard output (written
/// straight, as any device; the summary lines go to standard error anyway).
CLI::Option* writes_file(CLI::Option* option);
/// Makes `option` an input file that may be given as "-": standard input (kept whole,
/// so that it can be read more than once; one input at most).
CLI::Option* reads_file(CLI::Option* option);
/// `message` with the path standard input was kept at named "standard input".
std::string naming_stdin(std::string message);

/// --quiet: no summary lines, notes or progress on standard error (warnings and errors
/// still). say() prints like fprintf(stderr, ...) unless quiet.
void set_quiet(bool on);
bool quiet();
int say(const char* format, ...) __attribute__((format(printf, 1, 2)));

/// Keeps the command line for the JSON files (main calls it before parsing).
void remember_invocation(int argc, char** argv);
/// Writes a JSON object (text that opens with '{') to `path` atomically, with a first
/// field "disktune": {"version", "arguments"}: the tool and the command line that made
/// it, so that a report says how to make it again.
void write_json(const std::string& path, const std::string& object);
/// `text` as a JSON string, quotes included.
std::string json_string(const std::string& text);

void add_sample_command(CLI::App& app, Action& action);
void add_tune_command(CLI::App& app, Action& action);
void add_mesh_command(CLI::App& app, Action& action);
void add_report_command(CLI::App& app, Action& action);
void add_sweep_command(CLI::App& app, Action& action);
void add_remesh_command(CLI::App& app, Action& action);
void add_rve_command(CLI::App& app, Action& action);
/// `man` and `completion`: the manual page and a bash completion script, from the app itself.
void add_docs_commands(CLI::App& app, Action& action);

/// One sampling job, as `disktune sample` and the demo run it.
struct SampleJob {
  DomainArgs domain;
  std::uint64_t seed = 1;
  std::string output, svg;
  unsigned threads = 0;  // for the final check (set_default_threads); 0: one per core
};
int run_sample(const SampleJob& job);

/// One tuning job, as `disktune tune` and the demo run it.
struct TuneJob {
  DomainArgs domain;
  Target target;
  Method method = Method::automatic;
  std::string input, output, svg;
  std::uint64_t seed = 1;
  int relax_sweeps = 0;  // after tuning (--relax)
  unsigned threads = 0;  // for relaxation on a surface; 0: one per core
};
int run_tune(const TuneJob& job);

/// --relax: the rest length of relaxation's springs for `count` disks, `unit` of which
/// make area fraction 1 (the hexagonal spacing of that density, in radii), and the
/// summary's words for `sweeps` sweeps ("" for none).
double relax_spacing(std::size_t count, double unit);
std::string relaxed_text(int sweeps);

/// What `tune` does alike on the plane and on a surface (tune_command.cpp). Runs
/// `run(options)` with `method` and a progress bar towards `target` disks.
/// Should the result fail the library's final check (InternalError: the library put
/// the packing back to a valid state), `write_output` writes that packing to `output`,
/// if one was asked for, before the error goes on.
TuneResult tune_with_progress(std::size_t target, Method method,
                              const std::function<TuneResult(const TuneOptions&)>& run,
                              const std::string& output, const std::function<void()>& write_output);
/// Prints the result line, "tune: START -> COUNT disks (target ...), DENSITY, phase ...,
/// SECONDS s" then `where` (e.g. " (r = 0.1, the surface ...)") and " -> OUTPUT" when
/// one was written; when the target was not reached, also why, on stderr. `density` is
/// the density text of the count reached. Returns the exit code.
int report_tune(std::size_t start, const TuneResult& res, const std::string& density,
                double seconds, const std::string& where, const std::string& output);

/// The commands on a curved surface (surface_commands.cpp): each command runs these
/// instead when its --domain names a surface (names_surface in command_domain.h).
int run_surface_sample(const SampleJob& job);
int run_surface_tune(const TuneJob& job);
int run_surface_mesh(const std::string& input, const DomainArgs& domain, const std::string& output,
                     const std::string& format);
struct SurfaceReportJob {
  std::string input;
  DomainArgs domain;
  std::string json, svg;
  PictureArgs pictures;
  int spectrum_window = 0;
};
int run_surface_report(const SurfaceReportJob& job);
/// `disktune remesh`: a surface file in, a mesh of it with exactly `vertices` vertices
/// out (remesh.h), its summary line, and optionally a JSON report.
struct RemeshJob {
  std::string input, output, json;
  PictureArgs pictures;
  std::string format;  // --format: empty for the output's extension
  std::size_t vertices = 0;
  std::string features = "60";
  std::uint64_t seed = 1;
  int relax_sweeps = 30;
  double max_memory = 0;
  unsigned threads = 0;  // for relaxation; 0: one per core
};
int run_surface_remesh(const RemeshJob& job);

/// The built-in default job, run by `disktune` with no arguments.
int run_demo();

/// Throws IoError when the folder of an output path does not exist, so that a typo
/// costs no minutes of computing before the write fails.
void check_output_folder(const std::string& path);
/// The mesh format of an output: --format NAME when given, else the path's extension
/// (refused, naming --format, when it says none); called before any work. Triangle's
/// pair of files only from a path ending in .node or .ele, and not for a `surface`.
MeshFormat output_mesh_format(const std::string& path, const std::string& format,
                              bool surface = false);
/// --format on a command that writes a mesh.
void add_format_option(CLI::App* cmd, std::string& format);
/// Before sample or tune does any work: InvalidInput (exit 2) when it would write
/// nothing (no --output and no --svg), saying how to ask for the disks.
void require_output(const std::string& output, const std::string& svg, const char* command);

/// A file a command reads or writes, with the option (or argument) that names it.
struct NamedFile {
  std::string option, path;
};
/// Throws InvalidInput, before any work, when two outputs name one file or an output
/// names a file the command reads (it would replace that input: `report s.csv --json
/// s.csv`). Only the output option `in_place` may name an input other than the domain
/// (tune --output over its --input: an update, written atomically). Empty paths are
/// skipped, and devices (/dev/null, /dev/stdout) may be named more than once.
void check_files_apart(const std::vector<NamedFile>& inputs, const std::vector<NamedFile>& outputs,
                       const std::string& in_place = "");
/// The files the domain options read: --domain unless it is the periodic box, and
/// --sizing when it names a file (a grid).
std::vector<NamedFile> domain_files(const DomainArgs& domain);

}  // namespace disktune::cli
