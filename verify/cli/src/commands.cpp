#include "commands.hpp"

#include <sstream>

namespace fdh::verify {

long long ArgReader::integer(long long lo, long long hi) {
  const std::string flag = word();
  const std::string& v = value();
  try {
    std::size_t used = 0;
    const long long n = std::stoll(v, &used);
    if (used == v.size() && n >= lo && n <= hi) return n;
  } catch (const std::exception&) {
  }
  throw UsageError(flag + " takes a whole number from " + std::to_string(lo) + " to " +
                   std::to_string(hi) + ", not '" + v + "'");
}

std::vector<Method> methods_named(const std::vector<std::string>& names, int gate_k) {
  try {
    return names.empty() ? all_methods(gate_k) : select_methods(names, gate_k);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
}

std::vector<std::string> split_list(const std::string& s) {
  std::vector<std::string> out;
  std::string item;
  std::istringstream is(s);
  while (std::getline(is, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

}  // namespace fdh::verify
