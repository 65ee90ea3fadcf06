#include "fdh/plugin/loader.hpp"

#include <dlfcn.h>
#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <stdexcept>
#include <vector>

#include "elf_machine.hpp"
#include "exit_catch.hpp"
#include "fdh/check/registry.hpp"
#include "fdh/plugin.h"
#include "guard.hpp"
#include "init_call.hpp"
#include "private_stdout.hpp"
#include "probe.hpp"
#include "struct_checks.hpp"
#include "watchdog.hpp"

namespace fdh::verify {
namespace {

using plugin::CallSite;
using plugin::check_promises;
using plugin::check_settings;
using plugin::copy_of_version;
using plugin::InCall;
using plugin::is_name;
using plugin::refuse;
using plugin::within_struct;

// A loaded plug-in: its struct, copied, its name, settings and flags. The library stays loaded
// for the process (its functions are in the registry until the run ends).
struct Loaded {
  std::string path, name;
  fdh_plugin api{};
  PluginSettings settings;
  unsigned flags = 0;  // FDH_PLUGIN_* bits
  // Its minimum-separation functions (fdh_plugin_min_distance), when it exports them.
  std::optional<fdh_min_distance> within;
  bool one_thread() const { return !(flags & FDH_PLUGIN_THREAD_SAFE); }
};
using LoadedPtr = std::shared_ptr<const Loaded>;

// The files loaded in this run, by device and inode: the same file given twice (by any path) is
// refused as such, not as a taken method name. Cleared when the run ends (end_plugin_run).
std::vector<std::pair<dev_t, ino_t>>& loaded_files() {
  static std::vector<std::pair<dev_t, ino_t>> files;
  return files;
}

// What this run loaded, for loaded_plugins(); cleared with loaded_files().
std::vector<LoadedPlugin>& loaded_list() {
  static std::vector<LoadedPlugin> list;
  return list;
}

// A probe that waits for probe_plugins: the plug-in's methods and its place in loaded_list().
struct PendingProbe {
  std::string name;
  std::vector<Method> methods;
  std::vector<BoxMethod> boxes;
  std::size_t loaded = 0;
};
std::vector<PendingProbe>& pending_probes() {
  static std::vector<PendingProbe> pending;
  return pending;
}

// The entry point: fdh_plugin_v2, else fdh_plugin_v1, and its name.
std::pair<const fdh_plugin* (*)(), const char*> entry_point(void* lib, const std::string& path) {
  for (const char* name : {"fdh_plugin_v2", "fdh_plugin_v1"})
    if (void* f = ::dlsym(lib, name)) return {reinterpret_cast<const fdh_plugin* (*)()>(f), name};
  refuse(path, "exports neither fdh_plugin_v2 nor fdh_plugin_v1 (an fdhcert plug-in must)");
}

// How long a probing child may take: the call limit and then some, for the watchdog in the child
// to speak first; without a call limit, no limit.
double limit_of_child() {
  const double limit = plugin::call_limit();
  return limit > 0 ? std::max(10.0, limit + 5) : 1e9;
}

// The struct the entry point returns, checked field by field, after fdh_plugin_init took the
// settings; `flags` gets fdh_plugin_flags() and `within` fdh_plugin_min_distance's struct.
fdh_plugin entry_struct(const std::string& path, const PluginSettings& settings, unsigned& flags,
                        std::optional<fdh_min_distance>& within) {
  check_settings(path, settings);
  // A file path, never a name for dlopen to search for.
  const std::string file = path.find('/') == std::string::npos ? "./" + path : path;
  // First in a child: a constructor or a cut file that crashes takes the child, not fdhcert.
  if (const std::optional<std::string> why =
          plugin::probe_load(path, file, settings, limit_of_child()))
    refuse(path, "cannot load: " + plugin::not_loaded(file, *why));
  void* lib = nullptr;
  {
    const CallSite loading{path.c_str(), "dlopen (its constructors)"};
    const InCall in(loading);
    lib = ::dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  }
  if (!lib) refuse(path, "cannot load: " + plugin::not_loaded(file, ::dlerror()));
  const auto [entry, entry_name] = entry_point(lib, path);
  if (const std::optional<std::string> why = plugin::call_init(lib, path, settings))
    refuse(path, *why);
  flags = plugin::call_flags(lib, path);
  if (flags & ~(FDH_PLUGIN_THREAD_SAFE | FDH_PLUGIN_TOI_GIVES_VERDICT))
    refuse(path, "fdh_plugin_flags() has bits this fdhcert does not know (FDH_PLUGIN_* only)");
  const CallSite site{path.c_str(), entry_name};
  const fdh_plugin* returned = nullptr;
  {
    const InCall in(site);
    returned = entry();
  }
  if (!returned) refuse(path, std::string(entry_name) + " returned NULL");
  const fdh_plugin a = copy_of_version(returned, path);
  const fdh_plugin* p = &a;
  if (!is_name(p->name))
    refuse(path, "its name is not a letter or digit, then up to 39 of a-z A-Z 0-9 . _ + -");
  check_promises(path, "", p->promise, p->time_promise);
  if ((p->kdop_ks & ~0xfu) || (p->kdop_ks != 0) != (p->kdop != nullptr))
    refuse(path, "kdop_ks must name the k of a kdop builder (FDH_KDOP_* bits), and only then");
  within = within_struct(lib, path, a);
  if (!p->point_triangle && !p->vertex_face_ccd && !p->edge_edge_ccd && !p->kdop &&
      !p->vertex_face_toi && !p->edge_edge_toi && !within)
    refuse(path, "it has no function");
  return a;
}

// `v` in the fewest digits that read back as v.
std::string shortest(double v) {
  // to_chars and from_chars: the C locale's digits whatever LC_NUMERIC says (a Python host).
  char text[40];
  std::size_t n = 0;
  for (int digits = 15; digits <= 17; ++digits) {
    n = std::size_t(
        std::to_chars(text, text + sizeof text, v, std::chars_format::general, digits).ptr - text);
    double r = 0;
    std::from_chars(text, text + n, r);
    if (r == v || std::isnan(v)) break;
  }
  return std::string(text, n);
}

// The ABI's plain rows of three doubles.
using Points8 = double[8][3];
void points_of(const Query& q, Points8& x) {
  for (int i = 0; i < 8; ++i) x[i][0] = q.x[i].x, x[i][1] = q.x[i].y, x[i][2] = q.x[i].z;
}

// A plug-in's verdict: 0 or 1, anything else garbage.
bool verdict(const LoadedPtr& p, const CallSite& site, int r) {
  if (r != 0 && r != 1)
    throw PluginFailure("plug-in " + p->name + " returned " + std::to_string(r) +
                        " (garbage: not 0 or 1) " + plugin::where(site));
  return r == 1;
}

// A call past --plugin-timeout, abandoned (guard.hpp returned_within_limit): no answer on this
// query, which the checker counts as a broken promise.
[[noreturn]] void no_answer(const LoadedPtr& p, const CallSite& site) {
  const double limit = plugin::call_limit();
  throw NoAnswer("plug-in " + p->name + " did not return within " + shortest(limit) +
                     " s (--plugin-timeout) " + plugin::where(site),
                 p->name, limit);
}

// A query with δ > 0 asked of a decision without a δ function: the caller should have seen that
// the method does not apply (Method::applies_to, gives_toi), and no plug-in is to blame.
[[noreturn]] void not_answered(const LoadedPtr& p, const Query& q) {
  throw std::logic_error("plug-in " + p->name + " was asked about min_distance " +
                         shortest(q.min_distance) + ", which it does not answer (n/a)");
}

// One decision's functions: at contact (`contact`) and within δ (`within`); either may be null.
struct Verdicts {
  fdh_query_fn contact = nullptr;
  const char* contact_name = "";
  fdh_min_distance_fn within = nullptr;
  const char* within_name = "";
};

// A decision as a registry test: the 8 points in, 0 or 1 out. At δ = 0 the contact function
// answers, as before δ existed; the δ function answers δ > 0, and δ = 0 where there is no other.
QueryTest query_test(const LoadedPtr& p, const Verdicts& f) {
  return [p, f](const Query& q) {
    Points8 x;
    points_of(q, x);
    const bool at_contact = f.contact && q.min_distance == 0;
    if (!at_contact && !f.within) not_answered(p, q);
    const CallSite site{p->name.c_str(), at_contact ? f.contact_name : f.within_name, &q};
    int r = 0;
    if (!plugin::returned_within_limit(
            site, [&] { r = at_contact ? f.contact(x) : f.within(x, q.min_distance); }))
      no_answer(p, site);
    return verdict(p, site, r);
  };
}

// One decision's times, as Verdicts.
struct Times {
  fdh_toi_fn contact = nullptr;
  const char* contact_name = "";
  fdh_min_distance_toi_fn within = nullptr;
  const char* within_name = "";
};

// A TOI decision as a registry time: 0 or 1 out, and with 1 an interval of [0, 1] in order;
// anything else garbage. Contact and δ as query_test.
QueryToi query_toi(const LoadedPtr& p, const Times& f) {
  return [p, f](const Query& q, double width) {
    Points8 x;
    points_of(q, x);
    const bool at_contact = f.contact && q.min_distance == 0;
    if (!at_contact && !f.within) not_answered(p, q);
    const CallSite site{p->name.c_str(), at_contact ? f.contact_name : f.within_name, &q};
    double lo = 1, hi = 1;
    int r = 0;
    if (!plugin::returned_within_limit(site, [&] {
          r = at_contact ? f.contact(x, width, &lo, &hi)
                         : f.within(x, q.min_distance, width, &lo, &hi);
        }))
      no_answer(p, site);
    if (!verdict(p, site, r)) return Toi{};
    // A time outside [0, 1] goes to the checker as said: a broken promise ("not a time"), on
    // that query, not the end of the run (issue 34); t_hi = +inf is "no upper bound".
    return Toi{true, lo, hi};
  };
}

// The promise a method is held to: the weaker of its contact and δ promises where it has both
// (the ABI's values grow with strength: NONE 0, CONSERVATIVE 1, EXACT 2).
int weaker(bool has_contact, int contact, bool has_within, int within) {
  if (has_contact && has_within) return std::min(contact, within);
  return has_within ? within : contact;
}

// The verdict functions of each query decision, at contact and within δ. A still triangle is a
// moving one that stays: the CCD decides when there is no static test.
std::array<Verdicts, 3> verdicts_of(const fdh_plugin& a, const fdh_min_distance& w) {
  std::array<Verdicts, 3> v;
  v[std::size_t(Decision::PointTriangle)] = {
      a.point_triangle ? a.point_triangle : a.vertex_face_ccd,
      a.point_triangle ? "point_triangle" : "vertex_face_ccd",
      w.point_triangle ? w.point_triangle : w.vertex_face_ccd,
      w.point_triangle ? "point_triangle (min_distance)" : "vertex_face_ccd (min_distance)"};
  v[std::size_t(Decision::VertexFaceCcd)] = {a.vertex_face_ccd, "vertex_face_ccd",
                                             w.vertex_face_ccd, "vertex_face_ccd (min_distance)"};
  v[std::size_t(Decision::EdgeEdgeCcd)] = {a.edge_edge_ccd, "edge_edge_ccd", w.edge_edge_ccd,
                                           "edge_edge_ccd (min_distance)"};
  return v;
}

Method query_method(const LoadedPtr& p) {
  Method m;
  m.name = p->name;
  m.one_thread = p->one_thread();  // docs/plugins.md: one thread unless it says it is safe
  m.verdict_from_toi = p->flags & FDH_PLUGIN_TOI_GIVES_VERDICT;
  m.summary = std::string(p->api.summary ? p->api.summary : "") + " (plug-in " + p->path + ")";
  const fdh_plugin& a = p->api;
  const fdh_min_distance w = p->within.value_or(fdh_min_distance{});
  m.answers_min_distance = p->within.has_value();
  const std::array<Verdicts, 3> verdicts = verdicts_of(a, w);
  for (std::size_t d = 0; d < verdicts.size(); ++d)
    if (verdicts[d].contact || verdicts[d].within) m.test[d] = query_test(p, verdicts[d]);
  const Times times[2] = {
      {a.vertex_face_toi, "vertex_face_toi", w.vertex_face_toi, "vertex_face_toi (min_distance)"},
      {a.edge_edge_toi, "edge_edge_toi", w.edge_edge_toi, "edge_edge_toi (min_distance)"}};
  for (std::size_t d = 0; d < 2; ++d)
    if (times[d].contact || times[d].within) m.toi[d] = query_toi(p, times[d]);
  const int promise = weaker(a.point_triangle || a.vertex_face_ccd || a.edge_edge_ccd, a.promise,
                             w.point_triangle || w.vertex_face_ccd || w.edge_edge_ccd, w.promise);
  const int time_promise = weaker(a.vertex_face_toi || a.edge_edge_toi, a.time_promise,
                                  w.vertex_face_toi || w.edge_edge_toi, w.time_promise);
  m.promise = promise == FDH_PROMISE_EXACT          ? Promise::Exact
              : promise == FDH_PROMISE_CONSERVATIVE ? Promise::Conservative
                                                    : Promise::None;
  m.time_promise = time_promise == FDH_TIME_EXACT_ENCLOSURE ? TimePromise::Enclosure
                   : time_promise == FDH_TIME_NEVER_LATE    ? TimePromise::NeverLate
                                                            : TimePromise::None;
  return m;
}

// The builder for one k; garbage is a slab with NaN or lo > hi.
BoxMethod box_method(const LoadedPtr& p, int k) {
  BoxMethod b;
  b.name = p->name;
  b.one_thread = p->one_thread();
  b.summary = std::string(p->api.summary ? p->api.summary : "") + " (plug-in " + p->path + ")";
  b.k = k;
  b.directions = kdop_directions(k);  // the ABI's order (docs/plugins.md)
  b.promise = Promise::Conservative;
  b.build = [p, k](const Vec3* pts, std::size_t n, double* lo, double* hi) {
    std::vector<double> xyz;  // the ABI's plain rows of three doubles
    xyz.reserve(3 * n);
    for (std::size_t i = 0; i < n; ++i) xyz.insert(xyz.end(), {pts[i].x, pts[i].y, pts[i].z});
    const CallSite site{p->name.c_str(), "kdop", nullptr, k, n};
    const auto* points = reinterpret_cast<const double(*)[3]>(xyz.data());
    if (!plugin::returned_within_limit(site, [&] { p->api.kdop(k, points, n, lo, hi); }))
      no_answer(p, site);
    for (int s = 0; s < k / 2; ++s)
      if (!std::isfinite(lo[s]) || !std::isfinite(hi[s]) || lo[s] > hi[s])
        throw PluginFailure("plug-in " + p->name + " returned slab " + std::to_string(s) + " = [" +
                            shortest(lo[s]) + ", " + shortest(hi[s]) +
                            "] (garbage: not finite, or lo > hi) " + plugin::where(site));
  };
  // Closed slabs, as fdh::overlap: touching counts.
  b.overlap = [k](const double* la, const double* ha, const double* lb, const double* hb) {
    for (int s = 0; s < k / 2; ++s)
      if (ha[s] < lb[s] || hb[s] < la[s]) return false;
    return true;
  };
  return b;
}

}  // namespace

void load_plugin(const std::string& path, const PluginSettings& settings, bool probe_now) {
  plugin::install_crash_handlers();
  plugin::catch_exit(path);
  plugin::divert_stdout();
  struct stat st {};
  const bool known = ::stat(path.c_str(), &st) == 0;  // else dlopen names the reason below
  const std::pair<dev_t, ino_t> id{st.st_dev, st.st_ino};
  auto& files = loaded_files();
  if (known && std::find(files.begin(), files.end(), id) != files.end())
    refuse(path, "given twice: the same file as an earlier --plugin");
  auto loaded = std::make_shared<Loaded>();
  loaded->path = path;
  loaded->settings = settings;
  loaded->api = entry_struct(path, settings, loaded->flags, loaded->within);
  loaded->name = loaded->api.name;
  const LoadedPtr p = loaded;
  std::vector<Method> methods;
  if (p->api.point_triangle || p->api.vertex_face_ccd || p->api.edge_edge_ccd ||
      p->api.vertex_face_toi || p->api.edge_edge_toi || p->within)
    methods.push_back(query_method(p));
  std::vector<BoxMethod> boxes;
  for (int i = 0; i < 4; ++i)
    if (p->api.kdop_ks & (1u << i)) boxes.push_back(box_method(p, kCertifiedK[std::size_t(i)]));
  try {
    add_methods(methods, boxes);  // a taken name is refused before the probe
  } catch (const std::invalid_argument& e) {
    refuse(path, std::string(e.what()) + ": rename the plug-in");
  }
  if (probe_now) plugin::probe(p->name, methods, boxes, limit_of_child());
  if (known) files.push_back(id);
  if (!probe_now) pending_probes().push_back({p->name, methods, boxes, loaded_list().size()});
  loaded_list().push_back({path, p->name, settings, !p->one_thread()});
}

void probe_plugins(const Budget& budget) {
  std::vector<PendingProbe> pending;
  pending.swap(pending_probes());
  for (const PendingProbe& p : pending) {
    const plugin::ProbeCut cut =
        plugin::probe(p.name, p.methods, p.boxes, limit_of_child(), budget);
    loaded_list()[p.loaded].probe_cut = cut.cut;
    loaded_list()[p.loaded].probe_calls = cut.calls;
  }
}

std::vector<LoadedPlugin> loaded_plugins() {
  return loaded_list();
}

void set_plugin_timeout(double seconds) {
  plugin::set_call_limit(seconds);
}

void end_plugin_run() {
  pending_probes().clear();
  loaded_files().clear();
  loaded_list().clear();
  plugin::restore_stdout();
  plugin::run_finished();
}

PluginScope::PluginScope() {
  set_plugin_timeout(kDefaultPluginTimeout);
}

PluginScope::~PluginScope() {
  remove_added_methods();
  end_plugin_run();
}

}  // namespace fdh::verify
