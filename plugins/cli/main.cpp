// SPDX-License-Identifier: GPL-3.0-or-later
// The `disktune` command: a thin front door over the library. Each subcommand maps its
// flags onto library calls; errors become one clear line and a distinct exit code.
#include <CLI/CLI.hpp>
#include <csignal>
#include <iostream>
#include <new>
#include <string>

#include "commands.h"
#include "disktune/errors.h"
#include "disktune/io.h"

namespace {

// Interrupted, the command leaves no temporary file behind and replaces no output.
extern "C" void on_interrupt(int sig) {
  disktune::remove_temporary_outputs();
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

}  // namespace

namespace disktune::cli {

int with_outputs_as_one(const Action& command) {
  OutputTransaction outputs;
  int code = 0;
  try {
    code = command();
  } catch (const InternalError&) {
    outputs.commit();
    throw;
  }
  outputs.commit();
  return code;
}

}  // namespace disktune::cli

int main(int argc, char** argv) {
  using namespace disktune::cli;
  CLI::App app{
      "disktune: maximal Poisson-disk packings whose density is tuned by disk injection and "
      "ejection.\nWith no arguments, runs the built-in demo (writes disktune-demo/)."};
  app.require_subcommand(0, 1);
  app.set_version_flag("--version", std::string("disktune ") + DISKTUNE_VERSION);
  Action action = run_demo;
  add_sample_command(app, action);
  add_tune_command(app, action);
  add_mesh_command(app, action);
  add_report_command(app, action);
  add_sweep_command(app, action);
  add_remesh_command(app, action);
  add_rve_command(app, action);

  try {
    remember_invocation(argc, argv);
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "disktune: " << e.what() << "\nRun 'disktune --help' for the options.\n";
    return kExitUsage;
  }

  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
  // The demo is a pipeline of commands, each its own transaction (demo.cpp).
  const bool demo = app.get_subcommands().empty();
  try {
    return demo ? action() : with_outputs_as_one(action);
  } catch (const disktune::InvalidInput& e) {
    std::cerr << "disktune: error: " << e.what() << "\n";
    return kExitUsage;
  } catch (const disktune::IoError& e) {
    std::cerr << "disktune: error: " << e.what() << "\n";
    return kExitIo;
  } catch (const std::bad_alloc&) {
    // Not a bug: the job is larger than this machine's memory. No output was replaced
    // (every file is written whole or not at all).
    std::cerr << "disktune: error: out of memory: the job needs more memory than this machine "
                 "has; use a larger radius, a smaller domain or a lower target\n";
    return kExitUsage;
  } catch (const std::exception& e) {
    std::cerr << "disktune: internal error: " << e.what() << "\n";
    return kExitInternal;
  }
}
