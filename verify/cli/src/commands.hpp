// The fdhcert commands and what they share. Private to verify/cli; the public entry point is
// fdh/cli/cli.hpp (run_cli).
//
// The pattern, which every command follows (classify.cpp is the example): a command is one
// file with
//   - a struct of its options, held by a std::shared_ptr that the runner captures (CLI11 binds
//     the options to its fields, so it must outlive the parse);
//   - `Command add_<name>(CLI::App& app)`: adds the subcommand (a one-line description for the
//     command list), binds its options with CLI11 validators for ranges and choices (a bad value
//     is a usage error: exit 2), puts the long explanations in the description and the footer,
//     and returns the runner;
//   - the runner, `int(const Io&)`: calls the library and prints to io.out / io.err (never
//     std::cout), returning the exit status (0, or 1 when a requested check failed). Bad input
//     found while running throws UsageError or InputError (exit 2).
// Tables with fmt, JSON with nlohmann::ordered_json (print_json below), no function longer than
// about 60 lines. run_cli (cli.cpp) adds every command, parses, and runs the one named.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <functional>
#include <nlohmann/json_fwd.hpp>
#include <ostream>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "fdh/check/registry.hpp"
#include "fdh/check/thread_limit.hpp"
#include "fdh/io/usage_error.hpp"  // UsageError, for every command
#include "fdh/os/budget.hpp"
#include "fdh/os/progress_line.hpp"
#include "fdh/plugin/loader.hpp"  // PluginScope: the plug-ins last for one run

namespace fdh::verify {

// Where a command prints.
struct Io {
  std::ostream& out;
  std::ostream& err;
};

// A registered command: its subcommand and what runs it once the command line parsed.
struct Command {
  CLI::App* app = nullptr;
  std::function<int(const Io&)> run;
};

Command add_classify(CLI::App& app);
Command add_fuzz(CLI::App& app);
Command add_replay(CLI::App& app);
Command add_generate(CLI::App& app);
Command add_simulate(CLI::App& app);
Command add_audit(CLI::App& app);

// --- Shared options and checks -------------------------------------------------------------

// --methods LIST: comma-separated method names from the registry, checked by CLI11.
CLI::Option* add_methods_option(CLI::App& cmd, std::vector<std::string>& names,
                                const std::string& help);
// A word from a fixed list (a method, a family, on|off); the error lists the choices.
CLI::Validator one_of(std::vector<std::string> choices);
// A method of the registry, plug-ins' included (checked when parsing ends).
CLI::Validator known_method();
// A k-DOP's k: 6, 14, 18 or 26 (and 0 for "none" when allow_none).
CLI::Validator kdop_k_validator(bool allow_none);
// I/N with 1 <= I <= N <= max (fuzz --shard, audit --part), and the pair it gives once checked.
CLI::Validator i_of_n_validator(long max);
std::pair<int, int> i_of_n(const std::string& s);
// A subcommand with its one-line description and its long footer.
inline CLI::App* add_command(CLI::App& app, const char* name, const char* about,
                             const char* footer) {
  CLI::App* cmd = app.add_subcommand(name, about);
  cmd->footer(footer);
  return cmd;
}
// "[0.001, 1000]": a closed range as the help and the errors write it.
std::string range_text(double lo, double hi);

// A real number in [lo, hi], `shown` as the help and the error write the range ("[2^-52, 1]"):
// NaN, which passes CLI::Range (both of its comparisons are false), and infinities are refused,
// and `2^N` (as the help writes powers of two) is read as the double it names. Apply it with
// ->transform(), so that `2^N` reaches the option as a number.
CLI::Validator real_range(double lo, double hi, const std::string& shown);
// A number in [lo, hi]; outside it (or NaN) is a usage error naming the range.
template <class T>
CLI::Option* add_number_option(CLI::App& cmd, const std::string& name, T& value,
                               const std::string& help, const std::string& type_name, T lo, T hi) {
  CLI::Option* o = cmd.add_option(name, value, help)->type_name(type_name);
  if constexpr (std::is_floating_point_v<T>)
    return o->transform(real_range(double(lo), double(hi), range_text(double(lo), double(hi))));
  else
    return o->check(CLI::Range(lo, hi));
}

// `s` for a message: in quotes, at most about 80 characters (then "..." and its length),
// control bytes and non-ASCII bytes escaped as \xNN.
std::string quoted_input(std::string_view s, std::size_t shown = 80);

// --seed S: 0 to 2^62.
CLI::Option* add_seed_option(CLI::App& cmd, std::uint64_t& seed, const std::string& help);

// Every JSON output: one object, two-space indented, then a newline.
void print_json(std::ostream& os, const nlohmann::ordered_json& j);

// --- How a run runs (run_options.cpp) -------------------------------------------------------

// --quiet and --progress WHEN on a long command, into `when` (--quiet: Never).
CLI::Option* add_quiet_flag(CLI::App& cmd, ProgressWhen& when);
// How progress should show on the command's standard error (fdh/os/progress_line.hpp).
inline ProgressShow progress_wanted(const Io& io, ProgressWhen when) {
  return progress_wanted(io.err, when);
}
// --quiet given: none; else as --progress auto.
inline ProgressShow progress_wanted(const Io& io, bool quiet) {
  return progress_wanted(io.err, quiet ? ProgressWhen::Never : ProgressWhen::Auto);
}

// --threads N in [1, 1024] (default 0: every core) for ThreadLimit; `what` names the loops
// ("the step").
CLI::Option* add_threads_option(CLI::App& cmd, int& threads, const std::string& what);

// --budget SECONDS (0 < SECONDS <= 10^7) into `budget`, counted from run_start() (run_cli marks
// it first); `what` says what it stops.
CLI::Option* add_budget_option(CLI::App& cmd, Budget& budget, const std::string& what);

// --plugin FILE[:SETTINGS], repeatable: loads the plug-in (fdh/plugin/loader.hpp) the moment it
// is parsed, so that --methods and --method, checked when parsing ends, know its methods. A
// plug-in that cannot be loaded, a malformed argument (fdh/plugin/plugin_argument.hpp) or
// refused settings are a UsageError (exit 2); one that fails its probe, a PluginFailure (exit 3).
// Also adds --plugin-timeout SECONDS (fdh/plugin/loader.hpp set_plugin_timeout).
CLI::Option* add_plugin_option(CLI::App& cmd);

}  // namespace fdh::verify
