// fdhcert run as a process of its own, for the tests that need what an in-process run cannot
// give: output to files (not a terminal), the wall clock, a kill at a deadline.
#pragma once

#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "fdh/os/child_process.hpp"
#include "text_file.hpp"

namespace fdh::verify {

struct Ended {
  int status = -1;  // the exit status; -1 if it had to be killed at the deadline
  double seconds = 0;
  std::string out, err;
};

// fdhcert `args`, standard output and error into files of `dir`; SIGKILL at `deadline` seconds.
inline Ended run_fdhcert(const std::vector<std::string>& args, const std::filesystem::path& dir,
                         double deadline = std::numeric_limits<double>::infinity()) {
  std::vector<std::string> argv = {FDHCERT_BIN};
  argv.insert(argv.end(), args.begin(), args.end());
  std::vector<char*> a;
  for (const std::string& s : argv) a.push_back(const_cast<char*>(s.c_str()));
  a.push_back(nullptr);
  const std::string out = (dir / "stdout").string(), err = (dir / "stderr").string();
  const auto start = std::chrono::steady_clock::now();
  ChildProcess process([&] {
    ::dup2(::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644), 1);
    ::dup2(::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644), 2);
    ::execv(a[0], a.data());
    return 127;
  });
  Ended e;
  for (;;) {
    e.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (const std::optional<ChildStatus> s = process.poll()) {
      e.status = s->exited() ? s->exit_code() : -1;
      break;
    }
    if (e.seconds > deadline) {
      process.kill();
      process.wait();
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  e.out = text_of(out), e.err = text_of(err);
  return e;
}

}  // namespace fdh::verify
