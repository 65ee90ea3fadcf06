#include "progress.hpp"

#include <map>

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

}  // namespace fdh::verify
