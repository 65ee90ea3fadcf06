#include <iostream>

#include "fdh/cli/cli.hpp"
#include "fdh/os/last_resort.hpp"
#include "fdh/os/standard_output.hpp"
#include "fdh/os/temporaries.hpp"

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
  return fdh::verify::checked_stdout(status);
}
