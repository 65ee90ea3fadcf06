#include "fdh/check/thread_limit.hpp"

#include <cstddef>
#include <set>

#include "fdh/check/registry.hpp"

namespace fdh::verify {

std::string threads_ignored(int threads) {
  if (threads <= 1 || registry_thread_safe()) return "";
  std::set<std::string> names;  // a plug-in's query and k-DOP methods share its name
  for (const Method& m : all_methods())
    if (m.one_thread) names.insert(m.name);
  for (const BoxMethod& b : all_box_methods())
    if (b.one_thread) names.insert(b.name);
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  return "--threads " + std::to_string(threads) + " is ignored: plug-in " + list +
         " is not declared thread-safe (FDH_PLUGIN_THREAD_SAFE, docs/plugins.md), so the "
         "checks run on one thread";
}

ThreadLimit::ThreadLimit(int threads) {
  if (threads > 0)
    limit_.emplace(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
}

ThreadLimit::ThreadLimit(int threads, std::ostream& err) : ThreadLimit(threads) {
  if (const std::string why = threads_ignored(threads); !why.empty())
    err << "fdhcert: " << why << "\n";
}

}  // namespace fdh::verify
