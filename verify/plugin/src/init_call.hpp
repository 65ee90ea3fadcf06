// A plug-in's optional exports beside its entry point (fdh/plugin.h): fdh_plugin_init, which
// takes the settings of `--plugin FILE:key=value,...`, fdh_plugin_flags and
// fdh_plugin_min_distance (minimum separation). Called the same
// way by the loader and by the child that first loads a plug-in (probe.cpp).
#pragma once

#include <optional>
#include <string>

#include "fdh/plugin.h"
#include "fdh/plugin/loader.hpp"

namespace fdh::verify::plugin {

// Calls fdh_plugin_init of the library `lib` (plug-in `path`) with `settings`, under the crash
// guard. Returns why they were refused (the plug-in's words, or that it exports no
// fdh_plugin_init while settings were given), nullopt when accepted or when there is no init
// function and no setting.
std::optional<std::string> call_init(void* lib, const std::string& path,
                                     const PluginSettings& settings);

// fdh_plugin_flags() of `lib` under the crash guard; 0 when it exports none.
unsigned call_flags(void* lib, const std::string& path);

// fdh_plugin_min_distance() of `lib` under the crash guard, called after the entry point; the
// struct it returns, or null when it exports none (or returned NULL: `exported` tells them apart).
const fdh_min_distance* call_min_distance(void* lib, const std::string& path,
                                          bool* exported = nullptr);

}  // namespace fdh::verify::plugin
