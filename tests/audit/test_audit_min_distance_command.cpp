// `fdhcert audit --min-distance D` run in-process on OBJ frames (issue 31): two sheets exactly
// 1/64 apart, clean without D, a violation at D = 1/64 and clean just below; the certificate's
// proximity block, the case file carrying D, and D = 0 writing exactly the audit without it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_run.hpp"
#include "temp_dir.hpp"

// A named namespace, not an anonymous one: the tests are built as one unity file.
namespace fdh::verify::min_distance_command_tests {

namespace fs = std::filesystem;
using Json = nlohmann::json;

// Two 4 x 4 sheets 0.1 apart in x and y, the second `gap` above the first: one cloth.
std::string sheets(double gap) {
  std::ostringstream os;
  os.precision(17);
  for (const double z : {0.0, gap})
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) os << "v " << 0.1 * c << " " << 0.1 * r << " " << z << "\n";
  for (const int base : {1, 17})
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        const int a = base + 4 * r + c, b = a + 1, d = a + 4, e = d + 1;
        os << "f " << a << " " << b << " " << e << "\nf " << a << " " << e << " " << d << "\n";
      }
  return os.str();
}

fs::path two_sheets() {
  const fs::path dir = fresh_temp_dir("audit_sheets");
  std::ofstream(dir / "f0.obj") << sheets(0.5);
  std::ofstream(dir / "f1.obj") << sheets(0x1p-6);
  std::ofstream(dir / "f2.obj") << sheets(0x1p-6);
  return dir;
}

Json without_cost(const std::string& text) {
  Json j = Json::parse(text);
  j.erase("cost");
  return j;
}

TEST(AuditMinDistanceCommand, TwoSheetsAt1Over64) {
  const fs::path dir = two_sheets();
  EXPECT_EQ(fdhcert({"audit", dir.string(), "--quiet"}).status, 0);
  const CliRun at = fdhcert({"audit", dir.string(), "--min-distance", "0.015625", "--quiet"});
  EXPECT_EQ(at.status, 1) << at.err;
  EXPECT_NE(at.out.find("self-proximity"), std::string::npos) << at.out;
  EXPECT_NE(at.out.find("squared 1/4096 exactly"), std::string::npos) << at.out;
  const CliRun below = fdhcert({"audit", dir.string(), "--min-distance", "0.0156249", "--quiet"});
  EXPECT_EQ(below.status, 0) << below.out;
  EXPECT_NE(below.out.find("clean: 3 frames, 2 steps, 0 violations (exact); min distance "
                           "0.0156249: no pair came within reach of it"),
            std::string::npos)
      << below.out;
}

TEST(AuditMinDistanceCommand, TheCertificateCarriesD) {
  const fs::path dir = two_sheets(), out = fresh_temp_dir("audit_sheets_out");
  const CliRun r = fdhcert({"audit", dir.string(), "--min-distance", "0x1p-6", "--out",
                            out.string(), "--json", "--quiet"});
  ASSERT_EQ(r.status, 1) << r.err;
  const Json j = Json::parse(r.out);
  EXPECT_EQ(j["proximity"]["min_distance"], 0.015625);
  EXPECT_EQ(j["proximity"]["near_rule"]["rings"], 2);
  EXPECT_EQ(j["proximity"]["nearest"]["self"]["squared"], "1/4096");
  EXPECT_EQ(j["proximity"]["nearest"]["obstacle"], nullptr);
  EXPECT_GT(j["totals"]["self-proximity"].get<long>(), 0);
  EXPECT_EQ(j["totals"]["self-intersection"], 0);
  EXPECT_TRUE(fs::exists(out / "first-violation.png"));
  // A step's case file asks at D, and classify reads it with truth 1.
  std::string found;
  for (const auto& e : fs::directory_iterator(out / "cases")) found = e.path().string();
  ASSERT_FALSE(found.empty());
  std::ifstream in(found);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("min-distance 0x1p-6"), std::string::npos) << text.str();
  const CliRun c = fdhcert({"classify", found, "--json", "--check", "--min-distance", "0x1p-6"});
  EXPECT_EQ(c.status, 0) << c.err;
  const Json cj = Json::parse(c.out);
  EXPECT_EQ(cj["truth"], "file");
  EXPECT_EQ(cj["methods"]["exact"]["tp"], 1);
  EXPECT_EQ(cj["methods"]["robust"]["tp"], 1);
  EXPECT_EQ(fdhcert({"replay", (out / "cases").string(), "--min-distance", "0x1p-6"}).status, 0);
}

TEST(AuditMinDistanceCommand, ZeroIsTheAuditWithoutIt) {
  const fs::path dir = two_sheets();
  const CliRun plain = fdhcert({"audit", dir.string(), "--json", "--quiet"});
  const CliRun zero = fdhcert({"audit", dir.string(), "--json", "--min-distance", "0", "--quiet"});
  EXPECT_EQ(without_cost(plain.out), without_cost(zero.out));
  EXPECT_EQ(without_cost(plain.out).count("proximity"), 0u);
}

TEST(AuditMinDistanceCommand, RefusesABadDistance) {
  const fs::path dir = two_sheets();
  for (const char* bad : {"-1", "nan", "inf", "x"}) {
    const CliRun r = fdhcert({"audit", dir.string(), "--min-distance", bad});
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_NE(r.err.find("--min-distance"), std::string::npos) << r.err;
  }
  EXPECT_EQ(fdhcert({"audit", dir.string(), "--near-first-frame", "maybe"}).status, 2);
}

}  // namespace fdh::verify::min_distance_command_tests
