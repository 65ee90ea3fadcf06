// A --plugin argument (FILE[:key=value,key2=value2], docs/plugins.md): the file to load and the
// settings for its fdh_plugin_init (fdh/plugin/loader.hpp load_plugin).
#pragma once

#include <string>

#include "fdh/plugin/loader.hpp"  // PluginSettings

namespace fdh::verify {

struct PluginArgument {
  std::string file;
  PluginSettings settings;
};

// FILE[:key=value,key2=value2]. An argument that names an existing file is that file, whole
// (a path with ':' loads as before). Otherwise the settings start at the first single ':';
// "::" in FILE stands for one ':'. Keys are non-empty, of a-z A-Z 0-9 _ . -, each given once;
// values run to the next ',' (none holds a ','), and may be empty. Throws UsageError
// (fdh/io/usage_error.hpp), naming the argument, for anything else.
PluginArgument parse_plugin_argument(const std::string& arg);

}  // namespace fdh::verify
