// fdhcert fuzz: search a generator family for queries where a method disagrees with `exact`,
// shrink each to a minimal case, and store the distinct ones.
//
// Case i of a run is drawn from its own seed (seed, i), so a run is the same whatever the
// number of workers, and a shard is a contiguous range of i. Work goes in chunks; a chunk's
// cases are written (each whole, by rename) before the chunk's done-marker is, so a run killed
// at any moment and restarted loses no case and repeats at most the unfinished chunks.
// Workers are processes, not threads: RapidCheck's generators keep global state.
#pragma once

#include <cstdint>
#include <ostream>
#include <set>
#include <string>

namespace fdh::verify {

struct FuzzOptions {
  std::string method;
  std::string family = "angled";  // a static family (fdh/gen/families.hpp)
  std::uint64_t seed = 1;
  long count = 10000;  // cases in the whole run, over all shards
  int shard = 0;       // this process runs shard `shard` of `shards` (0-based)
  int shards = 1;
  int threads = 0;  // worker processes; 0: every core
  int chunk = 500;  // cases per checkpoint step
  std::string out_dir;
  bool progress = false;  // a live progress line on `progress_stream`
};

struct FuzzSummary {
  long first = 0, last = 0;        // this shard's cases: [first, last)
  long cases = 0;                  // cases run, including chunks finished by an earlier run
  long resumed = 0;                // of which were done before this run started
  long disagreements = 0;          // raw disagreements before shrinking
  std::set<std::string> distinct;  // file paths of the distinct shrunk cases
};

// Throws std::invalid_argument for an unknown method or family, std::runtime_error for I/O
// failures.
FuzzSummary run_fuzz(const FuzzOptions& opt, std::ostream& progress_stream);

// The seed of case i of a run: splitmix64 of (seed, i).
std::uint64_t case_seed(std::uint64_t seed, long i);

}  // namespace fdh::verify
