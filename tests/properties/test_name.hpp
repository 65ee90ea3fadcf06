// GoogleTest parameter names may not contain '-': family and method names do.
#pragma once

#include <string>

namespace fdh {

inline std::string test_name(std::string n) {
  for (char& ch : n)
    if (ch == '-') ch = '_';
  return n;
}

}  // namespace fdh
