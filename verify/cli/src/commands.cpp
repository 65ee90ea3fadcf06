#include "commands.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>

#include "fdh/io/json_text.hpp"
#include "fdh/io/query_io.hpp"  // parse_double

namespace fdh::verify {

std::string quoted_input(std::string_view s, std::size_t shown) {
  std::string out = "'";
  for (std::size_t i = 0; i < s.size() && i < shown; ++i) {
    const unsigned char ch = static_cast<unsigned char>(s[i]);
    if (ch < 0x20 || ch >= 0x7f)
      out += fmt::format("\\x{:02x}", ch);
    else
      out += char(ch);
  }
  out += "'";
  if (s.size() > shown) out += fmt::format("... ({} bytes)", s.size());
  return out;
}

std::string range_text(double lo, double hi) {
  return fmt::format("[{:g}, {:g}]", lo, hi);
}

namespace {

// `2^N` or `2^-N` (N whole, the double's exponents), else nothing.
std::optional<double> power_of_two(const std::string& s) {
  if (s.size() < 3 || s.compare(0, 2, "2^") != 0) return std::nullopt;
  int n = 0;
  const char *b = s.data() + 2, *e = s.data() + s.size();
  const auto [p, ec] = std::from_chars(b, e, n);
  if (ec != std::errc() || p != e || n < -1074 || n > 1023) return std::nullopt;
  return std::ldexp(1.0, n);
}

}  // namespace

CLI::Validator real_range(double lo, double hi, const std::string& shown) {
  return CLI::Validator(
      [lo, hi, shown](std::string& s) -> std::string {
        const std::string given = s;
        std::string why;
        std::optional<double> v = power_of_two(s);
        if (v)
          s = fmt::format("{:.17g}", *v);  // what the option's conversion reads
        else if (s.compare(0, 2, "2^") == 0)
          why = quoted_input(s) + " is not 2^N with N a whole number in [-1074, 1023]";
        else
          v = parse_double(s, why);
        if (!v) return why + "; give a number in " + shown;
        if (!(*v >= lo && *v <= hi))
          return "Value " + quoted_input(given) + " not in range " + shown;
        return {};
      },
      "");
}

CLI::Validator known_method() {
  // The registry asked when the value is checked (parsing's end), not when the option is
  // declared, so that a --plugin's methods count wherever it stands.
  return CLI::Validator(
      [](std::string& s) {
        const std::string why = one_of(method_names())(s);
        return why.empty() ? why : why + "; a plug-in's methods need --plugin FILE";
      },
      "");
}

CLI::Option* add_methods_option(CLI::App& cmd, std::vector<std::string>& names,
                                const std::string& help) {
  // One word per --methods (not the files after it), split at commas.
  return cmd.add_option("--methods", names, help + "\n(a --plugin FILE adds its methods)")
      ->delimiter(',')
      ->allow_extra_args(false)
      ->type_name("LIST")
      ->check(known_method());
}

CLI::Validator one_of(std::vector<std::string> choices) {
  return CLI::Validator(
      [choices](std::string& s) -> std::string {
        if (std::find(choices.begin(), choices.end(), s) != choices.end()) return {};
        std::string list;
        for (const std::string& c : choices) list += (list.empty() ? "" : ", ") + c;
        return "unknown value " + quoted_input(s) + " (one of " + list + ")";
      },
      "");
}

CLI::Validator kdop_k_validator(bool allow_none) {
  return CLI::Validator(
      [allow_none](std::string& s) -> std::string {
        for (const char* k : {"6", "14", "18", "26"})
          if (s == k) return {};
        if (allow_none && s == "0") return {};
        return "takes 6, 14, 18 or 26, not " + quoted_input(s);
      },
      "");
}

CLI::Validator i_of_n_validator(long max) {
  return CLI::Validator(
      [max](std::string& s) -> std::string {
        const std::size_t slash = s.find('/');
        const auto digits = [](const std::string& d) {  // at most 7: no overflow
          return !d.empty() && d.size() <= 7 && d.find_first_not_of("0123456789") == d.npos;
        };
        if (slash != s.npos && digits(s.substr(0, slash)) && digits(s.substr(slash + 1))) {
          const long i = std::stol(s.substr(0, slash)), n = std::stol(s.substr(slash + 1));
          if (i >= 1 && i <= n && n <= max) return {};
        }
        return "takes I/N with 1 <= I <= N <= " + std::to_string(max) + ", not " + quoted_input(s);
      },
      "");
}

std::pair<int, int> i_of_n(const std::string& s) {
  const std::size_t slash = s.find('/');
  return {std::stoi(s.substr(0, slash)), std::stoi(s.substr(slash + 1))};
}

CLI::Option* add_seed_option(CLI::App& cmd, std::uint64_t& seed, const std::string& help) {
  return cmd.add_option("--seed", seed, help)
      ->type_name("S")
      ->check(CLI::Range(std::uint64_t(0), std::uint64_t(1) << 62));
}

void print_json(std::ostream& os, const nlohmann::ordered_json& j) {
  os << json_text(j, "the JSON output");
}

}  // namespace fdh::verify
