// A fresh, empty folder for one test, under GoogleTest's temporary directory.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace fdh {

inline std::filesystem::path fresh_temp_dir(const std::string& name) {
  const std::filesystem::path d = std::filesystem::path(::testing::TempDir()) / ("fdh_" + name);
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

}  // namespace fdh
