// The report's pieces are built from structs: measurements, the certificate's outputs, the
// report's tables, Table 1 and the scene JSON.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "fdh/cli/cli.hpp"

#include "fdh/certify/certify.hpp"
#include "fdh/check/registry.hpp"
#include "fdh/os/build_info.hpp"
#include "fdh/report/measurements.hpp"
#include "fdh/report/report_document.hpp"
#include "fdh/report/report_html.hpp"
#include "fdh/report/report_summary.hpp"
#include "temp_dir.hpp"

namespace fdh::verify {
namespace {

std::size_t lines(const std::string& s) {
  return std::size_t(std::count(s.begin(), s.end(), '\n'));
}

std::string twin_name() {
  for (const Method& m : all_methods())
    if (m.is_twin) return m.name;
  return {};
}

TEST(Measurements, TheParetoFrontRunsFastestFirstWithFallingError) {
  const std::vector<SpeedAccuracyRow> rows = {{"a", "f", 10, 5, 0.25, 0.25},
                                              {"b", "f", 10, 1, 0.3, 0.3},
                                              {"c", "f", 10, 9, 0, 0},
                                              {"d", "f", 10, 7, 0.4, 0.4}};
  const auto front = pareto_front(rows);
  ASSERT_EQ(front.size(), 3u);
  EXPECT_EQ(front[0].method, "b");
  EXPECT_EQ(front[1].method, "a");
  EXPECT_EQ(front[2].method, "c");
  EXPECT_EQ(pareto_csv(front),
            "method,family,ns_per_query,error_rate,kind\nb,f,1,0.6,static\na,f,5,0.5,static\n"
            "c,f,9,0,static\n");
}

TEST(Measurements, EachKindOfFamilyHasAParetoFrontOfItsOwn) {
  std::vector<SpeedAccuracyRow> rows = {{"a", "f", 10, 5, 0.25, 0.25},
                                        {"b", "f", 10, 1, 0.3, 0.3},
                                        {"c", "g", 10, 900, 0, 0},
                                        {"d", "g", 10, 50, 0.1, 0}};
  rows[2].kind = rows[3].kind = "moving";
  const auto fronts = pareto_fronts(rows);
  ASSERT_EQ(fronts.size(), 4u);  // one front over both would drop c (slower than a, b and d)
  EXPECT_EQ(fronts[0].method, "b");
  EXPECT_EQ(fronts[1].method, "a");
  EXPECT_EQ(fronts[2].method, "d");
  EXPECT_EQ(fronts[3].method, "c");
}

TEST(Measurements, SpeedAccuracyMeasuresTheMovingFamiliesForTheMethodsThatDecideThem) {
  std::set<std::string> moving;
  for (const SpeedAccuracyRow& r : speed_accuracy(2, 1))
    if (r.kind == "moving") moving.insert(r.method);
  for (const Method& m : all_methods())
    EXPECT_EQ(moving.count(m.name), m.test[std::size_t(Decision::VertexFaceCcd)] ? 1u : 0u)
        << m.name;
}

TEST(Measurements, DataFilesHaveAHeaderAndOneLinePerRow) {
  const std::vector<SpeedAccuracyRow> speed = {{"robust", "angled", 100, 12.5, 0, 0.25}};
  EXPECT_EQ(speed_accuracy_csv(speed),
            "method,family,queries,ns_per_query,fp_rate,fn_rate,kind\n"
            "robust,angled,100,12.5,0,0.25,static\n");
  const std::vector<StabilityRow> stab = {{"edge", 3, "linear-system", 0.125}};
  EXPECT_EQ(stability_csv(stab),
            "sweep,parameter,method,failure_rate\nedge,3,linear-system,0.125\n");
}

TEST(Measurements, TheKdopTreeFileSeparatesGridsByABlankLine) {
  const std::vector<KdopTreeRow> rows = {{6, 30, 1, 2, 0.5, 0.25, 0.125, 7},
                                         {14, 30, 1, 2, 0.5, 0.25, 0.125, 6},
                                         {6, 50, 3, 2, 1, 1, 1, 9}};
  const std::string csv = kdop_tree_csv(rows);
  EXPECT_EQ(lines(csv), 5u);
  EXPECT_NE(csv.find("14,30,1,2,0.5,0.25,0.125,6\n\n6,50,"), std::string::npos) << csv;
}

TEST(Measurements, StabilityMeasuresEveryMethodButTheTwin) {
  const std::vector<StabilityRow> rows = stability(2, 1);
  ASSERT_FALSE(rows.empty());
  for (const StabilityRow& r : rows) {
    EXPECT_NE(r.method, twin_name());
    EXPECT_GE(r.failure_rate, 0);
    EXPECT_LE(r.failure_rate, 1);
  }
  for (const StabilitySweep& sw : stability_sweeps())
    EXPECT_TRUE(std::any_of(rows.begin(), rows.end(), [&](const StabilityRow& r) {
      return r.sweep == sw.name && r.parameter == sw.last;
    })) << sw.name;
}

// The report's counted measurements do not depend on the thread count: the stability rates,
// and each speed row's queries and FP and FN rates (its time is measured, not counted), with
// 1, 2 and 64 threads.
TEST(Measurements, TheRatesAreTheSameForAnyThreadCount) {
  std::string stab, rates;
  for (const std::size_t threads : {1, 2, 64}) {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    const std::string s = stability_csv(stability(3, 5));
    std::string r;
    for (const SpeedAccuracyRow& row : speed_accuracy(20, 5))
      r += row.method + row.family + std::to_string(row.queries) + std::to_string(row.fp_rate) +
           std::to_string(row.fn_rate) + "\n";
    if (threads == 1) stab = s, rates = r;
    EXPECT_EQ(s, stab) << threads;
    EXPECT_EQ(r, rates) << threads;
  }
  EXPECT_GT(lines(stab), 100u);
}

Certificate two_promises() {
  Certificate c;
  c.commit = "abc";
  c.options.out_dir = "out";
  c.promises = {{"robust", Decision::PointTriangle, Promise::Exact, 100, 90, 0},
                {"robust", Decision::EdgeEdgeCcd, Promise::Exact, 40, 10, 2}};
  c.boxes = {{"fdh", 6, 500, 0, 3, 77, 1}, {"fdh", 18, 500, 0, 3, 60, 0}};
  c.truths = 20;
  c.truth_violations = 1;
  c.first_violation = "robust says \"hit\"";
  return c;
}

TEST(Certificate, ChecksAndViolationsCountEveryPromiseBoxAndTruth) {
  const Certificate c = two_promises();
  EXPECT_EQ(c.checks(), 100 + 40 + 500 + 3 + 500 + 3 + 20);
  EXPECT_EQ(c.violations(), 2 + 1 + 1);
}

TEST(Certificate, JsonListsEveryPromiseAndKeysTheBoxesByK) {
  const auto j = nlohmann::json::parse(certificate_json(two_promises()));
  EXPECT_FALSE(j["certified"].get<bool>());
  EXPECT_EQ(j["commit"], "abc");
  ASSERT_EQ(j["promises"].size(), 2u);
  EXPECT_EQ(j["promises"][1]["method"], "robust");
  EXPECT_EQ(j["promises"][1]["decision"], to_string(Decision::EdgeEdgeCcd));
  EXPECT_EQ(j["promises"][1]["promise"], to_string(Promise::Exact));
  EXPECT_EQ(j["promises"][1]["checked"], 40);
  EXPECT_EQ(j["promises"][1]["decided_by_filter"], 10);
  EXPECT_EQ(j["promises"][1]["violations"], 2);
  EXPECT_EQ(j["kdop_contains_exact"]["18"]["boxes"], 500);
  EXPECT_EQ(j["kdop_contains_exact"]["6"]["method"], "fdh");
  EXPECT_EQ(j["tree_no_false_cull"]["6"]["exact_overlapping_pairs"], 77);
  EXPECT_EQ(j["tree_no_false_cull"]["6"]["violations"], 1);
  EXPECT_EQ(j["exact_equals_stored_truth"]["violations"], 1);
  EXPECT_EQ(j["first_violation"], "robust says \"hit\"");  // escaped and read back
  for (const char* key : {"cgal", "gmp", "mode", "seed", "inputs"}) EXPECT_TRUE(j.contains(key));
}

TEST(Certificate, MarkdownHasOneRowPerPromiseCheck) {
  const std::string md = certificate_markdown(two_promises());
  EXPECT_NE(md.find("**Violated**"), std::string::npos);
  EXPECT_NE(md.find("| point-triangle verdict = the exact twin | `robust` | – | 100 queries (90 "
                    "decided by the float filter alone) | 0 |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| edge-edge-ccd verdict"), std::string::npos);
  EXPECT_EQ(certificate_section(two_promises()).rfind("**Violated**", 0), 0u);
}

TEST(Report, TablesComeFromTheRows) {
  Report r;
  r.certificate = two_promises();
  Measurements& m = r.measurements;
  m.speed = {{"robust", "a", 10, 20, 0, 0},
             {"robust", "b", 10, 40, 0, 0},
             {"paper-literal", "a", 10, 5, 0.5, 0.25}};
  m.stability = {{"angle", 0, "robust", 0},
                 {"angle", 0, "paper-literal", 0},
                 {"angle", 1, "paper-literal", 0.5}};
  m.kdop = {{18, 30, 1682, 2304, 1, 0.5, 0.25, 6000}};
  const std::string md = report_markdown(r);
  EXPECT_NE(md.find("| robust | 40.0 | 0 | 0 | 2 of 2 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| paper-literal | 5.0 | 0.5 | 0.25 | 0 of 1 |"), std::string::npos);
  EXPECT_NE(md.find("| angle | never wrong | wrong from p = 1, worst 0.5 |"), std::string::npos);
  EXPECT_NE(md.find("| 18 | 30×30 | 1682 / 2304 | 1 | 0.5 | 0.25 | 6000 |"), std::string::npos);
  EXPECT_NE(md.find("at commit `abc`"), std::string::npos);
}

TEST(Report, AtAGlanceCountsEachMethodsFpAndFnOverTheFamilies) {
  Report r;
  r.certificate = two_promises();
  r.measurements.speed = {{"robust", "a", 10, 20, 0, 0},
                          {"paper-literal", "a", 10, 5, 0.5, 0.2},
                          {"paper-literal", "b", 20, 7, 0.25, 0}};
  const std::string md = glance_markdown(r);
  EXPECT_NE(md.find("| `paper-literal` | none | 30 | 10 | 2 | 7 | 0 | – | – | – |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| `robust` | exact | 10 | 0 | 0 | 20 |"), std::string::npos) << md;
  const std::string summary = report_summary(r);
  EXPECT_EQ(lines(summary), 3u) << summary;  // no peers: no bounding-volume line
  EXPECT_EQ(summary.rfind("VIOLATED: ", 0), 0u) << summary;
  EXPECT_NE(summary.find("robust edge-edge-ccd 2/40"), std::string::npos) << summary;
}

// index.html: the gnuplot charts inline with their ids apart, a titled circle per speed row, a
// file named in the text linked relative to the page, nothing from the network.
TEST(Report, ThePageInlinesTheChartsAndLinksTheCases) {
  const std::filesystem::path dir = fresh_temp_dir("report_page");
  for (const char* chart : {"toi_speed", "stability", "toi_stability", "kdop_k"})
    std::ofstream(dir / (std::string(chart) + ".svg"))
        << "<?xml version=\"1.0\"?>\n<svg viewBox='0 0 9 9'><title>Gnuplot</title><defs><path "
           "id='gpPt1' d='M0,0'/></defs><use xlink:href='#gpPt1'/></svg>\n";
  std::filesystem::create_directories(dir / "peers");
  std::ofstream(dir / "peers" / "case.txt") << "x\n";
  Report r;
  r.certificate = two_promises();
  r.certificate.options.out_dir = dir.string();
  r.certificate.first_violation = "saved to " + (dir / "peers" / "case.txt").string() + ".";
  r.measurements.speed = {{"robust", "a&b", 10, 20, 0, 0}, {"paper-literal", "a", 10, 5, 0.5, 0}};
  const std::string html = report_html(r, dir.string());
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("<a href=\"peers/case.txt\">"), std::string::npos) << html;
  for (const char* id : {"id='c1-gpPt1'", "href='#c1-gpPt1'", "id='c4-gpPt1'"})
    EXPECT_NE(html.find(id), std::string::npos) << id;
  EXPECT_EQ(html.find("<?xml"), std::string::npos);
  EXPECT_NE(html.find("<title>robust on a&amp;b (static): FP rate 0, FN rate 0 of 10 queries; "
                      "20.0 ns per query</title>"),
            std::string::npos);
  std::size_t points = 0;
  for (std::size_t at = 0; (at = html.find("<circle class=\"point\"", at)) != std::string::npos;
       ++at)
    ++points;
  EXPECT_EQ(points, 2u);
  EXPECT_EQ(html.find("src=\"http"), std::string::npos);
  std::filesystem::remove(dir / "kdop_k.svg");
  EXPECT_THROW(report_html(r, dir.string()), std::runtime_error);
}

TEST(BuildInfo, TheCommitIsFixedAtConfigureTime) {
  const std::string commit = build_commit();
  EXPECT_FALSE(commit.empty());
  EXPECT_EQ(commit.find_first_of("\n\r\" "), std::string::npos) << commit;
}

}  // namespace
}  // namespace fdh::verify
