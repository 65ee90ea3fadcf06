#include "plugin_option.hpp"

#include <sys/stat.h>

#include <cctype>
#include <cstring>

#include "commands.hpp"
#include "fdh/plugin/loader.hpp"

namespace fdh::verify {
namespace {

[[noreturn]] void malformed(const std::string& arg, const std::string& why) {
  throw UsageError("--plugin " + quoted_input(arg) + ": " + why +
                   " (FILE:key=value,key2=value2; a ':' in FILE is written '::'; "
                   "docs/plugins.md)");
}

bool is_key(const std::string& key) {
  if (key.empty()) return false;
  for (const char c : key)
    if (!std::isalnum(static_cast<unsigned char>(c)) && !std::strchr("_.-", c)) return false;
  return true;
}

// "key=value,key2=value2" into pairs, in order.
PluginSettings settings_of(const std::string& arg, const std::string& text) {
  PluginSettings settings;
  std::size_t begin = 0;
  for (;;) {
    const std::size_t end = std::min(text.find(',', begin), text.size());
    const std::string item = text.substr(begin, end - begin);
    const std::size_t eq = item.find('=');
    if (item.empty()) malformed(arg, "an empty setting (two ',' in a row, or one at an end)");
    if (eq == std::string::npos) malformed(arg, "setting " + quoted_input(item) + " has no '='");
    const std::string key = item.substr(0, eq);
    if (key.empty()) malformed(arg, "setting " + quoted_input(item) + " has an empty key");
    if (!is_key(key)) malformed(arg, "key " + quoted_input(key) + " is not of a-z A-Z 0-9 _ . -");
    for (const auto& [k, v] : settings)
      if (k == key) malformed(arg, "key " + quoted_input(key) + " is given twice");
    settings.emplace_back(key, item.substr(eq + 1));
    if (end == text.size()) return settings;
    begin = end + 1;
  }
}

}  // namespace

PluginArgument parse_plugin_argument(const std::string& arg) {
  struct stat st {};
  if (::stat(arg.c_str(), &st) == 0 && !S_ISDIR(st.st_mode)) return {arg, {}};
  PluginArgument a;
  std::size_t i = 0;
  for (; i < arg.size(); ++i) {
    if (arg[i] != ':') {
      a.file += arg[i];
    } else if (i + 1 < arg.size() && arg[i + 1] == ':') {
      a.file += ':', ++i;  // "::": a ':' of the path
    } else {
      break;
    }
  }
  if (a.file.empty()) malformed(arg, "no file before the settings");
  if (i == arg.size()) return a;
  if (i + 1 == arg.size()) malformed(arg, "no settings after ':'");
  a.settings = settings_of(arg, arg.substr(i + 1));
  return a;
}

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

PluginScope::PluginScope() {
  set_plugin_timeout(kDefaultPluginTimeout);
}

PluginScope::~PluginScope() {
  remove_added_methods();
  end_plugin_run();
}

}  // namespace fdh::verify
