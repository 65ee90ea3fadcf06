#include "fdh/io/json_text.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <charconv>
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

// The first code point escaped by json_string: U+EF00 + byte, for bytes 0x80-0xFF.
constexpr unsigned kEscapeBase = 0xEF00;

bool in(unsigned char c, unsigned lo, unsigned hi) {
  return c >= lo && c <= hi;
}

// The length of the valid UTF-8 sequence (RFC 3629: no overlong form, no surrogate, at most
// U+10FFFF) that starts s[i], or 0.
std::size_t utf8_length(std::string_view s, std::size_t i) {
  const auto at = [&](std::size_t k) { return static_cast<unsigned char>(s[i + k]); };
  const std::size_t left = s.size() - i;
  const unsigned char c = at(0);
  if (c < 0x80) return 1;
  if (in(c, 0xC2, 0xDF)) return left >= 2 && in(at(1), 0x80, 0xBF) ? 2 : 0;
  if (in(c, 0xE0, 0xEF)) {
    const unsigned lo = c == 0xE0 ? 0xA0 : 0x80, hi = c == 0xED ? 0x9F : 0xBF;
    return left >= 3 && in(at(1), lo, hi) && in(at(2), 0x80, 0xBF) ? 3 : 0;
  }
  if (in(c, 0xF0, 0xF4)) {
    const unsigned lo = c == 0xF0 ? 0x90 : 0x80, hi = c == 0xF4 ? 0x8F : 0xBF;
    return left >= 4 && in(at(1), lo, hi) && in(at(2), 0x80, 0xBF) && in(at(3), 0x80, 0xBF) ? 4 : 0;
  }
  return 0;
}

// Whether the 3-byte sequence at s[i] encodes U+EF80-U+EFFF, the escapes' own range.
bool is_escape_range(std::string_view s, std::size_t i) {
  return static_cast<unsigned char>(s[i]) == 0xEE &&
         in(static_cast<unsigned char>(s[i + 1]), 0xBE, 0xBF);
}

void append_escaped(std::string& out, unsigned char byte) {
  const unsigned cp = kEscapeBase + byte;
  out += char(0xE0 | (cp >> 12));
  out += char(0x80 | ((cp >> 6) & 0x3F));
  out += char(0x80 | (cp & 0x3F));
}

bool needs_escape(std::string_view s) {
  for (std::size_t i = 0; i < s.size();) {
    const std::size_t n = utf8_length(s, i);
    if (n == 0 || (n == 3 && is_escape_range(s, i))) return true;
    i += n;
  }
  return false;
}

bool any_needs_escape(const json& j) {
  if (j.is_string()) return needs_escape(j.get_ref<const std::string&>());
  if (j.is_object()) {
    for (const auto& [key, value] : j.items())
      if (needs_escape(key) || any_needs_escape(value)) return true;
  } else if (j.is_array()) {
    for (const json& v : j)
      if (any_needs_escape(v)) return true;
  }
  return false;
}

// j with every string and key through json_string.
json escaped(const json& j) {
  if (j.is_string()) return json_string(j.get_ref<const std::string&>());
  if (j.is_object()) {
    json out = json::object();
    for (const auto& [key, value] : j.items()) out[json_string(key)] = escaped(value);
    return out;
  }
  if (j.is_array()) {
    json out = json::array();
    for (const json& v : j) out.push_back(escaped(v));
    return out;
  }
  return j;
}

std::string dumped(const json& j, const std::string& what, int indent) {
  if (const std::optional<std::string> at = non_finite_at(j, ""))
    throw std::runtime_error(what +
                             ": refusing to write a non-finite number (NaN or infinity) "
                             "into JSON at " +
                             *at + "; the run's values left the finite range");
  // The copy only for the rare output that holds a name that is not UTF-8.
  return any_needs_escape(j) ? escaped(j).dump(indent) : j.dump(indent);
}

}  // namespace

std::string json_string(std::string_view bytes) {
  std::string out;
  out.reserve(bytes.size());
  for (std::size_t i = 0; i < bytes.size();) {
    const std::size_t n = utf8_length(bytes, i);
    if (n == 0 || (n == 3 && is_escape_range(bytes, i))) {
      for (std::size_t k = 0; k < std::max<std::size_t>(n, 1); ++k)
        append_escaped(out, static_cast<unsigned char>(bytes[i + k]));
      i += std::max<std::size_t>(n, 1);
    } else {
      out.append(bytes.substr(i, n));
      i += n;
    }
  }
  return out;
}

std::string bytes_of_json_string(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = std::max<std::size_t>(utf8_length(text, i), 1);
    if (n == 3 && is_escape_range(text, i)) {
      const unsigned cp = ((static_cast<unsigned char>(text[i]) & 0x0Fu) << 12) |
                          ((static_cast<unsigned char>(text[i + 1]) & 0x3Fu) << 6) |
                          (static_cast<unsigned char>(text[i + 2]) & 0x3Fu);
      out += char(cp - kEscapeBase);
    } else {
      out.append(text.substr(i, n));
    }
    i += n;
  }
  return out;
}

std::string json_text(const json& j, const std::string& what) {
  return dumped(j, what, 2) + "\n";
}

double six_digits(double v) {
  // Read back with from_chars: std::stod follows LC_NUMERIC, which a Python host may set.
  const std::string s = fmt::format("{:.6g}", v);
  double r = v;
  std::from_chars(s.data(), s.data() + s.size(), r);
  return r;
}

}  // namespace fdh::verify
