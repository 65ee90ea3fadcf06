#include "fdh/plugin/plugin_argument.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cstring>

#include "fdh/io/input_error.hpp"
#include "fdh/io/usage_error.hpp"

namespace fdh::verify {
namespace {

[[noreturn]] void malformed(const std::string& arg, const std::string& why) {
  throw UsageError("--plugin " + quote(arg) + ": " + why +
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
    if (eq == std::string::npos) malformed(arg, "setting " + quote(item) + " has no '='");
    const std::string key = item.substr(0, eq);
    if (key.empty()) malformed(arg, "setting " + quote(item) + " has an empty key");
    if (!is_key(key)) malformed(arg, "key " + quote(key) + " is not of a-z A-Z 0-9 _ . -");
    for (const auto& [k, v] : settings)
      if (k == key) malformed(arg, "key " + quote(key) + " is given twice");
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

}  // namespace fdh::verify
