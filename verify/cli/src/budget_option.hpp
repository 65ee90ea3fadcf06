// --budget SECONDS on certify and fuzz: the run's time budget (fdh/os/budget.hpp), counted from
// the start of the command (run_start).
#pragma once

#include <CLI/CLI.hpp>

#include "fdh/os/budget.hpp"

namespace fdh::verify {

// --budget SECONDS (0 < SECONDS <= 10^7) into `budget`; `what` says what it stops.
CLI::Option* add_budget_option(CLI::App& cmd, Budget& budget, const std::string& what);

}  // namespace fdh::verify
