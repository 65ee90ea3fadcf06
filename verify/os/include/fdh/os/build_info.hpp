// What this build is: fixed when CMake configures, so that a run never asks git.
#pragma once

#include <string>

namespace fdh::verify {

// `git rev-parse --short=12 HEAD` of the source tree when the build was configured, or
// "unknown" outside a git checkout. A new commit re-runs the configure step (the ref files are
// its dependencies) and recompiles one file.
std::string build_commit();

}  // namespace fdh::verify
