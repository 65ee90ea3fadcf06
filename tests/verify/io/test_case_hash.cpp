// The hash that names stored cases (fdh/io/case_hash.hpp): its basis, -0 as +0, and the names
// the stored peers cases already have.
#include "fdh/io/case_hash.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "fdh/io/case_files.hpp"
#include "fdh/io/peer_case_file.hpp"

namespace fdh::verify {
namespace {

TEST(CaseHash, StartsFromItsBasisAndTakesMinusZeroAsZero) {
  EXPECT_EQ(CaseHash().hex(), "14650fb0739d0383");  // the basis the stored names were made with
  CaseHash plus, minus, one;
  plus.add_coordinate(0.0);
  minus.add_coordinate(-0.0);
  one.add_coordinate(1.0);
  EXPECT_EQ(plus.hex(), minus.hex());
  EXPECT_NE(plus.hex(), one.hex());
  Query q, r;
  q.x[0] = {0.0, 1, 2};
  r.x[0] = {-0.0, 1, 2};
  EXPECT_EQ(case_hash(q), case_hash(r));
  r.kind = QueryKind::EdgeEdge;
  EXPECT_NE(case_hash(q), case_hash(r));
}

// The stored peers cases keep their names: the hash is the one they were saved under.
TEST(CaseHash, NamesTheStoredPeersCasesAsTheyAre) {
  const auto files = list_peer_case_files(FDH_SOURCE_DIR "/corpus/peers");
  ASSERT_GT(files.size(), 10u);
  for (const std::string& f : files)
    EXPECT_EQ(std::filesystem::path(f).filename().string(), peer_case_file_name(read_peer_case(f)));
}

}  // namespace
}  // namespace fdh::verify
