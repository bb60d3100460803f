// SPDX-License-Identifier: GPL-3.0-or-later
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>

#include "disktune/errors.h"
#include "disktune/io.h"

namespace disktune {

void write_file_atomically(const std::string& path,
                           const std::function<void(std::ostream&)>& write) {
  // A device or a pipe (/dev/null, /dev/stdout, a FIFO) is written straight into:
  // renaming a temporary over it would replace the device with a plain file.
  std::error_code ec;
  const auto kind = std::filesystem::status(path, ec);
  if (!ec && std::filesystem::exists(kind) && !std::filesystem::is_regular_file(kind) &&
      !std::filesystem::is_directory(kind)) {
    std::ofstream out(path, std::ios::binary);
    if (!out) throw IoError("cannot write '" + path + "': " + std::strerror(errno));
    write(out);
    out.flush();
    if (!out) throw IoError("writing '" + path + "' failed");
    return;
  }
  // A per-call suffix keeps concurrent writers to the same path apart.
  const std::string tmp = path + ".tmp" + std::to_string(std::random_device{}() & 0xffffff);
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) {
      throw IoError("cannot write '" + path + "': " + std::strerror(errno) +
                    " (check that the folder exists and is writable)");
    }
    try {
      write(out);
      out.flush();
    } catch (...) {
      out.close();
      std::remove(tmp.c_str());
      throw;
    }
    if (!out) {
      std::remove(tmp.c_str());
      throw IoError("writing '" + path + "' failed (disk full?)");
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    std::remove(tmp.c_str());
    throw IoError("cannot write '" + path + "': " + why);
  }
}

}  // namespace disktune
