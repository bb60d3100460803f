// SPDX-License-Identifier: GPL-3.0-or-later
// Checks on the files a command will write, made before any work: their folders exist,
// no two outputs are one file, and no output is a file the command reads.
#include <cstdio>
#include <filesystem>
#include <system_error>

#include "commands.h"
#include "disktune/errors.h"

namespace disktune::cli {

namespace fs = std::filesystem;

void check_output_folder(const std::string& path) {
  if (path.empty()) return;
  const fs::path parent = fs::path(path).parent_path();
  if (!parent.empty() && !fs::is_directory(parent)) {
    throw IoError("cannot write '" + path + "': folder '" + parent.string() + "' does not exist");
  }
}

MeshFormat output_mesh_format(const std::string& path, const std::string& format, bool surface) {
  MeshFormat out;
  try {
    out = format.empty() ? mesh_format_for_path(path) : mesh_format_named(format);
  } catch (const InvalidInput& e) {
    throw InvalidInput(std::string(e.what()) + (format.empty() ? " with --format NAME" : ""));
  }
  if (out != MeshFormat::Triangle) return out;
  if (surface) {
    throw InvalidInput(
        "Triangle's .node/.ele files hold planar meshes, and this one is a surface: write it as "
        ".off, .obj, .ply, .vtk, .vtu, .msh or .stl");
  }
  // Two files, so a path the library itself names by extension (.node or .ele).
  bool named = false;
  try {
    named = mesh_format_for_path(path) == MeshFormat::Triangle;
  } catch (const InvalidInput&) {
  }
  if (!named) {
    throw InvalidInput(
        "Triangle's mesh format is two files, NAME.node and NAME.ele: give --output NAME.node");
  }
  return out;
}

void add_format_option(CLI::App* cmd, std::string& format) {
  cmd->add_option(
      "--format", format,
      "Mesh format when the output's extension does not say it (standard output, -): off, obj, "
      "ply, "
      "ply-binary, vtk, vtu, msh, stl (triangle: Triangle's .node/.ele pair, by path only)");
}

void require_output(const std::string& output, const std::string& svg, const char* command) {
  if (!output.empty() || !svg.empty()) return;
  throw InvalidInput(
      std::string(command) +
      ": nothing would be written: give --output FILE.csv (or -o - for standard output, "
      "-o /dev/null for the summary line alone)");
}

namespace {

// True when both paths name one regular file (or would: for a file not yet written, the
// same place once links and "." / ".." in its folders are resolved). Devices such as
// /dev/null may be named twice.
bool same_file(const std::string& a, const std::string& b) {
  std::error_code ea, eb;
  const auto sa = fs::status(a, ea), sb = fs::status(b, eb);
  if ((fs::exists(sa) && !fs::is_regular_file(sa)) || (fs::exists(sb) && !fs::is_regular_file(sb))) return false;
  if (fs::exists(sa) && fs::exists(sb)) return fs::equivalent(a, b, ea) && !ea;
  const fs::path ca = fs::weakly_canonical(fs::absolute(a), ea), cb = fs::weakly_canonical(fs::absolute(b), eb);
  return !ea && !eb && ca == cb;
}

}  // namespace

void check_files_apart(const std::vector<NamedFile>& inputs, const std::vector<NamedFile>& outputs,
                       const std::string& in_place) {
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const NamedFile& out = outputs[i];
    if (out.path.empty()) continue;
    for (std::size_t j = 0; j < i; ++j)
      if (!outputs[j].path.empty() && same_file(outputs[j].path, out.path))
        throw InvalidInput(outputs[j].option + " and " + out.option + " name the same file '" + out.path +
                           "': one would replace the other; give each output its own file");
    for (const NamedFile& in : inputs) {
      if (in.path.empty() || !same_file(in.path, out.path)) continue;
      if (out.option == in_place && in.option != "--domain") continue;  // an update in place
      throw InvalidInput(out.option + " '" + out.path + "' is the file this command reads (" + in.option +
                         "): writing it would replace that input; write to another file");
    }
  }
}

std::vector<NamedFile> domain_files(const DomainArgs& domain) {
  std::vector<NamedFile> files;
  if (domain.kind != "periodic") files.push_back({"--domain", domain.kind});
  std::error_code ec;
  if (!domain.sizing.empty() && fs::is_regular_file(domain.sizing, ec)) files.push_back({"--sizing", domain.sizing});
  return files;
}

}  // namespace disktune::cli
