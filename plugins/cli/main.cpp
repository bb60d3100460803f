// SPDX-License-Identifier: GPL-3.0-or-later
// The `disktune` command: a thin front door over the library. Each subcommand maps its
// flags onto library calls; errors become one clear line and a distinct exit code.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <csignal>
#include <iostream>
#include <new>
#include <string>
#include <vector>

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

// Levenshtein distance, for suggestions.
std::size_t edits(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
      diagonal = up;
    }
  }
  return row[b.size()];
}

// The words the command line did not expect, in the order given, each with the closest
// name it may have meant (within two edits): an option of the subcommand given, or at
// the top a subcommand. "sample: unknown option --radus (did you mean --radius?)".
std::string unexpected(const CLI::App& app) {
  const std::vector<CLI::App*> given = app.get_subcommands();
  const CLI::App& where = given.empty() ? app : *given.front();
  std::vector<std::string> names;
  for (const CLI::Option* option : where.get_options()) {
    for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
    for (const std::string& name : option->get_snames()) names.push_back("-" + name);
  }
  if (given.empty())
    for (const CLI::App* sub : app.get_subcommands({})) names.push_back(sub->get_name());
  const auto closest = [&](const std::string& word) {
    std::string best;
    std::size_t least = 3;
    for (const std::string& name : names) {
      const std::size_t d = edits(word, name);
      if (d < least) least = d, best = name;
    }
    return best;
  };
  std::vector<std::string> words = app.remaining(true);
  if (given.empty() && !words.empty() && !words[0].empty() && words[0][0] != '-') {
    const std::string guess = closest(words[0]);  // a misspelt command: what follows is its
    return "unknown command " + words[0] + (guess.empty() ? "" : " (did you mean " + guess + "?)");
  }
  const bool options =
      std::any_of(words.begin(), words.end(), [](const std::string& w) { return w[0] == '-'; });
  std::string out = given.empty() ? "" : where.get_name() + ": ";
  for (const std::string& word : words) {
    if (word.empty() || (options && word[0] != '-')) continue;  // a value after an unknown option
    const std::string bare = word.substr(0, word.find('='));
    const std::string guess = closest(bare);
    if (out.size() > (given.empty() ? 0 : where.get_name().size() + 2)) out += ", ";
    out += (bare[0] == '-' ? "unknown option " : "unexpected argument ") + bare;
    if (!guess.empty()) out += " (did you mean " + guess + "?)";
    if (!options) break;  // the first stray word says enough
  }
  return out;
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
  bool quiet = false;
  app.add_flag("--quiet,-q", quiet, "No summary lines, notes or progress on standard error (warnings and errors still)");
  app.fallthrough();  // --quiet after the command too
  Action action = run_demo;
  add_sample_command(app, action);
  add_tune_command(app, action);
  add_mesh_command(app, action);
  add_report_command(app, action);
  add_sweep_command(app, action);
  add_remesh_command(app, action);
  add_rve_command(app, action);
  add_docs_commands(app, action);

  try {
    remember_invocation(argc, argv);
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ExtrasError&) {
    const std::vector<CLI::App*> given = app.get_subcommands();
    std::cerr << "disktune: " << unexpected(app) << "\nRun 'disktune "
              << (given.empty() ? std::string() : given.front()->get_name() + " ")
              << "--help' for the options.\n";
    return kExitUsage;
  } catch (const CLI::ParseError& e) {
    std::cerr << "disktune: " << e.what() << "\nRun 'disktune --help' for the options.\n";
    return kExitUsage;
  }

  set_quiet(quiet);
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
  // The demo is a pipeline of commands, each its own transaction (demo.cpp).
  const bool demo = app.get_subcommands().empty();
  try {
    return demo ? action() : with_outputs_as_one(action);
  } catch (const disktune::InvalidInput& e) {
    std::cerr << "disktune: error: " << naming_stdin(e.what()) << "\n";
    return kExitUsage;
  } catch (const disktune::IoError& e) {
    std::cerr << "disktune: error: " << naming_stdin(e.what()) << "\n";
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
