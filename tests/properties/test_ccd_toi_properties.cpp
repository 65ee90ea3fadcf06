// robust's time of impact against its exact twin, over the moving generator families and the
// CCD benchmark sample (skipped without one, FDH_CCD_SAMPLE), at w = 2^-30 and 2^-50: the verdict
// is exact's; with a contact, t_lo <= t* <= t_hi, decided exactly by compare_with_toi; the
// width is at most w; and t_lo = 0 only when t* = 0.
#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>

#include "fdh/ccd/toi.hpp"
#include "fdh/exact/ccd.hpp"
#include "fdh/gen/rapidcheck.hpp"
#include "fdh/io/query_io.hpp"
#include "test_name.hpp"

namespace fdh::verify {
namespace {

constexpr double kToiWidths[] = {0x1p-30, 0x1p-50};

// "" if robust's TOI keeps the contract on q at width w, else what it broke.
std::string broken_toi_promise(const Query& q, double w) {
  const Toi toi = robust_ccd_toi(q, w, exact::ccd_toi);
  const bool hit = exact::ccd_hit(q);
  std::ostringstream why;
  if (toi.hit != hit) return "verdict";
  if (!hit) return toi.t_lo == 1 && toi.t_hi == 1 ? "" : "no contact but not [1, 1]";
  if (!(0 <= toi.t_lo && toi.t_lo <= toi.t_hi && toi.t_hi <= 1)) return "not in [0, 1]";
  if (toi.t_hi - toi.t_lo > w) return "too wide";
  const int lo = exact::compare_with_toi(q, toi.t_lo);
  if (lo > 0) return "late";
  if (exact::compare_with_toi(q, toi.t_hi) < 0) return "t_hi before t*";
  if (toi.t_lo == 0 && lo != 0) return "0 where t* > 0";
  return "";
}

class MovingFamilyToi : public ::testing::TestWithParam<std::string> {};

TEST_P(MovingFamilyToi, RobustEnclosesTheExactContactTime) {
  const Family& f = *family_named(GetParam());
  for (const double w : kToiWidths)
    EXPECT_TRUE(rc::check("robust-toi-encloses/" + f.name, [&f, w] {
      const Query q = (*gen_family(f)).query;
      RC_ASSERT(broken_toi_promise(q, w) == "");
    }));
}

INSTANTIATE_TEST_SUITE_P(All, MovingFamilyToi, ::testing::ValuesIn(family_names(true)),
                         [](const auto& info) { return test_name(info.param); });

TEST(SampleToi, RobustEnclosesTheExactContactTimeOnEveryQuery) {
  namespace fs = std::filesystem;
  const fs::path root = FDH_CCD_SAMPLE;  // the build's FDH_CCD_SAMPLE, empty for none
  if (!fs::is_directory(root)) GTEST_SKIP() << "no CCD benchmark sample (FDH_CCD_SAMPLE)";
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(root))
    if (e.path().extension() == ".csv") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  std::size_t checked = 0;
  for (const fs::path& file : files) {
    const auto kind = kind_from_folder(file.string());
    if (!kind) continue;
    const std::vector<QueryRecord> qs = read_benchmark_csv(file.string(), *kind);
    for (std::size_t i = 0; i < qs.size(); ++i, ++checked)
      for (const double w : kToiWidths)
        EXPECT_EQ(broken_toi_promise(qs[i].query, w), "") << file << " query " << i << " w " << w;
  }
  EXPECT_GT(checked, 2800u);
}

}  // namespace
}  // namespace fdh::verify
