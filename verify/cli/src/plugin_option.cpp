#include "plugin_option.hpp"

#include "commands.hpp"
#include "fdh/plugin/loader.hpp"
#include "fdh/plugin/plugin_argument.hpp"

namespace fdh::verify {

CLI::Option* add_plugin_option(CLI::App& cmd) {
  cmd.add_option_function<double>(
         "--plugin-timeout", [](double seconds) { set_plugin_timeout(seconds); },
         "seconds one plug-in call may take (default 5; 0: no limit).\n"
         "A call over it ends the run with exit status 3, naming the\n"
         "plug-in, the function and the query (docs/plugins.md).\n"
         "Give it before --plugin to limit loading too")
      ->type_name("SECONDS")
      ->check(CLI::Range(0.0, 1e6))
      ->trigger_on_parse();
  return cmd
      .add_option_function<std::string>(
          "--plugin",
          [](const std::string& arg) {
            const PluginArgument a = parse_plugin_argument(arg);
            try {
              load_plugin(a.file, a.settings);
            } catch (const PluginLoadError& e) {
              throw UsageError(e.what());
            }
          },
          "load a plug-in: a shared library exporting fdh_plugin_v2\n"
          "(fdh/plugin.h); its methods run like the built-in ones.\n"
          "FILE:key=value,key2=value2 passes settings to its\n"
          "fdh_plugin_init ('::' for a ':' in FILE). Repeatable.\n"
          "A plug-in that crashes, answers garbage, calls exit() or\n"
          "hangs ends the run with a message and exit status 3\n"
          "(docs/plugins.md)")
      ->type_name("FILE")
      ->trigger_on_parse()
      ->allow_extra_args(false);
}

}  // namespace fdh::verify
