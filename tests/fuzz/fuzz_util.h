// SPDX-License-Identifier: GPL-3.0-or-later
// What the fuzz targets share (README, "Sanitizers and fuzzing"): the input as a file,
// since the readers take paths; the rule that disktune's documented exceptions
// (InvalidInput, IoError) are answers and anything else is a finding; and a small
// surface to read surface samples and sizings onto.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <string>

#include "disktune/errors.h"
#include "disktune/surface_domain.h"

namespace disktune::fuzz {

/// A file of this process, named with `extension` (the mesh readers choose their format
/// by it), rewritten with every input and removed at exit.
class InputFile {
 public:
  explicit InputFile(const std::string& extension) {
    const char* dir = std::getenv("TMPDIR");
    path_ = std::string(dir && *dir ? dir : "/tmp") + "/disktune-fuzz-" +
            std::to_string(static_cast<long>(getpid())) + extension;
  }
  ~InputFile() { std::remove(path_.c_str()); }
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  const std::string& write(const std::uint8_t* data, std::size_t size) {
    std::ofstream out(path_, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    out.close();
    if (!out) {
      // Not a finding in disktune: the harness cannot run. Stop loudly.
      std::fprintf(stderr, "fuzz harness: cannot write %s\n", path_.c_str());
      std::abort();
    }
    return path_;
  }

 private:
  std::string path_;
};

/// Runs `read`; InvalidInput and IoError are the answers a bad file may get, so they end
/// the input quietly, but only with a message (errors.h: a sentence a user can act on).
/// Any other exception escapes to libFuzzer, which reports it as a crash.
template <class F>
void expect_documented_errors(F&& read) {
  try {
    read();
  } catch (const InvalidInput& e) {
    if (!*e.what()) std::abort();  // an empty message is a finding too
  } catch (const IoError& e) {
    if (!*e.what()) std::abort();
  }
}

/// A unit cube without its top face: 8 vertices, 10 triangles facing out, one open
/// boundary loop (so boundary disks are exercised as well as interior ones).
inline std::shared_ptr<const SurfaceDomain> open_box() {
  std::vector<Vec3> v = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                         {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  std::vector<SurfaceDomain::Triangle> t = {{0, 2, 1}, {0, 3, 2}, {0, 1, 5}, {0, 5, 4}, {1, 2, 6},
                                            {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  return std::make_shared<const SurfaceDomain>(std::move(v), std::move(t));
}

}  // namespace disktune::fuzz
