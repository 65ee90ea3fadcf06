// Which records the calling thread is asking methods about. A query carries no provenance
// (fdh/query.hpp), yet a message from deep inside a method's call (a plug-in's crash handler,
// docs/plugins.md) must name the query by its FILE:LINE, or by its id. The code that holds the
// records says here what it asks, for the scope's lifetime; scopes nest.
#pragma once

#include <cstddef>
#include <vector>

#include "fdh/io/query_record.hpp"

namespace fdh::verify {

class RecordScope {
 public:
  // Every query asked on this thread derives from r: r.query itself, or a copy or transform of
  // it (a metamorphic check, a shrinking step), which is named after r.
  explicit RecordScope(const QueryRecord& r);
  // queries[i] is records[i].query (a copy of it, as a method's batch takes them): a query
  // asked at &queries[i] is named after records[i]. Both outlive the scope.
  RecordScope(const std::vector<QueryRecord>& records, const std::vector<Query>& queries);
  ~RecordScope();
  RecordScope(const RecordScope&) = delete;
  RecordScope& operator=(const RecordScope&) = delete;

 private:
  const RecordScope* outer_;
  const QueryRecord* records_;
  const Query* queries_;
  std::size_t n_;  // 0 for one record that every query derives from

  friend const QueryRecord* record_of(const Query& q);
};

// The record the calling thread's innermost scope gives q, or nullptr outside every scope.
// Allocates nothing and takes no lock: a signal handler may ask.
const QueryRecord* record_of(const Query& q);

}  // namespace fdh::verify
