#include "guard.hpp"

#include <signal.h>
#include <unistd.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>

#include "fdh/io/record_scope.hpp"
#include "fdh/plugin/loader.hpp"
#include "watchdog.hpp"

namespace fdh::verify::plugin {
namespace {

thread_local const CallSite* t_site = nullptr;
thread_local sigjmp_buf* t_escape = nullptr;
volatile sig_atomic_t g_report_fd = 2;

constexpr std::array<int, 5> kSignals = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT};
std::array<struct sigaction, kSignals.size()> g_previous;

const char* signal_name(int sig) {
  switch (sig) {
    case SIGSEGV:
      return "SIGSEGV";
    case SIGBUS:
      return "SIGBUS";
    case SIGFPE:
      return "SIGFPE";
    case SIGILL:
      return "SIGILL";
    case SIGABRT:
      return "SIGABRT";
  }
  return "a signal";
}

constexpr const char* kHexDigits[16] = {"0", "1", "2", "3", "4", "5", "6", "7",
                                        "8", "9", "a", "b", "c", "d", "e", "f"};

// A message built inside a signal handler: no allocation, only write(2) at the end.
class SignalText {
 public:
  SignalText& operator<<(const char* s) {
    while (*s && n_ < sizeof buf_) buf_[n_++] = *s++;
    return *this;
  }
  SignalText& operator<<(unsigned long v) {
    char digits[24];
    int d = 0;
    do digits[d++] = char('0' + v % 10), v /= 10;
    while (v);
    while (d > 0 && n_ < sizeof buf_) buf_[n_++] = digits[--d];
    return *this;
  }
  // v in C99 hex-float ("-0x1.8p+3"), exactly, as the native query format reads it.
  SignalText& hex(double v) {
    std::uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    if (bits >> 63) *this << "-";
    const int biased = int((bits >> 52) & 0x7ff);
    std::uint64_t mantissa = bits & ((std::uint64_t(1) << 52) - 1);
    if (biased == 0x7ff) return *this << (mantissa ? "nan" : "inf");
    *this << (biased ? "0x1" : "0x0");
    if (mantissa) {
      *this << ".";
      for (int shift = 48; mantissa; shift -= 4) {  // 13 digits, the trailing zeros left out
        *this << kHexDigits[(mantissa >> shift) & 0xf];
        mantissa &= (std::uint64_t(1) << shift) - 1;
      }
    }
    const int exponent = biased ? biased - 1023 : (bits << 1 ? -1022 : 0);
    *this << (exponent < 0 ? "p-" : "p+") << (unsigned long)(exponent < 0 ? -exponent : exponent);
    return *this;
  }
  std::string str() const { return std::string(buf_, n_); }
  void write_to(int fd) const {
    for (std::size_t done = 0; done < n_;) {
      const ssize_t w = ::write(fd, buf_ + done, n_ - done);
      if (w <= 0) return;
      done += std::size_t(w);
    }
  }

 private:
  char buf_[1024];
  std::size_t n_ = 0;
};

// where()'s words, without allocating: the handler says them too. The query is named after the
// record it was asked for (fdh/io/record_scope.hpp).
void add_where(SignalText& t, const CallSite& s) {
  t << "in " << s.function;
  const QueryRecord* r = s.query ? record_of(*s.query) : nullptr;
  if (r && !r->file.empty())
    t << " on query " << r->file.c_str() << ":" << (unsigned long)(r->line);
  else if (s.query) {  // a generated query: the line of a query file that asks it again
    const char* kind = s.query->kind == QueryKind::EdgeEdge ? "ee " : "vf ";
    const char* id = r && !r->id.empty() ? r->id.c_str() : "unnamed";
    t << " on query '" << id << "': " << kind << id;
    for (const Vec3& p : s.query->x) {
      t << " ";
      t.hex(p.x) << " ";
      t.hex(p.y) << " ";
      t.hex(p.z);
    }
  } else if (s.points)
    t << " (k = " << (unsigned long)(s.k) << ") on " << (unsigned long)(s.points) << " points";
}

// The time-out's signal: one of the real-time ones, which nothing else here uses.
int time_out_signal() {
  return SIGRTMIN + 5;
}
char g_limit_text[32];  // "1.5", written before the signal is sent

void on_time_out(int) {
  const CallSite* site = t_site;
  if (!site) return;  // the call ended meanwhile
  // A query's call is abandoned and the run goes on (the caller reports "no answer in T s").
  if (sigjmp_buf* escape = t_escape) ::siglongjmp(*escape, 1);
  SignalText t;
  t << "fdhcert: plug-in " << site->plugin << " did not return within " << g_limit_text
    << " s (--plugin-timeout) ";
  add_where(t, *site);
  t << "\n";
  t.write_to(g_report_fd);
  ::_exit(kPluginFailureStatus);
}

void on_crash(int sig) {
  const CallSite* site = t_site;
  if (!site) {  // not ours: the previous handler (or the default) takes it once we return
    for (std::size_t i = 0; i < kSignals.size(); ++i)
      if (kSignals[i] == sig) ::sigaction(sig, &g_previous[i], nullptr);
    ::raise(sig);
    return;
  }
  SignalText t;
  t << "fdhcert: plug-in " << site->plugin << " crashed (" << signal_name(sig) << ") ";
  add_where(t, *site);
  t << "\n";
  t.write_to(g_report_fd);
  ::_exit(kPluginFailureStatus);
}

// The handler's own stack: a plug-in that overflowed its stack is still reported.
void use_alternate_stack() {
  stack_t current;
  if (::sigaltstack(nullptr, &current) == 0 && !(current.ss_flags & SS_DISABLE)) return;
  static char memory[1 << 16];
  stack_t s{};
  s.ss_sp = memory;
  s.ss_size = sizeof memory;
  ::sigaltstack(&s, nullptr);
}

}  // namespace

std::string where(const CallSite& s) {
  SignalText t;
  add_where(t, s);
  return t.str();
}

void install_crash_handlers() {
  static bool installed = false;
  if (installed) return;
  installed = true;
  use_alternate_stack();
  struct sigaction a {};
  a.sa_handler = &on_crash;
  a.sa_flags = SA_ONSTACK;
  sigemptyset(&a.sa_mask);
  for (std::size_t i = 0; i < kSignals.size(); ++i) ::sigaction(kSignals[i], &a, &g_previous[i]);
  a.sa_handler = &on_time_out;
  ::sigaction(time_out_signal(), &a, nullptr);
}

void report_time_out(pthread_t thread, double limit) {
  std::snprintf(g_limit_text, sizeof g_limit_text, "%g", limit);
  ::pthread_kill(thread, time_out_signal());
}

void set_crash_report_fd(int fd) {
  g_report_fd = fd;
}

int report_fd() {
  return g_report_fd;
}

sigjmp_buf*& escape_point() {
  return t_escape;
}

const CallSite* current_call() {
  return t_site;
}

InCall::InCall(const CallSite& site) : outer_(t_site) {
  t_site = &site;
  if (!outer_) watch_begin(&site);
}

InCall::~InCall() {
  if (!outer_) watch_end();
  t_site = outer_;
}

}  // namespace fdh::verify::plugin
