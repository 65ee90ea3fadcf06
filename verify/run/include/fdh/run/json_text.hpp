// The JSON rule: how every JSON output of fdhcert and the Python module is written.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <string>

namespace fdh::verify {

// j as text (two-space indented, then a newline), the one way every JSON output is written.
// JSON has no NaN or infinity (nlohmann would write null silently): a non-finite number
// anywhere in j throws std::runtime_error naming its place (a JSON pointer) and `what`.
std::string json_text(const nlohmann::ordered_json& j, const std::string& what);

// v to six significant digits: the precision of every time and energy in the JSON outputs.
double six_digits(double v);

}  // namespace fdh::verify
