// The report's time-of-impact measurements: a row per method and moving family, and per sweep
// point; the certified methods never late; float-cubic's late count the checker's own; the
// data files, the report's text and the charts.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "fdh/check/checker.hpp"
#include "fdh/check/registry.hpp"
#include "fdh/gen/families.hpp"
#include "fdh/os/atomic_file.hpp"
#include "fdh/report/measurements.hpp"
#include "fdh/report/report_document.hpp"
#include "temp_dir.hpp"

namespace fdh::verify {
namespace toi_measure_test {

std::size_t count_lines(const std::string& s) {
  return std::size_t(std::count(s.begin(), s.end(), '\n'));
}

std::vector<std::string> toi_method_names() {
  std::vector<std::string> out;
  for (const Method& m : toi_methods()) out.push_back(m.name);
  return out;
}

bool certified(const std::string& method) {
  return method == "robust" || method == "exact";
}

TEST(ToiReport, SpeedHasOneRowPerMethodAndMovingFamily) {
  const std::vector<ToiSpeedRow> rows = toi_speed(20, 3);
  const std::vector<std::string> methods = toi_method_names();
  ASSERT_TRUE(std::count(methods.begin(), methods.end(), "float-cubic"));
  std::size_t moving = 0;
  for (const Family& f : all_families()) {
    if (!f.moving) continue;
    ++moving;
    for (const std::string& m : methods)
      EXPECT_EQ(
          std::count_if(rows.begin(), rows.end(),
                        [&](const ToiSpeedRow& r) { return r.method == m && r.family == f.name; }),
          1)
          << m << " " << f.name;
  }
  EXPECT_EQ(rows.size(), moving * methods.size());
  for (const ToiSpeedRow& r : rows) {
    EXPECT_EQ(r.queries, 20) << r.method << " " << r.family;
    EXPECT_LE(r.late, r.contacts);
    EXPECT_GT(r.ns_per_query, 0);
    if (certified(r.method)) {
      EXPECT_EQ(r.late + r.verdict_errors, 0) << r.method << " " << r.family;
    }
  }
  const std::string csv = toi_speed_csv(rows);
  EXPECT_EQ(csv.rfind("method,family,queries,contacts,ns_per_query,early_median,early_max,late,"
                      "early,zero,verdict_errors\n",
                      0),
            0u);
  EXPECT_EQ(count_lines(csv), rows.size() + 1);
}

// The rows' late counts are the checker's on the same queries (family_queries), query by query.
TEST(ToiReport, FloatCubicsLateCountIsTheCheckersOnTheSameQueries) {
  const std::vector<ToiSpeedRow> rows = toi_speed(20, 3);
  const Method cubic = select_methods({"float-cubic"}).front();
  long total = 0;
  for (std::size_t k = 0; k < all_families().size(); ++k) {
    if (!all_families()[k].moving) continue;
    long late = 0;
    for (const Query& q : family_queries(k, 20, 3))
      late += check_time(cubic, q, kToiWidthAsked).late;
    const auto row = std::find_if(rows.begin(), rows.end(), [&](const ToiSpeedRow& r) {
      return r.method == "float-cubic" && r.family == all_families()[k].name;
    });
    ASSERT_NE(row, rows.end());
    EXPECT_EQ(row->late, late) << row->family;
    total += late;
  }
  EXPECT_GT(total, 0);  // the baseline is late somewhere in these queries: the count is tested
}

TEST(ToiReport, TheSweepHasEveryPointForEveryMethodButTheTwin) {
  const std::vector<ToiStabilityRow> rows = toi_stability(4, 2);
  std::vector<std::string> methods;
  for (const Method& m : toi_methods())
    if (!m.is_twin) methods.push_back(m.name);
  ASSERT_FALSE(toi_stability_sweeps().empty());
  std::size_t points = 0;
  for (const StabilitySweep& sw : toi_stability_sweeps()) points += std::size_t(sw.last) + 1;
  EXPECT_EQ(rows.size(), points * methods.size());
  for (const ToiStabilityRow& r : rows) {
    EXPECT_NE(std::find(methods.begin(), methods.end(), r.method), methods.end()) << r.method;
    EXPECT_EQ(r.queries, 4);
    EXPECT_LE(r.late, r.contacts);
    EXPECT_GE(r.early_max, r.early_median);
    if (certified(r.method)) {
      EXPECT_EQ(r.late, 0) << r.sweep << " " << r.parameter;
    }
  }
  EXPECT_EQ(count_lines(toi_stability_csv(rows)), rows.size() + 1);
}

TEST(ToiReport, DataFilesHaveAHeaderAndOneLinePerRow) {
  EXPECT_EQ(toi_speed_csv({{"float-cubic", "coplanar", 100, 54, 29.5, 0, 0.25, 41, 2, 1, 29}}),
            "method,family,queries,contacts,ns_per_query,early_median,early_max,late,early,zero,"
            "verdict_errors\nfloat-cubic,coplanar,100,54,29.5,0,0.25,41,2,1,29\n");
  EXPECT_EQ(toi_stability_csv({{"edge", 3, "robust", 100, 40, 0, 1e-10, 2e-10}}),
            "sweep,parameter,method,queries,contacts,late,early_median,early_max\n"
            "edge,3,robust,100,40,0,1e-10,2e-10\n");
}

Measurements toi_rows() {
  Measurements m;
  m.per_family = m.per_point = 10;
  m.toi_speed = {{"exact", "coplanar", 10, 5, 9000, 0, 0, 0, 0, 0, 0},
                 {"robust", "coplanar", 10, 5, 900, 1e-10, 2e-10, 0, 0, 0, 0},
                 {"float-cubic", "coplanar", 10, 5, 30, 0, 0.5, 3, 1, 1, 2},
                 {"float-cubic", "sliding-on-edge", 10, 4, 40, 0, 1e-3, 2, 1, 0, 0}};
  m.toi_stability = {{"edge", 0, "robust", 10, 5, 0, 1e-10, 1e-10},
                     {"edge", 0, "float-cubic", 10, 5, 0, 0, 0},
                     {"edge", 1, "robust", 10, 5, 0, 1e-10, 1e-10},
                     {"edge", 1, "float-cubic", 10, 5, 4, 0, 1e-16}};
  return m;
}

TEST(ToiReport, TheReportShowsBothChartsAndFloatCubicsCounts) {
  Report r;
  r.measurements = toi_rows();
  const std::string md = report_markdown(r);
  EXPECT_NE(md.find("![time of impact against speed](toi_speed.svg)"), std::string::npos) << md;
  EXPECT_NE(md.find("![time of impact, grazing](toi_stability.svg)"), std::string::npos);
  EXPECT_NE(md.find("| float-cubic | 20 | 9 | 40.0 | 0.5 | 5 | 2 | 1 | 2 |"), std::string::npos);
  EXPECT_NE(md.find("**5 late** TOIs and **2 early** by more than 2^-30 of the step, of 9 "
                    "contacts; 1 of its TOIs are 0"),
            std::string::npos);
  EXPECT_NE(md.find("| edge | float-cubic | 4 | 1 | 1e-16 |"), std::string::npos);
  EXPECT_NE(md.find("| edge | robust | 0 | never | 1e-10 |"), std::string::npos);
}

TEST(ToiReport, TheChartsAreDrawnFromTheDataFiles) {
  const std::filesystem::path dir = fresh_temp_dir("toi_charts");
  const Measurements m = toi_rows();
  std::filesystem::create_directories(dir / "data");
  write_file_atomically((dir / "data/toi_speed.csv").string(), toi_speed_csv(m.toi_speed));
  write_file_atomically((dir / "data/toi_stability.csv").string(),
                        toi_stability_csv(m.toi_stability));
  draw_toi_charts(dir.string(), m);
  for (const char* chart :
       {"toi_speed.png", "toi_speed.svg", "toi_stability.png", "toi_stability.svg"})
    EXPECT_GT(std::filesystem::file_size(dir / chart), 1000u) << chart;
  std::ifstream svg(dir / "toi_speed.svg");
  const std::string text((std::istreambuf_iterator<char>(svg)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("sliding-on-edge"), std::string::npos);  // the family's key entry
}

}  // namespace toi_measure_test
}  // namespace fdh::verify
