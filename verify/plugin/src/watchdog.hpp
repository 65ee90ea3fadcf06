// A time limit on each plug-in call (--plugin-timeout, docs/plugins.md): a thread that wakes a
// few times a second and ends the process with kPluginFailureStatus when a call it saw running
// is still the same call after the limit, naming plug-in, function and query. Arming a call is
// two stores into the calling thread's slot, no clock read and no system call, so that the
// limit costs nothing measurable per query (docs/plugins.md has the measurement).
#pragma once

#include "guard.hpp"

namespace fdh::verify::plugin {

// The limit in seconds; 0 or less: none. Read by the watchdog at each wake-up.
void set_call_limit(double seconds);
double call_limit();

// The calling thread enters `site` (the outermost plug-in call) / leaves it. The first entry in
// a process (also in a forked child) starts the watchdog.
void watch_begin(const CallSite* site);
void watch_end();

}  // namespace fdh::verify::plugin
