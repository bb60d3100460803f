// SPDX-License-Identifier: GPL-3.0-or-later
// Glue between the library and the independent oracle: the oracle sees plain numbers.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "disktune/packing.h"
#include "disktune/periodic_box.h"
#include "oracle/oracle.h"

namespace disktune::test {

inline oracle::Points centers_of(const Packing& packing) {
  oracle::Points out;
  for (DiskId id : packing.ids()) out.push_back({packing.center(id).x, packing.center(id).y});
  return out;
}

inline oracle::Box box_of(const PeriodicBox& box) { return {box.width(), box.height()}; }

/// A fresh folder for the running test, removed afterwards.
struct TempDir {
  std::filesystem::path path =
      std::filesystem::temp_directory_path() /
      ("disktune_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
       ::testing::UnitTest::GetInstance()->current_test_info()->test_suite_name() + "_" +
       ::testing::UnitTest::GetInstance()->current_test_info()->name());
  TempDir() { std::filesystem::create_directories(path); }
  ~TempDir() { std::filesystem::remove_all(path); }
  std::string file(const std::string& name) const { return (path / name).string(); }
};

}  // namespace disktune::test
