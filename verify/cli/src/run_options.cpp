// The options of how a run runs, shared by the long commands: --progress and --quiet (the
// progress line, fdh/os/progress_line.hpp), --threads (fdh/check/thread_limit.hpp), --budget
// (fdh/os/budget.hpp), --plugin and --plugin-timeout (fdh/plugin/).
#include <map>

#include "commands.hpp"
#include "fdh/plugin/plugin_argument.hpp"

namespace fdh::verify {

CLI::Option* add_quiet_flag(CLI::App& cmd, ProgressWhen& when) {
  const std::map<std::string, ProgressWhen> words = {{"auto", ProgressWhen::Auto},
                                                     {"always", ProgressWhen::Always},
                                                     {"never", ProgressWhen::Never}};
  CLI::Option* progress =
      cmd.add_option("--progress", when,
                     "auto (default): a line redrawn in place on a terminal;\n"
                     "off one, a line every few seconds once the run has\n"
                     "taken 10 s. always: lines from the start off a\n"
                     "terminal. never: none")
          ->type_name("WHEN")
          ->transform(CLI::CheckedTransformer(words, CLI::ignore_case).description(""));
  return cmd
      .add_flag_callback(
          "--quiet", [&when] { when = ProgressWhen::Never; }, "no progress (--progress never)")
      ->excludes(progress);
}

CLI::Option* add_threads_option(CLI::App& cmd, int& threads, const std::string& what) {
  return add_number_option(cmd, "--threads", threads,
                           "threads for " + what +
                               " (default: every core); the results\n"
                               "are the same for any number",
                           "N", 1, 1024);
}

CLI::Option* add_budget_option(CLI::App& cmd, Budget& budget, const std::string& what) {
  return cmd
      .add_option_function<double>(
          "--budget",
          [&budget](double seconds) {
            budget = Budget(seconds, run_start());
            set_run_budget(budget);  // the plug-ins' probe, after the command line, heeds it
          },
          "seconds the whole run may take (default: no limit): " + what +
              "\nstop at a clean point once it is spent, the outputs are\n"
              "written whole and say what was cut short. A plug-in call\n"
              "in progress ends first (at most --plugin-timeout)")
      ->type_name("SECONDS")
      ->transform(real_range(1e-3, 1e7, range_text(1e-3, 1e7)));
}

CLI::Option* add_plugin_option(CLI::App& cmd) {
  cmd.add_option_function<double>(
         "--plugin-timeout", [](double seconds) { set_plugin_timeout(seconds); },
         "seconds one plug-in call may take (default 5; 0: no limit).\n"
         "A call over it is abandoned: certify counts a broken promise\n"
         "'no answer in T s' on that query, saves the case and goes\n"
         "on; the other commands end with exit status 3, naming the\n"
         "plug-in, the function and the query (docs/plugins.md).\n"
         "Give it before --plugin to limit loading too")
      ->type_name("SECONDS")
      ->transform(real_range(0.0, 1e6, range_text(0.0, 1e6)))
      ->trigger_on_parse();
  return cmd
      .add_option_function<std::string>(
          "--plugin",
          [](const std::string& arg) {
            const PluginArgument a = parse_plugin_argument(arg);
            try {
              load_plugin(a.file, a.settings, false);  // probed after the command line
            } catch (const PluginLoadError& e) {
              throw UsageError(e.what());
            }
          },
          "load a plug-in: a shared library exporting fdh_plugin_v2\n"
          "(fdh/plugin.h); its methods run like the built-in ones.\n"
          "FILE:key=value,key2=value2 passes settings to its\n"
          "fdh_plugin_init ('::' for a ':' in FILE). Repeatable.\n"
          "A plug-in that crashes, answers garbage or calls exit()\n"
          "ends the run with a message and exit status 3; a hang and a\n"
          "time outside [0, 1] are broken promises in certify\n"
          "(docs/plugins.md)")
      ->type_name("FILE")
      ->trigger_on_parse()
      ->allow_extra_args(false);
}

}  // namespace fdh::verify
