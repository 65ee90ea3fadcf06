// Plug-ins and the minimum separation δ (fdh_plugin_min_distance, docs/plugins.md "Minimum
// separation"): which function the loader calls at which δ, which structs it refuses, and the
// L∞ example (verify/plugin/example/linf_plugin.c) on queries whose Euclidean and L∞ distances
// are known by construction.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli_run.hpp"
#include "fdh/check/classify.hpp"
#include "fdh/check/registry.hpp"
#include "fdh/plugin/loader.hpp"
#include "temp_dir.hpp"
#include "test_data.hpp"
#include "text_file.hpp"

namespace fdh::verify {
namespace {

namespace fs = std::filesystem;

// Loads one plug-in in this process for one test, and ends the run after it.
class Loaded {
 public:
  explicit Loaded(const std::string& path) { load_plugin(path); }
  ~Loaded() {
    remove_added_methods();
    end_plugin_run();
  }
  Loaded(const Loaded&) = delete;
  Loaded& operator=(const Loaded&) = delete;
};

Query at(Query q, double delta) {
  q.min_distance = delta;
  return q;
}

// Every point moves by (0, 0, 1) over the step: a common velocity keeps every distance.
Query drifting(QueryKind kind, std::array<Vec3, 4> x) {
  Query q;
  q.kind = kind;
  for (std::size_t i = 0; i < 4; ++i) q.x[i] = x[i], q.x[i + 4] = x[i] + Vec3{0, 0, 1};
  return q;
}

constexpr double h = 0x1p-20;

// A point at (-h, -h, h) from the corner of the triangle (0,0,0) (1,0,0) (0,1,0): Euclidean
// distance h√3 (to the corner), L∞ distance h.
Query corner_diagonal() {
  return drifting(QueryKind::VertexFace, {{{-h, -h, h}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}}});
}
// Parallel edges along x, h apart in y and in z: Euclidean distance h√2, L∞ distance h.
Query parallel_diagonal() {
  return drifting(QueryKind::EdgeEdge, {{{0, 0, 0}, {1, 0, 0}, {0, h, h}, {1, h, h}}});
}
// A point h above the triangle's interior: both distances h.
Query above_face() {
  return drifting(QueryKind::VertexFace, {{{0.25, 0.25, h}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}}});
}

const Method& named(const std::vector<Method>& ms, const std::string& name) {
  for (const Method& m : ms)
    if (m.name == name) return m;
  throw std::invalid_argument("no method " + name);
}

TEST(PluginMinDistance, ContactFunctionsAnswerAtZeroAndTheDeltaOnesAbove) {
  const Loaded loaded(FDH_MIN_DISTANCE_PLUGIN);
  const Method m = named(all_methods(), "min-distance-test");
  EXPECT_TRUE(m.answers_min_distance);
  // Its contact functions say 0 and its δ ones 1 at δ > 0, 7 (garbage) at 0: at δ = 0 the loader
  // must call the contact ones, as before δ existed.
  for (const Query& q : {above_face(), parallel_diagonal()}) {
    EXPECT_TRUE(m.applies_to(q));
    EXPECT_FALSE(m.hit(q));
    EXPECT_FALSE(m.time_of_impact(q, kDefaultToiWidth).hit);
    for (const double delta : {0x1p-1074, 0x1p-20, 1e300}) {
      EXPECT_TRUE(m.applies_to(at(q, delta)));
      EXPECT_TRUE(m.hit(at(q, delta))) << delta;
      EXPECT_TRUE(m.time_of_impact(at(q, delta), kDefaultToiWidth).hit) << delta;
    }
  }
}

TEST(PluginMinDistance, APlugInWithoutTheExportIsNotApplicableAboveZero) {
  const Loaded loaded(FDH_EXAMPLE_PLUGIN);
  const Method m = named(all_methods(), "aabb");
  EXPECT_FALSE(m.answers_min_distance);
  EXPECT_TRUE(m.applies_to(above_face()));
  EXPECT_FALSE(m.applies_to(at(above_face(), h)));
  // Asked all the same, it says so rather than calling a function it does not have.
  EXPECT_THROW(m.hit(at(above_face(), h)), std::logic_error);
  EXPECT_THROW(m.time_of_impact(at(above_face(), h), kDefaultToiWidth), std::logic_error);
}

TEST(PluginMinDistance, AStructThatLeavesADecisionOutIsRefused) {
  const std::string file = FDH_MIN_DISTANCE_PLUGIN;
  const struct {
    std::string settings, words;
  } cases[] = {
      {"missing=edge_edge_ccd", "fdh_plugin_min_distance gives no edge_edge_ccd"},
      {"missing=vertex_face_ccd", "fdh_plugin_min_distance gives no vertex_face_ccd"},
      {"missing=vertex_face_toi", "fdh_plugin_min_distance gives no vertex_face_toi"},
      {"missing=all", "fdh_plugin_min_distance gives no"},
      {"null=1", "fdh_plugin_min_distance returned NULL"},
      {"promise=5", "fdh_plugin_min_distance's promise 5 is none of 0, 1, 2"},
  };
  for (const auto& c : cases) {
    const CliRun r =
        fdhcert({"classify", kData + "static.vf", "--plugin", file + ":" + c.settings});
    EXPECT_EQ(r.status, 2) << c.settings;
    EXPECT_NE(r.err.find(c.words), std::string::npos) << c.settings << ": " << r.err;
  }
  EXPECT_EQ(fdhcert({"classify", kData + "static.vf", "--plugin", file}).status, 0);
}

