// SPDX-License-Identifier: GPL-3.0-or-later
// Options shared by several commands, validated as they are parsed: CLI11 turns "-1"
// or 2^64 into an unsigned number silently (wrapping), so whole numbers are checked as
// text first.
#include <fcntl.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <string>

#include "commands.h"
#include "disktune/threads.h"

namespace disktune::cli {

CLI::Validator whole_number(std::uint64_t low, std::uint64_t high, const std::string& what) {
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        const std::string range = std::to_string(low) + " to " + std::to_string(high);
        if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
          return what + " must be a whole number from " + range + ", not '" + text + "'";
        const std::string max = std::to_string(high);
        const std::string digits = text.substr(std::min(text.find_first_not_of('0'), text.size() - 1));
        if (digits.size() > max.size() || (digits.size() == max.size() && digits > max) ||
            std::stoull(digits) < low)
          return what + " " + text + " is out of range: give " + range;
        return "";
      },
      "");
}

CLI::Option* add_seed_option(CLI::App* cmd, std::uint64_t& seed) {
  return cmd->add_option("--seed", seed, "Random seed (0 to 2^64-1); the same seed gives the same output")
      ->check(whole_number(0, UINT64_MAX, "--seed"))
      ->capture_default_str();
}

CLI::Option* add_threads_option(CLI::App* cmd, unsigned& threads, const std::string& what) {
  // Also the library's default (set_default_threads), for the work a command does without
  // naming a count: the final checks, the restricted Delaunay meshes.
  return cmd
      ->add_option("--threads", threads,
                   what + " (default: one per core); the output is the same for any number")
      ->check(whole_number(1, 4096, "--threads"))
      ->each([](const std::string& text) {
        set_default_threads(static_cast<unsigned>(std::stoul(text)));
      });
}

void add_picture_options(CLI::App* cmd, PictureArgs& args, const std::string& pictures) {
  cmd->add_option("--picture-dir,--png-dir", args.dir,
                  "Write " + pictures + " into this existing folder");
  cmd->add_option("--picture-format", args.format,
                  "The pictures as png (the default), pdf or svg (vectors and real text, for "
                  "papers and slides; angles.pdf for angles.png)")
      ->transform(CLI::Validator(
          [](std::string& text) -> std::string {
            std::string name = text;
            for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
            for (const PictureFormat f :
                 {PictureFormat::png, PictureFormat::pdf, PictureFormat::svg}) {
              if (name == extension(f)) return text = std::to_string(static_cast<int>(f)), "";
            }
            return "--picture-format must be png, pdf or svg, not '" + text + "'";
          },
          "png|pdf|svg", "picture format"));
}

namespace {
bool quiet_flag = false;
}  // namespace

void set_quiet(bool on) { quiet_flag = on; }
bool quiet() { return quiet_flag; }

int say(const char* format, ...) {
  if (quiet_flag) return 0;
  std::va_list args;
  va_start(args, format);
  const int n = std::vfprintf(stderr, format, args);
  va_end(args);
  return n;
}

CLI::Option* writes_file(CLI::Option* option) {
  return option->transform([](std::string path) { return path == "-" ? std::string("/dev/stdout") : path; });
}

namespace {

// Standard input copied whole into a file that has no name (unlinked at once), so that
// a reader may open it more than once (the radius is read before the disks); the path
// /proc/self/fd/N opens it afresh each time. Empty until "-" is read.
std::string stdin_copy() {
  char name[] = "/tmp/disktune-stdin-XXXXXX";
  const int fd = mkstemp(name);
  if (fd < 0) throw CLI::ValidationError("-", "cannot keep standard input: no temporary file in /tmp");
  unlink(name);
  char buffer[1 << 16];
  for (ssize_t n; (n = read(STDIN_FILENO, buffer, sizeof buffer)) != 0;) {
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 || write(fd, buffer, static_cast<std::size_t>(n)) != n)
      throw CLI::ValidationError("-", "cannot read standard input into /tmp");
  }
  return "/proc/self/fd/" + std::to_string(fd);
}

std::string& stdin_path() {
  static std::string copy;
  return copy;
}

}  // namespace

CLI::Option* reads_file(CLI::Option* option) {
  return option->transform([](std::string path) {
    if (path != "-") return path;
    if (!stdin_path().empty()) throw CLI::ValidationError("-", "only one input can be standard input");
    return stdin_path() = stdin_copy();
  });
}

std::string naming_stdin(std::string message) {
  const std::string& path = stdin_path();
  if (path.empty()) return message;
  for (std::size_t at; (at = message.find(path)) != std::string::npos;) message.replace(at, path.size(), "standard input");
  return message;
}

double memory_size(const std::string& text) {
  // Digits with an optional fraction, then an optional unit: K, M, G or T, alone or
  // followed by B or iB (binary either way, as ulimit and free count).
  std::size_t i = 0;
  while (i < text.size() && (std::isdigit(static_cast<unsigned char>(text[i])) || text[i] == '.')) ++i;
  const std::string number = text.substr(0, i);
  std::string unit = text.substr(i);
  for (char& c : unit) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (number.empty() || number.find_first_of("0123456789") == std::string::npos ||
      number.find('.') != number.rfind('.'))
    return -1;
  double scale = 1;
  if (!unit.empty() && unit != "B") {
    const std::string prefixes = "KMGT";
    const std::size_t p = prefixes.find(unit[0]);
    const std::string rest = unit.substr(1);
    if (p == std::string::npos || !(rest.empty() || rest == "B" || rest == "IB")) return -1;
    scale = std::pow(1024.0, static_cast<double>(p + 1));
  }
  const double bytes = std::stod(number) * scale;
  return bytes >= 1 && std::isfinite(bytes) ? bytes : -1;
}

void add_memory_option(CLI::App* cmd, double& bytes) {
  cmd->add_option_function<std::string>(
         "--max-memory", [&bytes](const std::string& text) { bytes = memory_size(text); },
         "Memory the job may use: bytes, or with K, M, G, T (powers of 1024), e.g. 8G, 500M. "
         "Jobs estimated to need more are refused before any work; by default the memory "
         "available (MemAvailable, the process's limits and its cgroup's, the smallest)")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            return memory_size(text) > 0 ? ""
                                         : "--max-memory must be a positive size in bytes, or with K, M, G "
                                           "or T (e.g. 8G, 500M), not '" + text + "'";
          },
          "SIZE"));
}

}  // namespace disktune::cli
