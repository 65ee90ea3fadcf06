// --plugin FILE[:SETTINGS] and --plugin-timeout SECONDS on classify, fuzz, replay and certify
// (docs/plugins.md).
#pragma once

#include <CLI/CLI.hpp>

#include <string>

#include "fdh/check/registry.hpp"
#include "fdh/plugin/loader.hpp"

namespace fdh::verify {

// --plugin FILE[:SETTINGS], repeatable: loads the plug-in (fdh/plugin/loader.hpp) the moment it
// is parsed, so that --methods and --method, checked when parsing ends, know its methods. A
// plug-in that cannot be loaded, a malformed argument or refused settings are a UsageError
// (exit 2); one that fails its probe, a PluginFailure (exit 3).
// Also adds --plugin-timeout SECONDS (fdh/plugin/loader.hpp set_plugin_timeout).
CLI::Option* add_plugin_option(CLI::App& cmd);

// A --plugin argument read: the file and its settings.
struct PluginArgument {
  std::string file;
  PluginSettings settings;
};

// FILE[:key=value,key2=value2]. An argument that names an existing file is that file, whole
// (a path with ':' loads as before). Otherwise the settings start at the first single ':';
// "::" in FILE stands for one ':'. Keys are non-empty, of a-z A-Z 0-9 _ . -, each given once;
// values run to the next ',' (none holds a ','), and may be empty. Throws UsageError, naming
// the argument, for anything else.
PluginArgument parse_plugin_argument(const std::string& arg);

// The plug-ins' methods and their cage last for one run of run_cli: they are forgotten when it
// returns, so that in-process runs (the tests) start with the built-in methods only and the
// default time limit.
struct PluginScope {
  PluginScope();
  PluginScope(const PluginScope&) = delete;
  PluginScope& operator=(const PluginScope&) = delete;
  ~PluginScope();
};

}  // namespace fdh::verify
