// Calling into a plug-in: while one of its functions runs, the process knows which plug-in,
// function and query it is, so that a crash (SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT) prints
//   fdhcert: plug-in NAME crashed (SIGSEGV) in FUNCTION on query FILE:LINE
// and ends the process with kPluginFailureStatus instead of dying without a word. Outside a
// plug-in call the handlers hand the signal back to whatever handled it before.
#pragma once

#include <pthread.h>
#include <setjmp.h>

#include <cstddef>
#include <string>

#include "fdh/query.hpp"

namespace fdh::verify::plugin {

// One call into a plug-in: what a message about it names.
struct CallSite {
  const char* plugin = "";       // the plug-in's name
  const char* function = "";     // "point_triangle", "vertex_face_ccd", ..., "kdop"
  const Query* query = nullptr;  // the query asked, for the query functions (its record:
                                 // fdh/io/record_scope.hpp)
  int k = 0;                     // the k-DOP's k and
  std::size_t points = 0;        // its number of points, for kdop
};

// "in vertex_face_ccd on query FILE:LINE" (or on query 'ID' for a generated query; "in kdop (k =
// 18) on 8 points"): the words of every message about a call.
std::string where(const CallSite& site);

// Installs the crash handlers (once; later calls do nothing) and an alternate signal stack, so
// that a plug-in's stack overflow is reported too.
void install_crash_handlers();

// Asks `thread`, stuck in a plug-in call for `limit` seconds, to report the call and end the
// process (a signal whose handler runs on that thread: the query's FILE:LINE is known only
// there). Returns; the process normally ends soon after.
void report_time_out(pthread_t thread, double limit);

// Where a crash, a time-out or an exit() is reported: standard error (2) unless a probing child
// says otherwise.
void set_crash_report_fd(int fd);
int report_fd();

// The plug-in call the calling thread is in, or null.
const CallSite* current_call();

// Where the calling thread's time-out signal jumps to (null: it reports and ends the process).
sigjmp_buf*& escape_point();

// Marks the calling thread as inside `site` for the object's lifetime, and arms the call's time
// limit (watchdog.hpp).
class InCall {
 public:
  explicit InCall(const CallSite& site);
  ~InCall();
  InCall(const InCall&) = delete;
  InCall& operator=(const InCall&) = delete;

 private:
  const CallSite* outer_;
};

// Calls `call` (the plug-in's function, through a lambda that holds no C++ object of its own) as
// the call `site`. Returns false when it did not return within --plugin-timeout: its thread left
// it by siglongjmp from the time-out's signal, abandoning its frames where they were (the
// plug-in's state is then its own affair: docs/plugins.md). No object with a destructor lives
// between here and the jump.
template <class Call>
bool returned_within_limit(const CallSite& site, const Call& call) {
  const InCall in(site);
  sigjmp_buf here;
  sigjmp_buf* const outer = escape_point();
  if (sigsetjmp(here, 1) != 0) {
    escape_point() = outer;
    return false;
  }
  escape_point() = &here;
  call();
  escape_point() = outer;
  return true;
}

}  // namespace fdh::verify::plugin
