#include "fdh/gen/case_seed.hpp"

namespace fdh::verify {

std::uint64_t case_seed(std::uint64_t seed, long i) {
  std::uint64_t z = seed * 0x9e3779b97f4a7c15ull + std::uint64_t(i) + 0x632be59bd9b4e019ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

}  // namespace fdh::verify
