#include "fdh/io/query_io.hpp"
#include "test_data.hpp"

#include <gtest/gtest.h>

#include <cctype>

#include <sstream>

#include "fdh/io/input_error.hpp"
#include "temp_dir.hpp"

namespace fdh::verify {
namespace {

TEST(QueryIo, ReadsNativeWithCommentsHexFloatsAndOptionalTruth) {
  const std::vector<QueryRecord> qs = read_native(kData + "static.vf");
  ASSERT_EQ(qs.size(), 4u);
  EXPECT_EQ(qs[0].id, "through-face");
  EXPECT_EQ(qs[0].file, kData + "static.vf");
  EXPECT_EQ(qs[0].line, 2);
  EXPECT_EQ(qs[0].truth, Truth::Yes);
  EXPECT_EQ(qs[2].query.x[0], qs[0].query.x[0]);  // 0x1p-2 == 0.25
  EXPECT_EQ(qs[3].truth, Truth::Unknown);
  EXPECT_FALSE(qs[3].has_truth());
  EXPECT_TRUE(qs[0].query.is_static_vf());
}

TEST(QueryIo, DecimalsAreCorrectlyRounded) {
  std::string why;
  EXPECT_EQ(*parse_double("0.1", why), 0.1);
  EXPECT_EQ(*parse_double("9007199254740993", why), 9007199254740992.0);  // ties to even
  EXPECT_EQ(*parse_double("0x1.8p1", why), 3.0);
  EXPECT_FALSE(parse_double("inf", why));
  EXPECT_FALSE(parse_double("1e400", why));
  EXPECT_FALSE(parse_double("1.5x", why));
}

TEST(QueryIo, WriteNativeRoundTripsExactly) {
  QueryRecord q;
  q.id = "r";
  q.truth = Truth::No;
  for (int i = 0; i < 8; ++i) q.query.x[i] = Vec3{0.1 * i, -1e-300 * i, 3e300 / (i + 1)};
  std::stringstream ss;
  write_native(ss, q);
  const std::string path = (fresh_temp_dir("roundtrip") / "roundtrip.vf").string();
  FILE* f = fopen(path.c_str(), "w");
  fputs(ss.str().c_str(), f);
  fclose(f);
  const QueryRecord back = read_native(path).at(0);
  EXPECT_EQ(back.query.x, q.query.x);
  EXPECT_EQ(back.id, "r");
  EXPECT_EQ(back.truth, Truth::No);
}

TEST(QueryIo, ReadsBenchmarkCsvWithKindFromFolder) {
  const std::vector<QueryRecord> qs = read_query_file(kData + "vertex-face/good.csv");
  ASSERT_EQ(qs.size(), 1u);
  EXPECT_EQ(qs[0].query.kind, QueryKind::VertexFace);
  EXPECT_EQ(qs[0].query.x[0].x, 0.25);
  EXPECT_EQ(qs[0].truth, Truth::Yes);
  EXPECT_EQ(qs[0].id, "0");
}

struct BadFile {
  const char* file;
  const char* message;  // the error names the file and line, then this
};

class QueryIoErrors : public ::testing::TestWithParam<BadFile> {};

TEST_P(QueryIoErrors, NameTheFileAndLine) {
  const BadFile& b = GetParam();
  try {
    read_query_file(kData + b.file);
    FAIL() << "no error for " << b.file;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(b.message), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    All, QueryIoErrors,
    ::testing::Values(
        BadFile{"bad_count.vf", "bad_count.vf:2: expected 'vf <id> <24 numbers>"},
        BadFile{"bad_number.vf", "bad_number.vf:3: number 8: 'zero' is not a number"},
        BadFile{"bad_nan.vf", "bad_nan.vf:1: number 24: 'nan' is not a finite"},
        BadFile{"bad_inf.vf", "bad_inf.vf:1: number 24: '1e999' is outside the range"},
        BadFile{"bad_kind.vf", "bad_kind.vf:1: a query line starts with"},
        BadFile{"bad_truth.vf", "bad_truth.vf:1: truth must be 0 or 1"},
        BadFile{"vertex-face/bad_rational.csv",
                "bad_rational.csv:1: '1/3' is not exactly a double"},
        BadFile{"vertex-face/bad_short.csv", "bad_short.csv:5: the file ends inside a query"},
        BadFile{"missing.vf", "missing.vf: cannot open file"}),
    // The file's name, as a test name stable from build to build.
    [](const auto& info) {
      std::string n = info.param.file;
      for (char& ch : n)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
      return n;
    });

}  // namespace
}  // namespace fdh::verify
