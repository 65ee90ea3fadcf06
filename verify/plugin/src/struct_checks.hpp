// What the loader checks of a plug-in's input and structs before it registers anything: the
// settings, the promises, fdh_plugin_min_distance's struct against the contact functions. Each
// refusal is a PluginLoadError naming the plug-in (loader.cpp, docs/plugins.md).
#pragma once

#include <optional>
#include <string>

#include "fdh/plugin.h"
#include "fdh/plugin/loader.hpp"

namespace fdh::verify::plugin {

[[noreturn]] void refuse(const std::string& path, const std::string& why);

// A method name: a letter or digit, then up to 39 of a-z A-Z 0-9 . _ + -.
bool is_name(const char* s);

// The struct as far as its ABI version has fields (version 1 ends at kdop); another version is
// refused.
fdh_plugin copy_of_version(const fdh_plugin* p, const std::string& path);

// Settings as fdh_plugin_init may take them: keys non-empty and each given once.
void check_settings(const std::string& path, const PluginSettings& settings);

// A promise of the ABI as an int in range (`what` names where it was read), else refused.
void check_promises(const std::string& path, const char* what, int promise, int time_promise);

// fdh_plugin_min_distance's struct, checked: a method answers δ for every decision (and time)
// it answers at contact, or for none, since Method::answers_min_distance is one flag. nullopt
// when the library `lib` does not export it.
std::optional<fdh_min_distance> within_struct(void* lib, const std::string& path,
                                              const fdh_plugin& a);

}  // namespace fdh::verify::plugin
