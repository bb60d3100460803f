// SPDX-License-Identifier: GPL-3.0-or-later
// The subcommands of the `disktune` command.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>

namespace disktune::cli {

enum ExitCode : int { kExitOk = 0, kExitInternal = 1, kExitUsage = 2, kExitIo = 3 };

struct SampleArgs {
  std::string domain = "periodic";
  double width = 1, height = 1;
  double radius = 0;
  std::uint64_t seed = 1;
  std::string output, svg;
};
void add_sample_command(CLI::App& app, SampleArgs& args);
int run_sample(const SampleArgs& args);

/// The built-in default job, run by `disktune` with no arguments.
int run_demo();

}  // namespace disktune::cli
