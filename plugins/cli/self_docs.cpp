// SPDX-License-Identifier: GPL-3.0-or-later
// `disktune man` and `disktune completion`: the manual page (roff) and a bash completion
// script, both made from the options the command itself declares, so they cannot drift
// from it. The install rules write them under share/man/man1 and
// share/bash-completion/completions.
#include <cstdio>
#include <memory>
#include <sstream>
#include <string>

#include "commands.h"
#include "disktune/io.h"

namespace disktune::cli {
namespace {

// roff text: a leading '.' or '\'' would start a request; '\' and '-' are escaped.
std::string roff(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '\\') out += "\\e";
    else if (c == '-') out += "\\-";
    else out += c;
  }
  if (!out.empty() && (out[0] == '.' || out[0] == '\'')) out = "\\&" + out;
  return out;
}

bool documented(const CLI::App* sub) { return sub->get_name() != "man" && sub->get_name() != "completion"; }

// "--radius,-r R": the option's names and, when it takes one, its value's name.
std::string option_names(const CLI::Option* option) {
  std::string names;
  for (const std::string& n : option->get_lnames()) names += (names.empty() ? "--" : ", --") + n;
  for (const std::string& n : option->get_snames()) names += (names.empty() ? "-" : ", -") + n;
  if (names.empty()) names = option->get_name();  // a positional argument
  if (option->get_expected_max() != 0 && !option->get_type_name().empty()) names += " " + option->get_type_name();
  return names;
}

std::string manual(const CLI::App& app) {
  std::ostringstream m;
  m << ".TH DISKTUNE 1 \"\" \"disktune " << DISKTUNE_VERSION << "\" \"User Commands\"\n"
    << ".SH NAME\ndisktune \\- maximal random disk packings tuned by disk injection and ejection\n"
    << ".SH SYNOPSIS\n.B disktune\n[\\fICOMMAND\\fR] [\\fIOPTIONS\\fR]\n"
    << ".SH DESCRIPTION\n" << roff(app.get_description()) << "\n"
    << ".SH COMMANDS\n";
  for (const CLI::App* sub : app.get_subcommands({})) {
    if (!documented(sub)) continue;
    m << ".SS " << sub->get_name() << "\n" << roff(sub->get_description()) << "\n";
    for (const CLI::Option* option : sub->get_options()) {
      m << ".TP\n.B " << roff(option_names(option)) << "\n" << roff(option->get_description()) << "\n";
    }
  }
  m << ".SH EXIT STATUS\n.TP\n0\ndone\n.TP\n1\ninternal error (a bug)\n.TP\n2\nbad usage or input\n"
    << ".TP\n3\na file could not be read or written\n.TP\n4\nthe target was not reached (the closest packing was "
       "written)\n"
    << ".SH FILES\nSummary lines, notes and warnings go to standard error; an output given as \\- is standard "
       "output, a points CSV given as \\- standard input.\n"
    << ".SH SEE ALSO\nThe README and docs/ of the source, and \\fBdisktune COMMAND \\-\\-help\\fR.\n";
  return m.str();
}

std::string completion(const CLI::App& app) {
  std::ostringstream s;
  s << "# bash completion for disktune " << DISKTUNE_VERSION << " (made by 'disktune completion')\n"
    << "_disktune() {\n  local cur=${COMP_WORDS[COMP_CWORD]} words\n"
    << "  if [ \"$COMP_CWORD\" -eq 1 ]; then\n    words=\"--help --version";
  for (const CLI::App* sub : app.get_subcommands({})) s << ' ' << sub->get_name();
  s << "\"\n  else\n    case ${COMP_WORDS[1]} in\n";
  for (const CLI::App* sub : app.get_subcommands({})) {
    s << "      " << sub->get_name() << ") words=\"";
    std::string words;
    for (const CLI::Option* option : sub->get_options())
      for (const std::string& n : option->get_lnames()) words += (words.empty() ? "--" : " --") + n;
    s << words << "\" ;;\n";
  }
  s << "    esac\n  fi\n"
    << "  if [[ $cur == -* || $COMP_CWORD -eq 1 ]]; then\n    COMPREPLY=($(compgen -W \"$words\" -- \"$cur\"))\n"
    << "  else\n    COMPREPLY=($(compgen -f -- \"$cur\"))\n  fi\n}\n"
    << "complete -o filenames -F _disktune disktune\n";
  return s.str();
}

void add_text_command(CLI::App& app, Action& action, const char* name, const char* what,
                      std::string (*make)(const CLI::App&)) {
  auto output = std::make_shared<std::string>("/dev/stdout");  // also for -o -
  CLI::App* cmd = app.add_subcommand(name, what);
  writes_file(cmd->add_option("--output,-o", *output, "File to write (default: standard output)"));
  cmd->callback([&app, &action, output, make] {
    action = [&app, output, make] {
      const std::string text = make(app);
      write_file_atomically(*output, [&](std::ostream& out) { out << text; });
      return kExitOk;
    };
  });
}

}  // namespace

void add_docs_commands(CLI::App& app, Action& action) {
  add_text_command(app, action, "man", "Print the manual page (roff: man -l FILE shows it)", manual);
  add_text_command(app, action, "completion",
                   "Print a bash completion script (source it, or put it in "
                   "/usr/share/bash-completion/completions/disktune)",
                   completion);
}

}  // namespace disktune::cli
