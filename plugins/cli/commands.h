// SPDX-License-Identifier: GPL-3.0-or-later
// The subcommands of the `disktune` command. Each registers its options on the app and,
// when it is the one given, sets `action` to the work to run after parsing.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <string>

namespace disktune::cli {

enum ExitCode : int { kExitOk = 0, kExitInternal = 1, kExitUsage = 2, kExitIo = 3 };

using Action = std::function<int()>;

void add_sample_command(CLI::App& app, Action& action);

/// The built-in default job, run by `disktune` with no arguments.
int run_demo();

/// Throws IoError when the folder of an output path does not exist, so that a typo
/// costs no minutes of computing before the write fails.
void check_output_folder(const std::string& path);

}  // namespace disktune::cli
