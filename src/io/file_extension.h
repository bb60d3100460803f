// SPDX-License-Identifier: GPL-3.0-or-later
// A file's extension in lower case (internal), to choose its format by: ".OFF" reads
// and writes as ".off".
#pragma once

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace disktune::detail {

/// ".off" for "Model.OFF"; "" when the name has no extension.
inline std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace disktune::detail
