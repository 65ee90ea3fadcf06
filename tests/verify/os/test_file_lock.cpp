#include "fdh/os/file_lock.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "fdh/os/child_process.hpp"
#include "temp_dir.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;

TEST(FileLock, ASecondHolderWaitsThenIsRefusedAndGetsItOnceFree) {
  const fs::path d = fresh_temp_dir("file_lock");
  const std::string path = (d / "lock").string();
  {
    const FileLock held(path, 0);
    // flock locks belong to the open file: another process (even this one's child, opening
    // the file anew) is refused while it is held.
    ChildProcess other([&] {
      try {
        const FileLock again(path, 0.1);
        return 0;
      } catch (const LockBusy&) {
        return 7;
      }
    });
    EXPECT_EQ(other.wait().exit_code(), 7);
  }
  ChildProcess after([&] {
    const FileLock again(path, 0);
    return 0;
  });
  EXPECT_TRUE(after.wait().ok());
  fs::remove_all(d);
}

}  // namespace
}  // namespace fdh::verify
