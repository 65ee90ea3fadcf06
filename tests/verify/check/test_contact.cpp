// The exact contact of a query's own decision (fdh/check/contact.hpp): the twin's verdict, and
// the kind and time that the per-query CSV and fuzz's case files show.
#include "fdh/check/contact.hpp"

#include <gtest/gtest.h>

#include "fdh/check/registry.hpp"
#include "fdh/io/query_io.hpp"
#include "test_data.hpp"

namespace fdh::verify {
namespace {

TEST(Contact, StaticQueriesHaveAKindAndARationalTime) {
  for (const QueryRecord& r : read_native(kData + "static.vf")) {
    const TwinContact c = twin_contact(r.query);
    EXPECT_EQ(c.hit, twin_hit(r.query)) << r.id;
    EXPECT_FALSE(c.kind.empty()) << r.id;
    EXPECT_EQ(c.time_lo, c.time_hi) << r.id;
  }
  const TwinContact face = twin_contact(read_native(kData + "static.vf").front().query);
  EXPECT_EQ(contact_words(face), "hit (face at t = 1/2)");
  EXPECT_EQ(contact_words(twin_contact(read_native(kData + "static.vf")[1].query)), "no");
}

TEST(Contact, MovingQueriesHaveATimeOrABracket) {
  std::vector<std::string> words;
  for (const QueryRecord& r : read_native(kData + "moving_times.vf")) {
    const TwinContact c = twin_contact(r.query);
    EXPECT_EQ(c.hit, twin_hit(r.query)) << r.id;
    EXPECT_TRUE(c.kind.empty()) << r.id;
    words.push_back(contact_words(c));
  }
  ASSERT_GE(words.size(), 4u);
  EXPECT_EQ(words[0], "hit (at t = 1/4)");
  EXPECT_EQ(words[1], "hit (at t = 0)");
  EXPECT_EQ(words[2], "no");
  EXPECT_EQ(words[3].rfind("hit (at t in [", 0), 0u) << words[3];
}

}  // namespace
}  // namespace fdh::verify
