// A record is a query with its provenance and its file's truth (fdh/io/query_record.hpp); a
// record scope names the queries a thread asks after their records (fdh/io/record_scope.hpp).
#include "fdh/io/query_record.hpp"

#include <gtest/gtest.h>

#include <thread>

#include "fdh/io/record_scope.hpp"

namespace fdh::verify {
namespace {

std::vector<QueryRecord> three() {
  std::vector<QueryRecord> rs(3);
  for (int i = 0; i < 3; ++i) {
    rs[i].id = "q" + std::to_string(i);
    rs[i].query.x[0] = Vec3{double(i), 0, 0};
  }
  rs[0].truth = Truth::Yes, rs[1].truth = Truth::No;
  return rs;
}

TEST(QueryRecord, TruthIsAVerdictOrUnknown) {
  EXPECT_EQ(truth_of(true), Truth::Yes);
  EXPECT_EQ(truth_of(false), Truth::No);
  EXPECT_EQ(stated(Truth::Yes), true);
  EXPECT_EQ(stated(Truth::No), false);
  EXPECT_FALSE(stated(Truth::Unknown).has_value());
  const std::vector<QueryRecord> rs = three();
  EXPECT_TRUE(rs[1].has_truth());
  EXPECT_FALSE(rs[2].has_truth());
  EXPECT_EQ(truths_of(rs), (std::vector<std::optional<bool>>{true, false, std::nullopt}));
  const std::vector<Query> qs = queries_of(rs);
  ASSERT_EQ(qs.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(qs[i].x, rs[i].query.x);
}

TEST(RecordScope, ABatchNamesItsOwnQueriesByAddress) {
  const std::vector<QueryRecord> rs = three();
  const std::vector<Query> qs = queries_of(rs);
  EXPECT_EQ(record_of(qs[1]), nullptr);
  {
    const RecordScope asking(rs, qs);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(record_of(qs[i]), &rs[i]);
    const Query copy = qs[1];
    EXPECT_EQ(record_of(copy), nullptr);  // not one of the batch's
    // Another thread asks nothing.
    const QueryRecord* there = &rs[0];
    std::thread([&] { there = record_of(qs[0]); }).join();
    EXPECT_EQ(there, nullptr);
  }
  EXPECT_EQ(record_of(qs[1]), nullptr);
}

TEST(RecordScope, OneRecordNamesEveryQueryDerivedFromItAndScopesNest) {
  const std::vector<QueryRecord> rs = three();
  const std::vector<Query> qs = queries_of(rs);
  const RecordScope outer(rs[2]);
  const Query transformed{};
  EXPECT_EQ(record_of(transformed), &rs[2]);
  {
    const RecordScope inner(rs, qs);
    EXPECT_EQ(record_of(qs[0]), &rs[0]);
    EXPECT_EQ(record_of(transformed), &rs[2]);  // not in the batch: the outer scope's
  }
  EXPECT_EQ(record_of(qs[0]), &rs[2]);
}

}  // namespace
}  // namespace fdh::verify
