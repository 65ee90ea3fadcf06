#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>

#include "fdh/cli/cli.hpp"
#include "fdh/os/last_resort.hpp"
#include "fdh/os/temporaries.hpp"

namespace {

// Standard output is checked once more as the process ends: what std::cout held, then the C
// stream and its close. A full disk or a closed stdout is exit 2, never 0.
int checked_stdout(int status) {
  errno = 0;
  std::cout.flush();
  bool ok = bool(std::cout) && std::fflush(stdout) == 0 && !std::ferror(stdout);
  int why = errno;
  if (std::fclose(stdout) != 0 && ok) {
    ok = false;
    why = errno;
  }
  if (!ok) {
    if (status != 2)  // run_cli has not said so already
      std::cerr << "fdhcert: error: standard output: "
                << (why ? std::strerror(why) : "cannot write") << "\n";
    status = 2;
  }
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  // An exception nobody handles is an internal error (exit 3), never an abort; SIGTERM and
  // SIGINT remove the run's temporaries first (docs/limits.md).
  fdh::verify::end_with_internal_error_on_terminate();
  fdh::verify::remove_temporaries_on_signals();
  int status = 0;
  try {
    status =
        fdh::verify::run_cli(std::vector<std::string>(argv + 1, argv + argc), std::cout, std::cerr);
  } catch (const std::exception& e) {
    fdh::verify::end_with_internal_error(e.what());
  } catch (...) {
    fdh::verify::end_with_internal_error("an exception of unknown type");
  }
  return checked_stdout(status);
}
