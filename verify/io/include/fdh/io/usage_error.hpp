// A wrong command line, found by a job's options or a command after parsing (an option's value
// that CLI11 cannot check alone): fdhcert prints "fdhcert: <what>" and exits with status 2.
#pragma once

#include <stdexcept>

namespace fdh::verify {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace fdh::verify
