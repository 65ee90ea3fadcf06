// The progress line of long commands (certify, report, table1, simulate, scenes, fuzz, peers):
// it draws the jobs' one progress type (fdh/os/progress.hpp), what is being done, how far it has
// got and its rate, on standard error. Shown only when standard error
// is a terminal and the command has no --quiet, so that logs and pipes get none of it.
#pragma once

#include <CLI/CLI.hpp>

#include <chrono>
#include <ostream>
#include <string>
#include <string_view>

#include "commands.hpp"
#include "fdh/os/progress.hpp"

namespace fdh::verify {

class ProgressLine {
 public:
  ProgressLine(std::ostream& err, bool show) : err_(err), show_(show) {}
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;
  ~ProgressLine() { clear(); }

  // "<stage>: <done> of <total> <unit> (<rate> <unit>/s), <detail>"; total <= 0: no "of".
  // Redrawn at most ten times a second, and whenever the stage changes (its rate then starts
  // again) or the detail does.
  void draw(const Progress& p);
  // A sink that draws what a job reports, its stage after `prefix`.
  ProgressSink sink(std::string prefix = {});
  // Erases the line (before the command prints its results).
  void clear();

 private:
  using Clock = std::chrono::steady_clock;
  std::ostream& err_;
  bool show_;
  std::string what_, detail_;
  Clock::time_point stage_start_, last_draw_;
  std::size_t drawn_ = 0;  // characters on the line now
};

// True when progress should show: standard error is the process's own and a terminal, and the
// command was not given --quiet.
bool progress_wanted(const Io& io, bool quiet);

// --quiet on a long command.
CLI::Option* add_quiet_flag(CLI::App& cmd, bool& quiet);

}  // namespace fdh::verify
