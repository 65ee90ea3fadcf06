#include "threads_option.hpp"

#include "commands.hpp"

namespace fdh::verify {

CLI::Option* add_threads_option(CLI::App& cmd, int& threads, const std::string& what) {
  return add_number_option(cmd, "--threads", threads,
                           "threads for " + what +
                               " (default: every core); the results\n"
                               "are the same for any number",
                           "N", 1, 1024);
}

}  // namespace fdh::verify
