// The committed float-cubic TOI corpus: corpus/toi/float-cubic/<family>/<class>-<hash>.vf,
// written by fdhcert fuzz --toi (corpus/toi/README.md). Each case must still show float-cubic's
// time late (late-, missed-) or early (early-) through replay --toi, while the exact twin gives
// its stored truth and every method with a time promise keeps it.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <set>

#include "cli_run.hpp"
#include "fdh/check/checker.hpp"
#include "fdh/io/query_io.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;
const fs::path kCorpus = FDH_SOURCE_DIR "/corpus/toi/float-cubic";

// The corpus's case files by class (the name's part before '-').
std::map<std::string, std::set<std::string>> corpus_by_class() {
  std::map<std::string, std::set<std::string>> out;
  for (const auto& e : fs::recursive_directory_iterator(kCorpus)) {
    if (e.path().extension() != ".vf") continue;
    const std::string name = e.path().filename().string();
    out[name.substr(0, name.find('-'))].insert(e.path().string());
  }
  return out;
}

// The files of replay's FILE:LINE list.
std::set<std::string> files_of(const nlohmann::json& list) {
  std::set<std::string> out;
  for (const std::string w : list) out.insert(w.substr(0, w.rfind(':')));
  return out;
}

std::set<std::string> joined(const std::set<std::string>& a, const std::set<std::string>& b) {
  std::set<std::string> out = a;
  out.insert(b.begin(), b.end());
  return out;
}

// replay --toi (every early time listed: tolerance 0) names each late and missed case late and
// each early case early for float-cubic; robust and exact are late on none and keep their
// promise on all.
TEST(Corpus, ReplayListsTheTimeCorpusAsLateAndEarlyForFloatCubic) {
  std::map<std::string, std::set<std::string>> by_class = corpus_by_class();
  EXPECT_EQ(by_class.size(), 3u);  // late, missed, early: nothing else
  EXPECT_GE(by_class["late"].size(), 3u);
  EXPECT_GE(by_class["early"].size(), 3u);
  const CliRun r = fdhcert({"replay", kCorpus.string(), "--toi", "--toi-tolerance", "0",
                            "--methods", "exact,robust,float-cubic", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json toi = nlohmann::json::parse(r.out).at("toi");
  EXPECT_EQ(files_of(toi["float-cubic"]["late"]), joined(by_class["late"], by_class["missed"]));
  EXPECT_EQ(files_of(toi["float-cubic"]["early"]), by_class["early"]);
  for (const char* m : {"exact", "robust"}) {
    EXPECT_TRUE(toi[m]["late"].empty()) << m;
    EXPECT_TRUE(toi[m]["broken"].empty()) << m;
  }
}

// The same through the checker, case by case, with the stored truth.
TEST(Corpus, TimeCorpusKeepsEveryTimePromise) {
  const Method fc = select_methods({"float-cubic"}).front();
  int files = 0;
  for (const auto& [cls, paths] : corpus_by_class())
    for (const std::string& p : paths) {
      SCOPED_TRACE(p);
      const std::vector<QueryRecord> qs = read_native(p);
      ASSERT_EQ(qs.size(), 1u);
      ASSERT_TRUE(qs[0].has_truth());
      const TimeTwin twin = time_twin(qs[0].query);
      EXPECT_EQ(twin_matches_truth(stated(qs[0].truth), twin.hit), true);
      for (const Method& m : time_promised_methods())
        EXPECT_TRUE(check_time(m, qs[0].query, kDefaultToiWidth, twin).kept) << m.name;
      const TimeCheck c = check_time(fc, qs[0].query, kDefaultToiWidth, twin);
      EXPECT_EQ(c.late, cls != "early");
      EXPECT_EQ(c.said.hit, cls != "missed");
      if (cls == "early") {
        EXPECT_GT(c.early, 0);
      }
      ++files;
    }
  EXPECT_GE(files, 10);
}

}  // namespace
}  // namespace fdh::verify
