#include "fdh/io/record_scope.hpp"

#include <cstdint>

namespace fdh::verify {
namespace {

thread_local const RecordScope* t_scope = nullptr;

}  // namespace

RecordScope::RecordScope(const QueryRecord& r)
    : outer_(t_scope), records_(&r), queries_(nullptr), n_(0) {
  t_scope = this;
}

RecordScope::RecordScope(const std::vector<QueryRecord>& records, const std::vector<Query>& queries)
    : outer_(t_scope), records_(records.data()), queries_(queries.data()), n_(queries.size()) {
  t_scope = this;
}

RecordScope::~RecordScope() {
  t_scope = outer_;
}

const QueryRecord* record_of(const Query& q) {
  for (const RecordScope* s = t_scope; s; s = s->outer_) {
    if (s->n_ == 0) return s->records_;
    // Compared as addresses: q is one of the batch's queries, or not in it at all.
    const auto at = reinterpret_cast<std::uintptr_t>(&q);
    const auto begin = reinterpret_cast<std::uintptr_t>(s->queries_);
    if (at >= begin && at < begin + s->n_ * sizeof(Query) && (at - begin) % sizeof(Query) == 0)
      return s->records_ + (at - begin) / sizeof(Query);
  }
  return nullptr;
}

}  // namespace fdh::verify
