// The JSON rule: how every JSON output of fdhcert and the Python module is written.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <string>
#include <string_view>

namespace fdh::verify {

// j as text (two-space indented, then a newline), the one way every JSON output is written.
// JSON has no NaN or infinity (nlohmann would write null silently): a non-finite number
// anywhere in j throws std::runtime_error naming its place (a JSON pointer) and `what`.
// Names are bytes: every string and key goes through json_string first, so a name or path
// that is not UTF-8 is written, never an abort.
std::string json_text(const nlohmann::ordered_json& j, const std::string& what);

// Names are bytes (docs/formats.md, "Names that are not UTF-8"): `bytes` as valid UTF-8, by one
// reversible rule. Each byte 0x80-0xFF that does not belong to a valid UTF-8 sequence (RFC
// 3629) becomes the private-use character U+EF00 + byte (U+EF80-U+EFFF); a valid sequence is
// kept, except one that encodes U+EF80-U+EFFF itself, whose three bytes are escaped in turn.
// Valid UTF-8 without those characters is unchanged.
std::string json_string(std::string_view bytes);

// The inverse of json_string: the original bytes of a string read back from fdhcert's JSON.
std::string bytes_of_json_string(std::string_view text);

// v to six significant digits: the precision of every time and energy in the JSON outputs.
double six_digits(double v);

}  // namespace fdh::verify
