// The minimum separation δ in the native format (docs/formats.md, "min-distance"): the
// `min-distance D` line, its round trip, its errors, and the case hash that takes δ only when
// it is not 0.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>

#include "fdh/io/case_files.hpp"
#include "fdh/io/input_error.hpp"
#include "fdh/io/query_io.hpp"
#include "temp_dir.hpp"

namespace fdh::verify {
namespace {

const char* const kLine =
    " 0 0 1 0 0 0 1 0 0 0 1 0 0 0 -1 0 0 0 1 0 0 0 1 0";  // a point through a still triangle

std::string write(const std::string& name, const std::string& text) {
  const std::string path = (fresh_temp_dir("min_distance_io") / name).string();
  std::ofstream(path) << text;
  return path;
}

TEST(MinDistanceIo, ALineSetsTheQueriesAfterItAndAbsentIsZero) {
  const std::string path =
      write("d.vf", std::string("vf a") + kLine + "\nmin-distance 0x1p-20\nvf b" + kLine +
                        " 1\nee c" + kLine + "\nmin-distance 0.125 # a comment\nvf d" + kLine +
                        "\nmin-distance 0\nvf e" + kLine + "\n");
  const std::vector<QueryRecord> qs = read_native(path);
  ASSERT_EQ(qs.size(), 5u);
  EXPECT_EQ(qs[0].query.min_distance, 0);
  EXPECT_EQ(qs[1].query.min_distance, std::ldexp(1.0, -20));
  EXPECT_EQ(qs[1].truth, Truth::Yes);
  EXPECT_EQ(qs[2].query.min_distance, std::ldexp(1.0, -20));
  EXPECT_EQ(qs[3].query.min_distance, 0.125);
  EXPECT_EQ(qs[4].query.min_distance, 0);
  EXPECT_EQ(qs[1].line, 3);
}

TEST(MinDistanceIo, WritingRoundTripsEveryDoubleAndResetsToZero) {
  std::vector<QueryRecord> rs(4);
  const double ds[4] = {0.1, 0, std::numeric_limits<double>::denorm_min(), 0.1};
  std::ostringstream os;
  double at = 0;
  for (int i = 0; i < 4; ++i) {
    rs[i].id = "q" + std::to_string(i);
    for (int k = 0; k < 8; ++k) rs[i].query.x[k] = Vec3{0.3 * k, -1.0 / (k + 1), 1e-300 * i};
    rs[i].query.min_distance = ds[i];
    write_native(os, rs[i], at);
  }
  const std::vector<QueryRecord> back = read_native(write("rt.vf", os.str()));
  ASSERT_EQ(back.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(back[i].query.min_distance, ds[i]) << i;
    EXPECT_EQ(back[i].query.x, rs[i].query.x) << i;
  }
  // One line per change of δ: 0.1, 0, the smallest double, 0.1 again.
  const std::string text = os.str();
  EXPECT_EQ(std::count(text.begin(), text.end(), 'm'), 4) << text;
}

TEST(MinDistanceIo, ACaseFileCarriesItsDeltaAndAContactCaseHasNoLine) {
  QueryRecord r;
  r.id = "c";
  r.query.x[0] = {1, 2, 3};
  EXPECT_EQ(case_file_text(r, {"x"}).find("min-distance"), std::string::npos);
  r.query.min_distance = 0x1p-30;
  const std::string text = case_file_text(r, {"x"});
  EXPECT_NE(text.find("min-distance 0x1p-30\n"), std::string::npos) << text;
  EXPECT_EQ(read_native(write("case.vf", text)).at(0).query.min_distance, 0x1p-30);
}

TEST(MinDistanceIo, TheCaseHashTakesDeltaOnlyWhenNotZero) {
  Query q;
  q.x[1] = {1, 0, 0};
  const std::string contact = case_hash(q);
  q.min_distance = 0.5;
  const std::string half = case_hash(q);
  q.min_distance = 0.25;
  EXPECT_NE(half, contact);
  EXPECT_NE(case_hash(q), half);
  q.min_distance = 0;
  EXPECT_EQ(case_hash(q), contact);
}

// Every stored case is named by the hash of its query, as it was saved: δ = 0 changed no name.
TEST(MinDistanceIo, TheStoredCasesKeepTheirNames) {
  const std::regex named(".*-([0-9a-f]{16})\\.vf");
  int checked = 0;
  for (const std::string& f : list_query_files(FDH_SOURCE_DIR "/corpus")) {
    std::smatch m;
    const std::string name = std::filesystem::path(f).filename().string();
    if (!std::regex_match(name, m, named)) continue;
    const std::vector<QueryRecord> qs = read_native(f);
    if (qs.size() != 1 || qs[0].query.min_distance != 0) continue;  // one contact case a file
    EXPECT_EQ(case_hash(qs[0].query), m[1].str()) << f;
    ++checked;
  }
  EXPECT_GT(checked, 50);
}

struct BadDelta {
  const char* line;
  const char* message;
};

class MinDistanceErrors : public ::testing::TestWithParam<BadDelta> {};

TEST_P(MinDistanceErrors, NameTheFileAndLine) {
  const std::string path =
      write("bad.vf", std::string("vf a") + kLine + "\n" + GetParam().line + "\nvf b" + kLine);
  try {
    read_native(path);
    FAIL() << "no error for " << GetParam().line;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(std::string("bad.vf:2: ") + GetParam().message),
              std::string::npos)
        << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    All, MinDistanceErrors,
    ::testing::Values(BadDelta{"min-distance -1", "min-distance: '-1' is negative"},
                      BadDelta{"min-distance -0x1p-1074", "min-distance: '-0x1p-1074' is negative"},
                      BadDelta{"min-distance nan", "min-distance: 'nan' is not a finite number"},
                      BadDelta{"min-distance inf", "min-distance: 'inf' is not a finite number"},
                      BadDelta{"min-distance 1e999", "min-distance: '1e999' is outside the range"},
                      BadDelta{"min-distance 1mm", "min-distance: '1mm' is not a number"},
                      BadDelta{"min-distance", "expected 'min-distance D', found 0 fields"},
                      BadDelta{"min-distance 1 2", "expected 'min-distance D', found 2 fields"}));

}  // namespace
}  // namespace fdh::verify
