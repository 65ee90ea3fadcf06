// Bad input: names the file and line. The CLI prints it and exits with status 2.
#pragma once

#include <stdexcept>
#include <string>

namespace fdh::verify {

class InputError : public std::runtime_error {
 public:
  InputError(const std::string& file, int line, const std::string& what)
      : std::runtime_error(line > 0 ? file + ":" + std::to_string(line) + ": " + what
                                    : file + ": " + what) {}
};

}  // namespace fdh::verify
