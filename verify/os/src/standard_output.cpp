#include "fdh/os/standard_output.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>

namespace fdh::verify {

int checked_output(int status, std::ostream& out, std::ostream& err) {
  errno = 0;
  out.flush();
  if (out) return status;
  const int why = errno;
  err << "fdhcert: error: standard output: "
      << (why ? std::strerror(why) : "cannot write (the stream failed)") << "\n";
  return 2;
}

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

}  // namespace fdh::verify
