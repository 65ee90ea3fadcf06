// --threads N on simulate, certify and report: how many threads their loops use (oneTBB).
#pragma once

#include <tbb/global_control.h>
#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace fdh::verify {

// --threads N in [1, 1024] (default 0: every core); `what` names the loops ("the step"). The
// results are the same for any number: the loops cut their work by its size alone and merge in
// order (fdh/cloth/parallel.hpp, fdh/check/parallel.hpp).
CLI::Option* add_threads_option(CLI::App& cmd, int& threads, const std::string& what);

// Caps oneTBB at `threads` while it lives; 0 leaves every core.
class ThreadLimit {
 public:
  explicit ThreadLimit(int threads);

 private:
  std::optional<tbb::global_control> limit_;
};

}  // namespace fdh::verify
