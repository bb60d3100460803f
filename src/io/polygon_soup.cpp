// SPDX-License-Identifier: GPL-3.0-or-later
// The single entry of the mesh file readers: the file is read whole, then parsed by the
// reader of its extension. Each reader is an internal header compiled here only. They
// replace CGAL's readers, which crashed on some malformed headers and allocated whatever
// a file's counts claimed (#17).
#include "polygon_soup.h"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>

#include "disktune/errors.h"
#include "file_extension.h"
#include "obj_reader.h"
#include "off_reader.h"
#include "ply_reader.h"
#include "stl_reader.h"

namespace disktune::detail {
namespace {

std::string file_bytes(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw IoError("cannot read the mesh file " + path + ": it is a folder");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw IoError("cannot open the mesh file " + path + ": check the path and permissions");
  }
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw IoError("cannot read the mesh file " + path + ": a read error");
  return bytes;
}

}  // namespace

PolygonSoup read_polygon_soup(const std::string& path) {
  using Reader = PolygonSoup (*)(const std::string&, std::string_view);
  const std::string ext = lower_extension(path);
  const Reader reader = ext == ".off"   ? read_off
                        : ext == ".obj" ? read_obj
                        : ext == ".ply" ? read_ply
                        : ext == ".stl" ? read_stl
                                        : nullptr;
  if (!reader) {
    throw InvalidInput("cannot read " + path + " as a mesh: " +
                       (ext.empty() ? "it has no extension" : "its extension is '" + ext + "'") +
                       "; give it the one of its format: .off, .obj, .ply or .stl");
  }
  return reader(path, file_bytes(path));
}

}  // namespace disktune::detail
