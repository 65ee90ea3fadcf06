#include "plugin_option.hpp"

#include "commands.hpp"
#include "fdh/plugin/loader.hpp"

namespace fdh::verify {

CLI::Option* add_plugin_option(CLI::App& cmd) {
  return cmd
      .add_option_function<std::string>(
          "--plugin",
          [](const std::string& path) {
            try {
              load_plugin(path);
            } catch (const PluginLoadError& e) {
              throw UsageError(e.what());
            }
          },
          "load a plug-in: a shared library exporting fdh_plugin_v1\n"
          "(fdh/plugin.h); its methods run like the built-in ones.\n"
          "Repeatable. A plug-in that crashes or answers garbage ends\n"
          "the run with a message and exit status 3 (docs/plugins.md)")
      ->type_name("FILE")
      ->trigger_on_parse()
      ->allow_extra_args(false);
}

}  // namespace fdh::verify
