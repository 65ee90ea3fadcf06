// The fdhcert command line, callable in-process so that tests can run it.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace fdh::verify {

// Exit status: 0 success, 1 a requested check failed, 2 bad input or usage.
int run_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace fdh::verify
