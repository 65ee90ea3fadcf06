#include "watchdog.hpp"

#include <pthread.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <mutex>
#include <string>
#include <thread>

#include "fdh/os/atomic_file.hpp"
#include "fdh/plugin/loader.hpp"

namespace fdh::verify::plugin {
namespace {

using Clock = std::chrono::steady_clock;

// One per thread that calls plug-ins: `seq` is odd while a call runs and changes with each call,
// so the watchdog tells a call that hangs from many short ones without reading a clock per call.
struct Slot {
  std::atomic<bool> taken{false};
  std::atomic<std::uint64_t> seq{0};
  std::atomic<const CallSite*> site{nullptr};
  pthread_t thread{};
};
constexpr std::size_t kSlots = 256;  // more threads than this go unwatched
std::array<Slot, kSlots> g_slots;

std::atomic<double> g_limit{kDefaultPluginTimeout};
std::atomic<bool> g_running{false};  // in this process: a fork's child starts its own
std::mutex g_start;

struct ThreadSlot {
  Slot* slot = nullptr;
  ThreadSlot() {
    for (Slot& s : g_slots)
      if (bool free = false; s.taken.compare_exchange_strong(free, true)) {
        slot = &s;
        s.thread = ::pthread_self();
        break;
      }
  }
  ~ThreadSlot() {
    if (!slot) return;
    slot->site.store(nullptr);
    slot->taken.store(false);
  }
};
thread_local ThreadSlot t_slot;

// A child of fork has only the thread that forked: the others' calls are not running there.
void after_fork_in_child() {
  g_running.store(false);
  for (Slot& s : g_slots)
    if (&s != t_slot.slot) {
      s.site.store(nullptr);
      s.seq.store(s.seq.load() & ~std::uint64_t(1));
      s.taken.store(false);
    }
}

// The stuck thread reports itself (guard.cpp: it knows the query's FILE:LINE); if it has the
// signal blocked and is still stuck a second later, the watchdog says what it knows.
void time_out(Slot& slot, std::uint64_t seq, double limit) {
  report_time_out(slot.thread, limit);
  std::this_thread::sleep_for(std::chrono::seconds(1));
  const CallSite* site = slot.site.load(std::memory_order_acquire);
  if (!site || slot.seq.load(std::memory_order_acquire) != seq) return;
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%g", limit);
  const std::string text = std::string("fdhcert: plug-in ") + site->plugin +
                           " did not return within " + seconds + " s (--plugin-timeout) " +
                           where(*site) + "\n";
  write_all(report_fd(), text);
  ::_exit(kPluginFailureStatus);
}

// Wakes every 1/20 of the limit (10 ms .. 250 ms): a hang ends within the limit plus two wakes.
[[noreturn]] void watch() {
  std::array<std::uint64_t, kSlots> seen{};
  std::array<Clock::time_point, kSlots> since{};
  for (;;) {
    const double limit = g_limit.load();
    const double wake = std::clamp(limit / 20, 0.01, 0.25);
    std::this_thread::sleep_for(std::chrono::duration<double>(limit > 0 ? wake : 0.25));
    if (limit <= 0) continue;
    const Clock::time_point now = Clock::now();
    for (std::size_t i = 0; i < kSlots; ++i) {
      const std::uint64_t seq = g_slots[i].seq.load(std::memory_order_acquire);
      if (!(seq & 1) || !g_slots[i].taken.load()) continue;
      if (seq != seen[i]) {
        seen[i] = seq, since[i] = now;
        continue;
      }
      if (std::chrono::duration<double>(now - since[i]).count() < limit) continue;
      time_out(g_slots[i], seq, limit);
    }
  }
}

void start_watchdog() {
  const std::lock_guard<std::mutex> lock(g_start);
  if (g_running.load()) return;
  static const int registered = ::pthread_atfork(nullptr, nullptr, &after_fork_in_child);
  (void)registered;
  std::thread(&watch).detach();
  g_running.store(true);
}

}  // namespace

void set_call_limit(double seconds) {
  g_limit.store(seconds);
}

double call_limit() {
  return g_limit.load();
}

void watch_begin(const CallSite* site) {
  if (!g_running.load(std::memory_order_relaxed)) start_watchdog();
  Slot* s = t_slot.slot;
  if (!s) return;
  s->site.store(site, std::memory_order_relaxed);
  // Only this thread writes its seq: a load and a store, no locked instruction.
  s->seq.store(s->seq.load(std::memory_order_relaxed) + 1, std::memory_order_release);
}

void watch_end() {
  Slot* s = t_slot.slot;
  if (!s) return;
  s->seq.store(s->seq.load(std::memory_order_relaxed) + 1, std::memory_order_release);
}

}  // namespace fdh::verify::plugin
