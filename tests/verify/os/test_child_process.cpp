#include "fdh/os/child_process.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <string>
#include <thread>

namespace fdh::verify {
namespace {

// Whether `pid` has ended: no such process, or a zombie its new parent has not reaped yet.
bool ended(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(stat, line)) return true;
  const std::size_t close = line.rfind(')');  // the name may hold spaces
  return close == std::string::npos || line.substr(close + 2, 1) == "Z";
}

TEST(ChildProcess, ExitsWithWhatItsBodyReturns) {
  ChildProcess ok([] { return 0; });
  EXPECT_TRUE(ok.wait().ok());
  ChildProcess three([] { return 3; });
  const ChildStatus s = three.wait();
  EXPECT_TRUE(s.exited());
  EXPECT_EQ(s.exit_code(), 3);
  EXPECT_EQ(s.words(), "exit status 3");
}

TEST(ChildProcess, KilledItEndsBySignalAndPollSeesIt) {
  ChildProcess sleeper([] {
    ::pause();
    return 0;
  });
  EXPECT_FALSE(sleeper.poll());  // still running
  sleeper.kill();
  const ChildStatus s = sleeper.wait();
  EXPECT_TRUE(WIFSIGNALED(s.raw));
  EXPECT_EQ(s.words(), "signal 9");
}

// A child whose parent dies is killed with it (PR_SET_PDEATHSIG): the grandchild of this test
// reports its pid through a pipe, its parent exits, and the grandchild is gone soon after.
TEST(ChildProcess, DiesWithItsParent) {
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  ChildProcess parent([&] {
    ChildProcess child([] {
      ::pause();
      return 0;
    });
    const pid_t pid = child.pid();
    [[maybe_unused]] const ssize_t n = ::write(fds[1], &pid, sizeof pid);
    ::_exit(0);  // without reaping: the kernel's death signal must end the child
    return 0;
  });
  ::close(fds[1]);
  pid_t grandchild = 0;
  ASSERT_EQ(::read(fds[0], &grandchild, sizeof grandchild), ssize_t(sizeof grandchild));
  ::close(fds[0]);
  EXPECT_TRUE(parent.wait().ok());
  bool gone = false;
  for (int i = 0; i < 200 && !gone; ++i) {
    gone = ended(grandchild);
    if (!gone) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  EXPECT_TRUE(gone);
}

}  // namespace
}  // namespace fdh::verify
