// fdhcert's standard output is written in place: a write that failed (a full disk, a closed
// stdout) is found when the command is done, and is exit status 2 with the system's reason,
// never 0 (docs/limits.md).
#pragma once

#include <ostream>

namespace fdh::verify {

// `status`, or 2 when `out` cannot be flushed, saying why on `err` ("fdhcert: error: standard
// output: REASON").
int checked_output(int status, std::ostream& out, std::ostream& err);

// As the process ends: what std::cout held, then the C stream and its close. `status`, or 2
// (said on standard error unless `status` was 2 already: the command said so).
int checked_stdout(int status);

}  // namespace fdh::verify
