// The seed of case i of a run: each case drawn from its own seed, so that a run gives the same
// cases whatever the number of workers or shards (fuzz, certify, peers, the report's
// measurements, generate).
#pragma once

#include <cstdint>

namespace fdh::verify {

// splitmix64 of (seed, i) (Steele, Lea and Flood, "Fast splittable pseudorandom number
// generators", OOPSLA 2014).
std::uint64_t case_seed(std::uint64_t seed, long i);

}  // namespace fdh::verify
