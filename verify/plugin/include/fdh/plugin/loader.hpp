// Loading plug-ins (fdh/plugin.h) into the registry: `--plugin lib.so` on classify, fuzz, replay
// and certify. docs/plugins.md has the ABI, the promises and what happens when a plug-in fails.
#pragma once

#include <stdexcept>
#include <string>

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
void load_plugin(const std::string& path);

}  // namespace fdh::verify
