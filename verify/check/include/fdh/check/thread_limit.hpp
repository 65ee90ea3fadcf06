// How many threads the suite's loops use (--threads N on simulate, certify and report): oneTBB
// capped for a run. The results are the same for any number: the loops cut their work by its
// size alone and merge in order (fdh/cloth/parallel.hpp, fdh/check/parallel.hpp).
#pragma once

#include <tbb/global_control.h>

#include <optional>
#include <ostream>
#include <string>

namespace fdh::verify {

// Caps oneTBB at `threads` while it lives; 0 leaves every core. With `err`: when threads > 1
// while a plug-in that is not declared thread-safe is loaded (its loops then run on one thread,
// fdh/check/parallel.hpp), says so on `err`, naming the plug-ins.
class ThreadLimit {
 public:
  explicit ThreadLimit(int threads);
  ThreadLimit(int threads, std::ostream& err);

 private:
  std::optional<tbb::global_control> limit_;
};

// The words ThreadLimit prints, or "" when the thread count is not ignored.
std::string threads_ignored(int threads);

}  // namespace fdh::verify