TEST(PluginMinDistance, TheLinfExampleTellsItsFalseAlarmsFromEuclideanExactness) {
  const Loaded loaded(FDH_LINF_PLUGIN);
  const Method linf = named(all_methods(), "linf");
  EXPECT_TRUE(linf.answers_min_distance);
  EXPECT_EQ(linf.promise, Promise::Conservative);
  EXPECT_EQ(linf.time_promise, TimePromise::NeverLate);
  // Within δ in L∞, not in Euclidean distance: a false alarm, which its promise allows.
  for (const auto& [q, delta] :
       {std::pair{corner_diagonal(), 1.5 * h}, std::pair{parallel_diagonal(), 1.25 * h}}) {
    EXPECT_TRUE(linf.hit(at(q, delta)));
    EXPECT_FALSE(twin_hit(at(q, delta)));
    // Below the L∞ distance it proves the miss.
    EXPECT_FALSE(linf.hit(at(q, 0.75 * h)));
  }
  // Where both distances are h: a hit from δ = h on, none below.
  EXPECT_TRUE(linf.hit(at(above_face(), h)));
  EXPECT_FALSE(linf.hit(at(above_face(), h * (1 - 0x1p-20))));
  EXPECT_FALSE(linf.hit(above_face()));
}

TEST(PluginMinDistance, TheLinfExampleTimeIsNeverLate) {
  const Loaded loaded(FDH_LINF_PLUGIN);
  const Method linf = named(all_methods(), "linf");
  // A point falling through the triangle's interior, z = 1 - 2t: within δ = 2^-10 from
  // t = (1 - 2^-10) / 2 on, in both distances.
  Query q;
  q.x = {{{0.25, 0.25, 1},
          {0, 0, 0},
          {1, 0, 0},
          {0, 1, 0},
          {0.25, 0.25, -1},
          {0, 0, 0},
          {1, 0, 0},
          {0, 1, 0}}};
  q.min_distance = 0x1p-10;
  const Toi t = linf.time_of_impact(q, kDefaultToiWidth);
  ASSERT_TRUE(t.hit);
  const double t_star = 0.5 - 0x1p-11;
  EXPECT_LE(t.t_lo, t_star);
  EXPECT_GE(t.t_lo, t_star - 0x1p-9);  // its boxes stop at 2^-10 in t
}

TEST(PluginMinDistance, TheCheckerHoldsTheLinfExampleToItsPromiseAtADelta) {
  const Loaded loaded(FDH_LINF_PLUGIN);
  std::vector<Query> qs;
  for (const double delta : {0.0, 0.75 * h, h, 1.25 * h, 1.5 * h, 2 * h})
    for (const Query& q : {corner_diagonal(), parallel_diagonal(), above_face()})
      qs.push_back(at(q, delta));
  const Classification c = classify(qs, {}, select_methods({"exact", "robust", "linf"}));
  const MethodResult& linf = c.methods.at(2);
  EXPECT_EQ(linf.tally.na, 0);
  EXPECT_EQ(linf.tally.fn, 0);
  EXPECT_EQ(linf.against_exact.broken, 0);
  EXPECT_GE(linf.against_exact.allowed, 2);  // the two diagonals at 1.25 h (and 1.5 h)
}

// certify holds the example to both its promises, the verdicts' and the times' (at the δ of
// the queries it checks: 0 until certify takes --min-distance).
TEST(PluginMinDistance, CertifyCertifiesTheLinfExample) {
  const fs::path out = fresh_temp_dir("linf_certify"), corpus = fresh_temp_dir("linf_corpus");
  fs::copy(FDH_SOURCE_DIR "/corpus/queries", corpus / "queries");
  const CliRun r =
      fdhcert({"certify", "--quick", "--plugin", FDH_LINF_PLUGIN, "--corpus", corpus.string(),
               "--out", out.string(), "--per-family", "10", "--soups", "1", kData + "moving.vf"});
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json c = nlohmann::json::parse(text_of(out / "certificate.json"));
  std::set<std::string> decisions;
  for (const auto& p : c["promises"])
    if (p["method"] == "linf") {
      EXPECT_EQ(p["promise"], "conservative");
      EXPECT_GT(p["checked"], 0);
      EXPECT_EQ(p["violations"], 0);
      decisions.insert(p["decision"].get<std::string>());
    }
  EXPECT_EQ(decisions.size(), 3u);  // point-triangle, vertex-face-ccd, edge-edge-ccd
  EXPECT_TRUE(has(text_of(out / "certificate.md"), "`linf`"));
}

}  // namespace
}  // namespace fdh::verify
