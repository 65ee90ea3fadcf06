// Parameterised properties over the generator families: the parameters, and GoogleTest names
// for them (which may not contain '-': family and method names do).
#pragma once

#include <string>
#include <vector>

#include "fdh/gen/families.hpp"

namespace fdh {

inline std::string test_name(std::string n) {
  for (char& ch : n)
    if (ch == '-') ch = '_';
  return n;
}

// Every family's name, static then moving (the registry's order).
inline std::vector<std::string> every_family_name() {
  std::vector<std::string> names;
  for (const verify::Family& f : verify::all_families()) names.push_back(f.name);
  return names;
}

}  // namespace fdh
