#include "min_distance_option.hpp"

#include "commands.hpp"
#include "fdh/io/query_io.hpp"

namespace fdh::verify {

CLI::Option* add_min_distance_option(CLI::App& cmd, double& d, const std::string& what) {
  return cmd
      .add_option_function<std::string>(
          "--min-distance",
          [&d](const std::string& text) {
            std::string why;
            d = *parse_min_distance(text, why);  // checked below
          },
          what)
      ->type_name("D")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            std::string why;
            if (parse_min_distance(text, why)) return {};
            return "takes a finite number >= 0: " + why;
          },
          ""));
}

}  // namespace fdh::verify
