// A plug-in that calls exit() ends a run that has not finished: without this, `fdhcert certify
// --plugin x.so && release` would pass with exit status 0 and no certificate. An atexit handler
// that knows the run is unfinished says so, naming the plug-in (and the call it was in), and ends
// the process with kPluginFailureStatus instead.
#pragma once

#include <string>

namespace fdh::verify::plugin {

// From now until run_finished(), exit() is a plug-in's. `plugin` is named when exit() comes from
// outside any plug-in call (a thread of the plug-in's own, say).
void catch_exit(const std::string& plugin);

// The run is over (normally or by an error fdhcert reports itself): exit() is fdhcert's again.
void run_finished();

}  // namespace fdh::verify::plugin
