#include "init_call.hpp"

#include <dlfcn.h>

#include <vector>

#include "fdh/io/input_error.hpp"
#include "fdh/plugin.h"
#include "guard.hpp"

namespace fdh::verify::plugin {

std::optional<std::string> call_init(void* lib, const std::string& path,
                                     const PluginSettings& settings) {
  const auto init = reinterpret_cast<fdh_plugin_init_fn>(::dlsym(lib, "fdh_plugin_init"));
  if (!init) {
    if (settings.empty()) return std::nullopt;
    return "it takes no settings (it exports no fdh_plugin_init), but " + settings.front().first +
           "=... was given";
  }
  std::vector<const char*> keys, values;
  for (const auto& [key, value] : settings)
    keys.push_back(key.c_str()), values.push_back(value.c_str());
  const CallSite site{path.c_str(), "fdh_plugin_init"};
  std::optional<std::string> refused;
  {
    const InCall in(site);  // reading its words may crash too
    if (const char* why = init(settings.size(), keys.data(), values.data())) refused = why;
  }
  if (!refused) return std::nullopt;
  // Its words quoted as any input is (docs/limits.md): no raw control byte reaches the terminal.
  return "fdh_plugin_init refused its settings: " + quote(*refused, 200);
}

unsigned call_flags(void* lib, const std::string& path) {
  const auto flags = reinterpret_cast<fdh_plugin_flags_fn>(::dlsym(lib, "fdh_plugin_flags"));
  if (!flags) return 0;
  const CallSite site{path.c_str(), "fdh_plugin_flags"};
  const InCall in(site);
  return flags();
}

const fdh_min_distance* call_min_distance(void* lib, const std::string& path, bool* exported) {
  const auto entry =
      reinterpret_cast<fdh_plugin_min_distance_fn>(::dlsym(lib, "fdh_plugin_min_distance"));
  if (exported) *exported = entry != nullptr;
  if (!entry) return nullptr;
  const CallSite site{path.c_str(), "fdh_plugin_min_distance"};
  const InCall in(site);
  return entry();
}

}  // namespace fdh::verify::plugin
