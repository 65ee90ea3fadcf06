// --budget SECONDS on certify and fuzz: the run's time budget (fdh/os/budget.hpp), counted from
// the start of the command (loading and probing plug-ins included).
#pragma once

#include <CLI/CLI.hpp>

#include "fdh/os/budget.hpp"

namespace fdh::verify {

// The command starts now: run_cli calls it first, so that a budget counts the whole run.
void mark_run_start();

// --budget SECONDS (0 < SECONDS <= 10^7) into `budget`; `what` says what it stops.
CLI::Option* add_budget_option(CLI::App& cmd, Budget& budget, const std::string& what);

}  // namespace fdh::verify
