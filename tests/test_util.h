// SPDX-License-Identifier: GPL-3.0-or-later
// Glue between the library and the independent oracle: the oracle sees plain numbers.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "disktune/errors.h"
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

/// The message of the exception E that f throws ("" and a test failure if none).
template <class E = InvalidInput, class F>
std::string message_of(F&& f) {
  try {
    f();
  } catch (const E& e) {
    return e.what();
  }
  ADD_FAILURE() << "no exception thrown";
  return "";
}

/// The radius of each live disk, in id order (as centers_of), for the oracles.
inline std::vector<double> radii_of(const Packing& packing) {
  std::vector<double> out;
  for (DiskId id : packing.ids()) out.push_back(packing.radius(id));
  return out;
}

}  // namespace disktune::test
