// Probing a plug-in before a run: its functions on a few built-in inputs, in a forked child, so
// that a plug-in that crashes, answers garbage or hangs on ordinary input is refused before any
// work starts, with the words of the call that failed.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "fdh/check/registry.hpp"
#include "fdh/os/budget.hpp"
#include "fdh/plugin/loader.hpp"

namespace fdh::verify::plugin {

// How far a probe got when the run's budget ended it: cut, after `calls` calls.
struct ProbeCut {
  bool cut = false;
  long calls = 0;
};

// Runs every query test of `methods` and every builder of `boxes` on the built-in inputs in a
// child process. Throws PluginFailure saying what went wrong when the child crashed, answered
// garbage, ended early or went `seconds` without finishing a call. Once `budget` is spent the
// child is stopped and the probe is cut short (docs/plugins.md, "Slow plug-ins").
ProbeCut probe(const std::string& plugin, const std::vector<Method>& methods,
               const std::vector<BoxMethod>& boxes, double seconds = 10, const Budget& budget = {});

// Loads `file` (plug-in `path`) in a child and calls its fdh_plugin_init with `settings` (if it
// has one), its fdh_plugin_flags and its entry point, so that a constructor or a
// cut file that crashes, hangs or calls exit() is a PluginLoadError ("plug-in PATH: cannot load:
// crashed (SIGSEGV) in dlopen (its constructors)") and fdhcert lives on to say it. Returns
// dlerror's words when dlopen failed in the child, nullopt when it loaded.
std::optional<std::string> probe_load(const std::string& path, const std::string& file,
                                      const PluginSettings& settings, double seconds);

}  // namespace fdh::verify::plugin
