// The classify and replay jobs (fdh/classify/): options checked once, every query asked at the
// minimum separation δ given (a method that does not answer δ > 0 is n/a there, a file's truth
// counts only at its own δ), δ = 0 as before, and the Result's outputs.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "cli_run.hpp"
#include "fdh/classify/classify.hpp"
#include "fdh/classify/replay.hpp"
#include "temp_dir.hpp"
#include "test_data.hpp"
#include "text_file.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;

// Two methods that say "hit" exactly when asked at δ = 1/4: one answers δ > 0, one only contact.
struct DeltaMethods {
  DeltaMethods() {
    Method answers, contact;
    answers.name = "delta-probe", contact.name = "contact-only";
    answers.answers_min_distance = true;
    for (Method* m : {&answers, &contact})
      for (QueryTest& t : m->test) t = [](const Query& q) { return q.min_distance == 0.25; };
    add_methods({answers, contact}, {});
  }
  ~DeltaMethods() { remove_added_methods(); }
};

ClassifyOptions options(double delta) {
  ClassifyOptions o;
  o.files = {kData + "static.vf"};
  o.methods = {"exact", "delta-probe", "contact-only"};
  o.min_distance = delta;
  return o;
}

TEST(ClassifyJob, RefusesBadOptionsOnce) {
  for (const double d : {-1.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
    ClassifyOptions o = options(0);
    o.min_distance = d;
    EXPECT_THROW(o.validate(), std::invalid_argument) << d;
    EXPECT_THROW(classify_job(o), std::invalid_argument) << d;
  }
  ClassifyOptions o = options(0);
  o.kind = "vf";  // one vocabulary: vertex-face or edge-edge
  EXPECT_THROW(o.validate(), std::invalid_argument);
  o = options(0), o.methods = {"no-such-method"};
  EXPECT_THROW(o.validate(), std::invalid_argument);
  ReplayOptions r;
  r.paths = {kData + "static.vf"}, r.min_distance = -0.5;
  EXPECT_THROW(replay_job(r), std::invalid_argument);
}

TEST(ClassifyJob, EveryQueryIsAskedAtTheMinimumDistance) {
  const DeltaMethods added;
  const ClassifyResult at = classify_job(options(0.25));
  const MethodResult& probe = at.classified.total.methods[1];
  const MethodResult& contact = at.classified.total.methods[2];
  EXPECT_EQ(probe.tally.na, 0);
  EXPECT_EQ(probe.tally.tp + probe.tally.fp, long(at.classified.all.size()));  // all asked at 1/4
  EXPECT_EQ(contact.tally.na, long(at.classified.all.size()));                 // n/a at δ > 0
  for (const QueryRecord& r : at.classified.all) {
    EXPECT_EQ(r.query.min_distance, 0.25);
    EXPECT_FALSE(r.has_truth());  // the file's truths are at δ = 0
  }
  EXPECT_EQ(at.classified.total.truth, TruthSource::Exact);
  EXPECT_EQ(at.to_json()["min_distance"], 0.25);
  EXPECT_NE(at.text().find("asked at minimum separation 0.25"), std::string::npos);

  const ClassifyResult zero = classify_job(options(0));
  EXPECT_EQ(zero.classified.total.methods[1].tally.tp + zero.classified.total.methods[1].tally.fp,
            0);
  EXPECT_EQ(zero.classified.total.methods[2].tally.na, 0);
  EXPECT_FALSE(zero.to_json().contains("min_distance"));
  EXPECT_EQ(zero.classified.total.truth, TruthSource::Mixed);  // static.vf: 3 of 4 have truths
}

TEST(ClassifyJob, ResultWritesItsOutputsWhole) {
  const fs::path dir = fresh_temp_dir("classify_job") / "out";
  ClassifyOptions o = options(0);
  o.methods = {"exact", "robust"}, o.toi = true;
  const ClassifyResult r = classify_job(o);
  r.write(dir.string());
  EXPECT_EQ(text_of(dir / "classify.txt"), r.text());
  EXPECT_EQ(text_of(dir / "per-query.csv"), r.per_query_csv());
  const nlohmann::ordered_json j = nlohmann::ordered_json::parse(text_of(dir / "classify.json"));
  EXPECT_EQ(j["queries"], 4);
  EXPECT_EQ(j["toi"]["methods"]["robust"]["late"], 0);
  EXPECT_EQ(r.broken(), 0u);
  EXPECT_EQ(r.findings_text(), "");
}

TEST(ReplayJob, TheTwinsLostTruthIsFoundAndTheOthersListed) {
  ReplayOptions o;
  o.paths = {kData + "wrong_truth.vf"}, o.methods = {"exact", "robust"};
  const ReplayResult r = replay_job(o);
  ASSERT_EQ(r.twin_mismatches.size(), 1u);
  EXPECT_EQ(r.failing[1].cases, r.twin_mismatches);  // robust says what exact says
  EXPECT_NE(r.text().find("as exact, against the stored truth"), std::string::npos);
  o.min_distance = 0.25;  // the stored truth is at δ = 0: not counted at 1/4
  EXPECT_TRUE(replay_job(o).twin_mismatches.empty());
}

}  // namespace
}  // namespace fdh::verify

namespace fdh::verify {
namespace {

// The JSON without its times, which differ from run to run.
nlohmann::json untimed(const std::string& text) {
  nlohmann::json j = nlohmann::json::parse(text);
  const nlohmann::json flat = j.flatten();
  for (const auto& [pointer, value] : flat.items())
    if (pointer.find("ns") != std::string::npos) j[nlohmann::json::json_pointer(pointer)] = nullptr;
  return j;
}

TEST(ClassifyCli, MinDistanceZeroIsTheOutputWithoutIt) {
  const fs::path dir = fresh_temp_dir("classify_delta");
  const std::vector<std::string> args = {
      "classify", kData + "moving.vf", "--methods", "exact,robust,float-cubic", "--toi", "--json"};
  std::vector<std::string> at_zero = args;
  at_zero.insert(at_zero.end(), {"--min-distance", "0", "--per-query", (dir / "0.csv").string()});
  std::vector<std::string> without = args;
  without.insert(without.end(), {"--per-query", (dir / "none.csv").string()});
  const CliRun a = fdhcert(at_zero), b = fdhcert(without);
  ASSERT_EQ(a.status, 0) << a.err;
  ASSERT_EQ(b.status, 0) << b.err;
  EXPECT_EQ(untimed(a.out), untimed(b.out));
  EXPECT_EQ(a.err, b.err);
  EXPECT_EQ(text_of(dir / "0.csv"), text_of(dir / "none.csv"));
}

TEST(ClassifyCli, MinDistanceReachesTheJsonAndBadOnesAreUsageErrors) {
  const CliRun at = fdhcert(
      {"classify", kData + "moving.vf", "--methods", "exact", "--json", "--min-distance", "0.125"});
  ASSERT_EQ(at.status, 0) << at.err;
  EXPECT_EQ(nlohmann::json::parse(at.out)["min_distance"], 0.125);
  for (const std::string d : {"-1", "nan", "inf", "-inf"})
    for (const std::string command : {"classify", "replay"}) {
      const CliRun r = fdhcert({command, kData + "moving.vf", "--min-distance", d});
      EXPECT_EQ(r.status, 2) << command << " " << d << ": " << r.out;
      EXPECT_NE(r.err.find("min"), std::string::npos) << r.err;
      EXPECT_EQ(r.out, "");
    }
}

}  // namespace
}  // namespace fdh::verify
