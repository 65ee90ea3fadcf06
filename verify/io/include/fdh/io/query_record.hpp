// A query as a file holds it: the geometry (fdh::Query) with where it came from and what the
// file says of it. Readers return records, writers take them (fdh/io/query_io.hpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "fdh/query.hpp"

namespace fdh::verify {

// A file's verdict on its query: the native format's optional last field, the benchmark CSV's
// truth column (docs/formats.md). Unknown where the file gives none.
enum class Truth { Unknown, No, Yes };

inline Truth truth_of(bool hit) {
  return hit ? Truth::Yes : Truth::No;
}

// The truth as a verdict, nullopt when Unknown.
inline std::optional<bool> stated(Truth t) {
  if (t == Truth::Unknown) return std::nullopt;
  return t == Truth::Yes;
}

struct QueryRecord {
  Query query;
  std::string id;
  Truth truth = Truth::Unknown;
  std::string file;  // empty for a query made in memory (a generator, a simulation)
  int line = 0;      // the query's first line in `file`

  bool has_truth() const { return truth != Truth::Unknown; }
};

// The records' queries, in order.
inline std::vector<Query> queries_of(const std::vector<QueryRecord>& records) {
  std::vector<Query> out;
  out.reserve(records.size());
  for (const QueryRecord& r : records) out.push_back(r.query);
  return out;
}

// The records' truths as verdicts (stated()), in order.
inline std::vector<std::optional<bool>> truths_of(const std::vector<QueryRecord>& records) {
  std::vector<std::optional<bool>> out;
  out.reserve(records.size());
  for (const QueryRecord& r : records) out.push_back(stated(r.truth));
  return out;
}

}  // namespace fdh::verify
