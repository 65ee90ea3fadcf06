// A file of queries from one generator family (`fdhcert generate`), for classify and benchmarks.
#pragma once

#include <cstdint>
#include <string>

namespace fdh::verify {

constexpr long kMaxGeneratedQueries = 100'000'000L;  // generate --count

// Writes `count` queries of the family named `family` (families.hpp, a known name) to `path` in
// the native format, whole (fdh/os/atomic_file.hpp): a comment line with the command, then case
// i from the seed (seed, i) as in fuzz, with id FAMILY/i and the truth where the construction
// knows it. The same seed gives the same file.
void write_family_file(const std::string& family, long count, std::uint64_t seed,
                       const std::string& path);

}  // namespace fdh::verify
