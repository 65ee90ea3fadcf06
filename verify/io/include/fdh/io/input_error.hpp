// Bad input: the error that names the file and line (the CLI prints it and exits with status 2),
// the one way every reader quotes input in a message, and the resource bounds of
// docs/limits.md.
#pragma once

#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <string_view>

namespace fdh::verify {

// `s` fit for a terminal: bytes below 0x20, 0x7f and above, and the backslash, as \xNN (\\).
inline std::string printable(std::string_view s) {
  static const char* const kHex = "0123456789abcdef";
  std::string out;
  out.reserve(s.size());
  for (const char ch : s) {
    const auto b = static_cast<unsigned char>(ch);
    if (b == '\\') {
      out += "\\\\";
    } else if (b < 0x20 || b >= 0x7f) {
      out += "\\x";
      out += kHex[b >> 4];
      out += kHex[b & 15];
    } else {
      out += ch;
    }
  }
  return out;
}

// The offending input as a message quotes it (not named `quoted`: std::quoted would win by ADL):
// 'text', at most `max_bytes` bytes of it, made printable; a longer input is cut and its length
// given: '1234...' (10485760 bytes).
inline std::string quote(std::string_view s, std::size_t max_bytes = 80) {
  if (s.size() <= max_bytes) return "'" + printable(s) + "'";
  return "'" + printable(s.substr(0, max_bytes)) + "...' (" + std::to_string(s.size()) + " bytes)";
}

class InputError : public std::runtime_error {
 public:
  InputError(const std::string& file, long line, const std::string& what)
      : std::runtime_error(line > 0 ? printable(file) + ":" + std::to_string(line) + ": " + what
                                    : printable(file) + ": " + what) {}
};

// The resource bounds (docs/limits.md). Each has a default and an environment variable that
// sets it: a whole number from 1 to 2^62. Past a bound, a reader stops with an InputError that
// says the bound and how to raise it (bound_text).
struct Bound {
  const char* env;  // FDH_MAX_...
  long long fallback;
  const char* unit;  // "bytes", "queries", ...
};

inline constexpr Bound kMaxLineBytes = {"FDH_MAX_LINE_BYTES", 64 * 1024, "bytes"};
inline constexpr Bound kMaxFileBytes = {"FDH_MAX_FILE_BYTES", 1024LL * 1024 * 1024, "bytes"};
inline constexpr Bound kMaxQueries = {"FDH_MAX_QUERIES", 10000000, "queries"};
inline constexpr Bound kMaxGrid = {"FDH_MAX_GRID", 2000, "particles per side"};
inline constexpr Bound kMaxObstacleTriangles = {"FDH_MAX_OBSTACLE_TRIANGLES", 1000000, "triangles"};

// The bound in force: the environment's value, else the default. A malformed value is an
// InputError naming the variable.
inline long long bound_value(const Bound& b) {
  const char* s = std::getenv(b.env);
  if (!s || !*s) return b.fallback;
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(s, &end, 10);
  if (errno || *end != '\0' || v < 1 || v > (1LL << 62))
    throw InputError(
        b.env, 0, "must be a whole number from 1 to 2^62, not " + quote(s) + " (docs/limits.md)");
  return v;
}

// "the bound is 65536 bytes; set FDH_MAX_LINE_BYTES to raise it (docs/limits.md)"
inline std::string bound_text(const Bound& b, long long value) {
  return "the bound is " + std::to_string(value) + " " + b.unit + "; set " + b.env +
         " to raise it (docs/limits.md)";
}

}  // namespace fdh::verify
