#include "exit_catch.hpp"

#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <mutex>

#include "fdh/os/atomic_file.hpp"
#include "fdh/plugin/loader.hpp"
#include "guard.hpp"

namespace fdh::verify::plugin {
namespace {

std::atomic<bool> g_unfinished{false};
std::mutex g_names_lock;
std::string g_names;  // the loaded plug-ins, "a, b"

void on_exit() {
  if (!g_unfinished.load()) return;
  std::string text = "fdhcert: ";
  if (const CallSite* site = current_call())
    text += std::string("plug-in ") + site->plugin + " called exit() " + where(*site);
  else {
    const std::lock_guard<std::mutex> lock(g_names_lock);
    text += "exit() was called outside fdhcert's calls while plug-in " + g_names + " was loaded";
  }
  text += " before the run finished\n";
  write_all(report_fd(), text);
  ::_exit(kPluginFailureStatus);
}

}  // namespace

void catch_exit(const std::string& plugin) {
  static const int registered = std::atexit(&on_exit);
  (void)registered;
  {
    const std::lock_guard<std::mutex> lock(g_names_lock);
    g_names += (g_names.empty() ? "" : ", ") + plugin;
  }
  g_unfinished.store(true);
}

void run_finished() {
  g_unfinished.store(false);
  const std::lock_guard<std::mutex> lock(g_names_lock);
  g_names.clear();
}

}  // namespace fdh::verify::plugin
