// A file read whole and text found in it, for the tests that read what fdhcert wrote.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace fdh::verify {

// The bytes of `p`; "" when it cannot be read (the test's own expectations then fail).
inline std::string text_of(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline bool has(const std::string& text, const std::string& what) {
  return text.find(what) != std::string::npos;
}

}  // namespace fdh::verify
