#include "struct_checks.hpp"

#include <cctype>
#include <cstddef>
#include <cstring>

#include "init_call.hpp"

namespace fdh::verify::plugin {

[[noreturn]] void refuse(const std::string& path, const std::string& why) {
  throw PluginLoadError("plug-in " + path + ": " + why + " (docs/plugins.md)");
}

// A letter or digit, then letters, digits and . _ + -: never a path like "..", since fuzz makes
// folders of method names.
bool is_name(const char* s) {
  if (!s || !std::isalnum(static_cast<unsigned char>(s[0]))) return false;
  std::size_t n = 0;
  for (; s[n]; ++n)
    if (n >= 40 || !(std::isalnum(static_cast<unsigned char>(s[n])) || std::strchr("._+-", s[n])))
      return false;
  return n > 0;
}

// The struct as far as its version has fields: a version-1 struct ends at kdop, so nothing
// beyond is read (the version-2 fields stay zero: no time of impact).
fdh_plugin copy_of_version(const fdh_plugin* p, const std::string& path) {
  fdh_plugin api{};
  if (p->abi_version == FDH_PLUGIN_ABI_VERSION)
    api = *p;
  else if (p->abi_version == FDH_PLUGIN_ABI_VERSION_1)
    std::memcpy(static_cast<void*>(&api), p, offsetof(fdh_plugin, time_promise));
  else
    refuse(path, "ABI version " + std::to_string(p->abi_version) + ", but this fdhcert takes " +
                     std::to_string(FDH_PLUGIN_ABI_VERSION_1) + " or " +
                     std::to_string(FDH_PLUGIN_ABI_VERSION));
  return api;
}

void check_settings(const std::string& path, const PluginSettings& settings) {
  for (std::size_t i = 0; i < settings.size(); ++i) {
    if (settings[i].first.empty()) refuse(path, "a setting has an empty key");
    for (std::size_t j = 0; j < i; ++j)
      if (settings[j].first == settings[i].first)
        refuse(path, "setting '" + settings[i].first + "' is given twice");
  }
}

void check_promises(const std::string& path, const char* what, int promise, int time_promise) {
  if (promise < FDH_PROMISE_NONE || promise > FDH_PROMISE_EXACT)
    refuse(path, std::string(what) + "promise " + std::to_string(promise) + " is none of 0, 1, 2");
  if (time_promise < FDH_TIME_NONE || time_promise > FDH_TIME_EXACT_ENCLOSURE)
    refuse(path, std::string(what) + "time_promise " + std::to_string(time_promise) +
                     " is none of 0, 1, 2");
}

std::optional<fdh_min_distance> within_struct(void* lib, const std::string& path,
                                              const fdh_plugin& a) {
  bool exported = false;
  const fdh_min_distance* returned = call_min_distance(lib, path, &exported);
  if (!exported) return std::nullopt;
  if (!returned) refuse(path, "fdh_plugin_min_distance returned NULL");
  const fdh_min_distance w = *returned;
  check_promises(path, "fdh_plugin_min_distance's ", w.promise, w.time_promise);
  const auto missing = [&](bool at_contact, bool within, const char* function) {
    if (at_contact && !within)
      refuse(path, std::string("fdh_plugin_min_distance gives no ") + function +
                       ", which the plug-in answers at contact (a plug-in answers the minimum "
                       "separation for every decision it makes, or for none)");
  };
  missing(a.point_triangle && !a.vertex_face_ccd, w.point_triangle || w.vertex_face_ccd,
          "point_triangle");
  missing(a.vertex_face_ccd, w.vertex_face_ccd, "vertex_face_ccd");
  missing(a.edge_edge_ccd, w.edge_edge_ccd, "edge_edge_ccd");
  missing(a.vertex_face_toi, w.vertex_face_toi, "vertex_face_toi");
  missing(a.edge_edge_toi, w.edge_edge_toi, "edge_edge_toi");
  if (!w.point_triangle && !w.vertex_face_ccd && !w.edge_edge_ccd && !w.vertex_face_toi &&
      !w.edge_edge_toi)
    refuse(path, "fdh_plugin_min_distance gives no function");
  return w;
}

}  // namespace fdh::verify::plugin
