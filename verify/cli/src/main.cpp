#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>

#include "fdh/cli/cli.hpp"

int main(int argc, char** argv) {
  int status =
      fdh::verify::run_cli(std::vector<std::string>(argv + 1, argv + argc), std::cout, std::cerr);
  // Standard output is checked once more as the process ends: what std::cout held, then the C
  // stream and its close. A full disk or a closed stdout is exit 2, never 0.
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
