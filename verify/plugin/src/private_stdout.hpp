// A plug-in's writes to standard output (printf, write(1, ...)) would land in fdhcert's output:
// `classify --json` would no longer be JSON. While a run has plug-ins loaded, file descriptor 1
// is standard error, and std::cout (fdhcert's own output) writes to a copy of the real standard
// output. No cost per call: nothing is switched around the calls.
#pragma once

namespace fdh::verify::plugin {

// Moves fdhcert's output off fd 1 (once per run; later calls do nothing). Throws
// std::runtime_error when the descriptors cannot be duplicated.
void divert_stdout();

// Puts fd 1 back, after flushing what the plug-ins buffered to standard error.
void restore_stdout();

}  // namespace fdh::verify::plugin
