// SPDX-License-Identifier: GPL-3.0-or-later
// Options shared by several commands, validated as they are parsed: CLI11 turns "-1"
// or 2^64 into an unsigned number silently (wrapping), so whole numbers are checked as
// text first.
#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>

#include "commands.h"

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

}  // namespace disktune::cli
