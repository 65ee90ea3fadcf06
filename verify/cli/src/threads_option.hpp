// --threads N on simulate, certify and report: how many threads their loops use (oneTBB).
#pragma once

#include <tbb/global_control.h>
#include <CLI/CLI.hpp>

#include <optional>
#include <ostream>
#include <string>

namespace fdh::verify {

// --threads N in [1, 1024] (default 0: every core); `what` names the loops ("the step"). The
// results are the same for any number: the loops cut their work by its size alone and merge in
// order (fdh/cloth/parallel.hpp, fdh/check/parallel.hpp).
CLI::Option* add_threads_option(CLI::App& cmd, int& threads, const std::string& what);

// Caps oneTBB at `threads` while it lives; 0 leaves every core. With `err`: when --threads N > 1
// was given while a plug-in that is not declared thread-safe is loaded (its loops then run on
// one thread, fdh/check/parallel.hpp), says so on `err`, naming the plug-ins.
class ThreadLimit {
 public:
  explicit ThreadLimit(int threads);
  ThreadLimit(int threads, std::ostream& err);

 private:
  std::optional<tbb::global_control> limit_;
};

// The words ThreadLimit prints, or "" when --threads is not ignored.
std::string threads_ignored(int threads);

}  // namespace fdh::verify
