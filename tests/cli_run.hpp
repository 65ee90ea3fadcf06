// fdhcert's command line run in-process, for the tests: its exit status and what it printed.
#pragma once

#include <sstream>
#include <string>
#include <vector>

#include "fdh/cli/cli.hpp"

namespace fdh::verify {

struct CliRun {
  int status;
  std::string out, err;
};

inline CliRun fdhcert(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  const int status = run_cli(args, out, err);
  return {status, out.str(), err.str()};
}

}  // namespace fdh::verify
