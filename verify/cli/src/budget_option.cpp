#include "budget_option.hpp"

namespace fdh::verify {

CLI::Option* add_budget_option(CLI::App& cmd, Budget& budget, const std::string& what) {
  return cmd
      .add_option_function<double>(
          "--budget", [&budget](double seconds) { budget = Budget(seconds, run_start()); },
          "seconds the whole run may take (default: no limit): " + what +
              "\nstop at a clean point once it is spent, the outputs are\n"
              "written whole and say what was cut short. A plug-in call\n"
              "in progress ends first (at most --plugin-timeout)")
      ->type_name("SECONDS")
      ->check(CLI::Range(1e-3, 1e7));
}

}  // namespace fdh::verify
