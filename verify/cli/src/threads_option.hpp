// --threads N on simulate, certify and report: how many threads their loops use
// (fdh/check/thread_limit.hpp).
#pragma once

#include <CLI/CLI.hpp>

#include <string>

#include "fdh/check/thread_limit.hpp"

namespace fdh::verify {

// --threads N in [1, 1024] (default 0: every core); `what` names the loops ("the step").
CLI::Option* add_threads_option(CLI::App& cmd, int& threads, const std::string& what);

}  // namespace fdh::verify
