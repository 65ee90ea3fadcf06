#include "fdh/run/json_text.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <optional>
#include <stdexcept>

namespace fdh::verify {
namespace {

using json = nlohmann::ordered_json;

// The JSON pointer of the first non-finite number in j, if any.
std::optional<std::string> non_finite_at(const json& j, const std::string& at) {
  if (j.is_number_float()) {
    if (std::isfinite(j.get<double>())) return std::nullopt;
    return at.empty() ? "/" : at;
  }
  if (j.is_object()) {
    for (const auto& [key, value] : j.items())
      if (auto p = non_finite_at(value, at + "/" + key)) return p;
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i)
      if (auto p = non_finite_at(j[i], at + "/" + std::to_string(i))) return p;
  }
  return std::nullopt;
}

}  // namespace

std::string json_text(const json& j, const std::string& what) {
  if (const std::optional<std::string> at = non_finite_at(j, ""))
    throw std::runtime_error(what +
                             ": refusing to write a non-finite number (NaN or infinity) "
                             "into JSON at " +
                             *at + "; the run's values left the finite range");
  return j.dump(2) + "\n";
}

double six_digits(double v) {
  return std::stod(fmt::format("{:.6g}", v));
}

}  // namespace fdh::verify
