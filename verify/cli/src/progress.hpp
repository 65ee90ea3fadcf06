// --progress WHEN and --quiet on the long commands: how the progress line
// (fdh/os/progress_line.hpp) shows.
#pragma once

#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "fdh/os/progress_line.hpp"

namespace fdh::verify {

// How progress should show on the command's standard error (fdh/os/progress_line.hpp).
inline ProgressShow progress_wanted(const Io& io, ProgressWhen when) {
  return progress_wanted(io.err, when);
}
// --quiet given: none; else as --progress auto.
inline ProgressShow progress_wanted(const Io& io, bool quiet) {
  return progress_wanted(io.err, quiet ? ProgressWhen::Never : ProgressWhen::Auto);
}

// --quiet and --progress WHEN on a long command, into `when` (--quiet: Never).
CLI::Option* add_quiet_flag(CLI::App& cmd, ProgressWhen& when);

}  // namespace fdh::verify
