#include "fdh/io/case_hash.hpp"

#include <cstdio>
#include <cstring>

namespace fdh::verify {

void CaseHash::add(std::uint64_t v) {
  for (int b = 0; b < 8; ++b) h_ = (h_ ^ ((v >> (8 * b)) & 0xff)) * 1099511628211ull;
}

void CaseHash::add_coordinate(double v) {
  if (v == 0) v = 0.0;
  std::uint64_t bits;
  std::memcpy(&bits, &v, sizeof bits);
  add(bits);
}

std::string CaseHash::hex() const {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h_));
  return buf;
}

}  // namespace fdh::verify
