// SPDX-License-Identifier: GPL-3.0-or-later
// JSON files of the command, each with the tool's version and the command line first.
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "commands.h"
#include "disktune/errors.h"
#include "disktune/io.h"

namespace disktune::cli {
namespace {

std::vector<std::string>& invocation() {
  static std::vector<std::string> arguments;
  return arguments;
}

}  // namespace

void remember_invocation(int argc, char** argv) {
  invocation().assign(argv + (argc > 0 ? 1 : 0), argv + argc);
}

std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (const unsigned char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out + "\"";
}

void write_json(const std::string& path, const std::string& object) {
  const std::size_t open = object.find('{');
  if (open == std::string::npos) throw InternalError("write_json: the text for " + path + " is no JSON object");
  std::string head = "\n  \"disktune\": {\"version\": " + json_string(DISKTUNE_VERSION) + ", \"arguments\": [";
  for (std::size_t k = 0; k < invocation().size(); ++k) head += (k ? ", " : "") + json_string(invocation()[k]);
  head += "]}";
  const bool empty = object.find_first_not_of(" \t\r\n", open + 1) == object.find('}', open);
  const std::string text = object.substr(0, open + 1) + head + (empty ? "\n" : ",") + object.substr(open + 1);
  write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

}  // namespace disktune::cli
