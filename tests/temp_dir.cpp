#include "temp_dir.hpp"

#include <gtest/gtest.h>
#include <stdlib.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace fdh {
namespace {

namespace fs = std::filesystem;

// The folders made since the last removal, by this process (a forked child removes nothing).
struct Made {
  std::mutex mutex;
  std::vector<fs::path> folders;
  pid_t owner = ::getpid();
};

Made& made() {
  static Made m;
  return m;
}

bool keep_files() {
  const char* keep = std::getenv("FDH_KEEP_TEST_FILES");
  return keep && std::strcmp(keep, "1") == 0;
}

void remove_made() {
  Made& m = made();
  std::lock_guard<std::mutex> lock(m.mutex);
  if (::getpid() != m.owner) return;
  for (const fs::path& dir : m.folders) {
    if (keep_files()) {
      std::fprintf(stderr, "FDH_KEEP_TEST_FILES: kept %s\n", dir.c_str());
      continue;
    }
    std::error_code ec;
    fs::remove_all(dir, ec);
    if (ec) std::fprintf(stderr, "could not remove %s: %s\n", dir.c_str(), ec.message().c_str());
  }
  m.folders.clear();
}

// Removes each test's folders when it ends, whatever its result.
class RemoveAtTestEnd : public ::testing::EmptyTestEventListener {
  void OnTestEnd(const ::testing::TestInfo&) override { remove_made(); }
};

// Installed before main (gtest_main's) runs the tests; at exit for folders made outside a test
// (the list is made first, so that it outlives the exit handler).
[[maybe_unused]] const bool installed = [] {
  made();
  ::testing::UnitTest::GetInstance()->listeners().Append(new RemoveAtTestEnd);
  std::atexit(remove_made);
  return true;
}();

}  // namespace

fs::path fresh_temp_dir(const std::string& name) {
  std::string pattern = ::testing::TempDir() + "fdh_" + name + ".XXXXXX";
  if (::mkdtemp(pattern.data()) == nullptr)
    throw std::system_error(errno, std::generic_category(), "mkdtemp " + pattern);
  Made& m = made();
  std::lock_guard<std::mutex> lock(m.mutex);
  m.folders.emplace_back(pattern);
  return pattern;
}

}  // namespace fdh
