#include "fdh/os/temporaries.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <thread>

#include "fdh/os/child_process.hpp"
#include "fdh/os/last_resort.hpp"
#include "fdh/os/work_folder.hpp"
#include "temp_dir.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;

TEST(Temporaries, RecordedOnesAreRemovedFilesFirstForgottenOnesKept) {
  const fs::path dir = fresh_temp_dir("temporaries");
  fs::create_directories(dir / "folder");
  std::ofstream(dir / "folder" / "a") << "a";
  std::ofstream(dir / "b") << "b";
  std::ofstream(dir / "kept") << "k";
  {
    const RecordedTemporary folder((dir / "folder").string(), true);
    const RecordedTemporary a((dir / "folder" / "a").string()), b((dir / "b").string());
    { const RecordedTemporary forgotten((dir / "kept").string()); }
    remove_recorded_temporaries();
  }
  EXPECT_FALSE(fs::exists(dir / "folder"));
  EXPECT_FALSE(fs::exists(dir / "b"));
  EXPECT_TRUE(fs::exists(dir / "kept"));
}

TEST(Temporaries, AChildForgetsItsParentsRecord) {
  const fs::path dir = fresh_temp_dir("temporaries_child");
  std::ofstream(dir / "parents") << "p";
  const RecordedTemporary parents((dir / "parents").string());
  ChildProcess child([] {
    remove_recorded_temporaries();  // the child's record is empty
    return 0;
  });
  EXPECT_TRUE(child.wait().ok());
  EXPECT_TRUE(fs::exists(dir / "parents"));
}

TEST(Temporaries, NamesAndLiveProcesses) {
  EXPECT_EQ(temporary_name("a/b.vf", 7), "a/b.vf.tmp." + std::to_string(::getpid()) + ".7");
  EXPECT_TRUE(process_runs(::getpid()));
  ChildProcess child([] { return 0; });
  const pid_t pid = child.pid();
  child.wait();
  EXPECT_FALSE(process_runs(pid));
}

// An exception that escapes a thread ends the process with status 3, its temporaries removed.
TEST(LastResort, AnEscapedExceptionIsAnInternalErrorAfterTheTemporariesGo) {
  const fs::path dir = fresh_temp_dir("last_resort");
  const std::string temp = (dir / "out.tmp.1.0").string();
  ChildProcess child([&] {
    end_with_internal_error_on_terminate();
    std::ofstream(temp) << "half";
    const RecordedTemporary recorded(temp);
    std::thread([] { throw std::logic_error("nobody catches this"); }).join();
    return 0;
  });
  const ChildStatus s = child.wait();
  EXPECT_TRUE(s.exited()) << s.words();
  EXPECT_EQ(s.exit_code(), kInternalErrorStatus);
  EXPECT_FALSE(fs::exists(temp));
}

TEST(WorkFolder, RefusesALinkAtItsTemporariesAndWritesThroughNone) {
  const fs::path dir = fresh_temp_dir("work_folder_links");
  fs::create_directories(dir / "victim");
  std::ofstream(dir / "victim" / "precious") << "mine";
  fs::create_directories(dir / "work");
  fs::create_directory_symlink(dir / "victim", dir / "work" / "tmp");
  EXPECT_THROW(WorkFolder((dir / "work").string(), 0), std::runtime_error);
  fs::remove(dir / "work" / "tmp");
  const WorkFolder w((dir / "work").string(), 0);
  w.clear_stale_temporaries();
  fs::create_directory_symlink(dir / "victim", dir / "work" / "run");
  EXPECT_THROW(w.write_whole((dir / "work" / "run" / "marker").string(), "x"), std::runtime_error);
  EXPECT_FALSE(fs::exists(dir / "victim" / "marker"));
  EXPECT_EQ(fs::directory_iterator(dir / "work" / "tmp"), fs::directory_iterator());
  fs::remove(dir / "work" / "run");
  w.make_subfolder("run");
  w.write_whole((dir / "work" / "run" / "marker").string(), "x\n");
  EXPECT_TRUE(fs::is_regular_file(dir / "work" / "run" / "marker"));
}

}  // namespace
}  // namespace fdh::verify
