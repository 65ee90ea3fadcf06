// --plugin FILE and --plugin-timeout SECONDS on classify, fuzz, replay and certify
// (docs/plugins.md).
#pragma once

#include <CLI/CLI.hpp>

#include "fdh/check/registry.hpp"

namespace fdh::verify {

// --plugin FILE, repeatable: loads the plug-in (fdh/plugin/loader.hpp) the moment it is parsed,
// so that --methods and --method, checked when parsing ends, know its methods. A plug-in that
// cannot be loaded is a UsageError (exit 2); one that fails its probe, a PluginFailure (exit 3).
// Also adds --plugin-timeout SECONDS (fdh/plugin/loader.hpp set_plugin_timeout).
CLI::Option* add_plugin_option(CLI::App& cmd);

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
