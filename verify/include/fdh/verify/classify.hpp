// Runs methods side by side on the same queries and tallies them against a truth.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "fdh/query.hpp"
#include "fdh/verify/methods.hpp"

namespace fdh::verify {

struct Tally {
  long tp = 0, tn = 0, fp = 0, fn = 0;
  double ns_per_query = 0;
  long errors() const { return fp + fn; }
};

struct MethodResult {
  std::string name;
  Tally tally;
  std::vector<char> verdict;  // per query, 1 = hit
};

struct Classification {
  std::size_t queries = 0;
  std::string truth;            // "file" (every query has one), "exact" (none has), or "mixed"
  std::vector<char> reference;  // per query: the file's truth where given, else exact's verdict
  std::vector<char> exact;      // per query: exact's verdict
  std::vector<MethodResult> methods;
  std::vector<std::size_t> exact_vs_file;  // queries where exact disagrees with the file's truth
};

// Every query must be a static vertex-face query. Each method's time is the mean over enough
// passes to fill about 20 ms, so that short files still give a stable ns per query.
Classification classify(const std::vector<Query>& queries, const std::vector<Method>& methods);

}  // namespace fdh::verify
