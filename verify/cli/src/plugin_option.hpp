// --plugin FILE[:SETTINGS] and --plugin-timeout SECONDS on classify, fuzz, replay and certify
// (docs/plugins.md).
#pragma once

#include <CLI/CLI.hpp>

#include "fdh/plugin/loader.hpp"  // PluginScope: the plug-ins last for one run

namespace fdh::verify {

// --plugin FILE[:SETTINGS], repeatable: loads the plug-in (fdh/plugin/loader.hpp) the moment it
// is parsed, so that --methods and --method, checked when parsing ends, know its methods. A
// plug-in that cannot be loaded, a malformed argument (fdh/plugin/plugin_argument.hpp) or
// refused settings are a UsageError (exit 2); one that fails its probe, a PluginFailure (exit 3).
// Also adds --plugin-timeout SECONDS (fdh/plugin/loader.hpp set_plugin_timeout).
CLI::Option* add_plugin_option(CLI::App& cmd);

}  // namespace fdh::verify
