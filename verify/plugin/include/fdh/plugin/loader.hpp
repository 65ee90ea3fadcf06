// Loading plug-ins (fdh/plugin.h) into the registry: `--plugin lib.so` on classify, fuzz, replay
// and certify. docs/plugins.md has the ABI, the promises and what happens when a plug-in fails.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "fdh/os/budget.hpp"

namespace fdh::verify {

// A plug-in that cannot be used as given: a file that does not load, no fdh_plugin_v1, another
// ABI version, a malformed struct, a name already taken. Exit status 2.
struct PluginLoadError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A plug-in that crashed (in the probe) or answered garbage: which plug-in, which function, on
// which query. Exit status kPluginFailureStatus.
struct PluginFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The exit status of a run that a plug-in ended by crashing or by answering garbage.
inline constexpr int kPluginFailureStatus = 3;

// Loads the plug-in at `path` (a file path, also without a slash: never searched for), adds its
// methods to the registry (registry.hpp add_methods: one query method and one k-DOP method per
// k it builds, all under its name), then probes its functions in a forked child on built-in
// inputs. Throws PluginLoadError, or PluginFailure when the probe failed (the methods stay
// added until the run ends: remove_added_methods).
// From the first load until end_plugin_run, the run is caged (docs/plugins.md): exit() is
// reported as the plug-in's (exit status kPluginFailureStatus), fd 1 is standard error while
// fdhcert's own output (std::cout) goes to the real standard output, and each call has a time
// limit (set_plugin_timeout).
// `settings` go to the plug-in's fdh_plugin_init (fdh/plugin.h) before its entry point, in this
// process and in the probing children; a refusal, settings given to a plug-in without
// fdh_plugin_init, an empty key or a key given twice is a PluginLoadError.
// With `probe_now` false the probe waits for probe_plugins (the command line's --plugin: the
// probe then heeds a --budget given after it).
using PluginSettings = std::vector<std::pair<std::string, std::string>>;
void load_plugin(const std::string& path, const PluginSettings& settings = {},
                 bool probe_now = true);

// Probes the plug-ins loaded with probe_now false, in the order loaded, each cut short once
// `budget` is spent (LoadedPlugin::probe_cut). Throws PluginFailure as load_plugin.
void probe_plugins(const Budget& budget);

// A plug-in loaded in this run: its file as given, its method name, its settings and whether it
// declared itself thread-safe (FDH_PLUGIN_THREAD_SAFE), in the order loaded.
struct LoadedPlugin {
  std::string file, name;
  PluginSettings settings;
  bool thread_safe = false;
  bool probe_cut = false;  // the budget ended its probe, after probe_calls calls
  long probe_calls = 0;
};
std::vector<LoadedPlugin> loaded_plugins();

// The default of --plugin-timeout: seconds one plug-in call may take.
inline constexpr double kDefaultPluginTimeout = 5;

// Each plug-in call's time limit (0: none); a call over it ends the process with
// kPluginFailureStatus, naming plug-in, function and query.
void set_plugin_timeout(double seconds);

// The run is over: standard output back on fd 1, exit() fdhcert's own again.
void end_plugin_run();

// The plug-ins' methods and their cage last for one run: they are forgotten when the scope ends
// (remove_added_methods, end_plugin_run), so that in-process runs (the tests) start with the
// built-in methods only and the default time limit.
struct PluginScope {
  PluginScope();
  PluginScope(const PluginScope&) = delete;
  PluginScope& operator=(const PluginScope&) = delete;
  ~PluginScope();
};

}  // namespace fdh::verify
