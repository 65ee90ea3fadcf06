#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>

#include "fdh/cli/cli.hpp"
#include "fdh/os/temporaries.hpp"

namespace {

// The status of an error fdhcert did not foresee (docs/limits.md).
constexpr int kInternalErrorStatus = 3;

// The last resort: an exception nothing caught (in main or another thread) is an internal
// error, never an abort; this run's temporaries are removed first.
[[noreturn]] void internal_error(const char* what) {
  fdh::verify::remove_recorded_temporaries();
  std::fprintf(stderr, "fdhcert: internal error: %s\n", what);
  std::fflush(stderr);
  ::_exit(kInternalErrorStatus);
}

void on_terminate() {
  try {
    if (const std::exception_ptr e = std::current_exception()) std::rethrow_exception(e);
    internal_error("the program ended without an exception (std::terminate)");
  } catch (const std::exception& e) {
    internal_error(e.what());
  } catch (...) {
    internal_error("an exception of unknown type");
  }
}

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
  std::set_terminate(on_terminate);
  fdh::verify::remove_temporaries_on_signals();
  int status = 0;
  try {
    status =
        fdh::verify::run_cli(std::vector<std::string>(argv + 1, argv + argc), std::cout, std::cerr);
  } catch (const std::exception& e) {
    internal_error(e.what());
  } catch (...) {
    internal_error("an exception of unknown type");
  }
  return checked_stdout(status);
}
